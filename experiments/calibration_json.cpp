// The calibration's numbers as JSON, and candidates.json (calibration.h) written and read back.

#include "common/errors.h"
#include "common/input_file.h"
#include "experiments/calibration.h"
#include "experiments/calibration_detail.h"
#include "sim/json.h"

namespace multicpg::experiments {

namespace fs = std::filesystem;

namespace calibration_detail {
namespace {

nlohmann::json to_json(const TunnelNumbers& t) {
  return {{"deviation_deg", t.deviation_deg}, {"passed", t.passed},
          {"touched_wall", t.touched_wall},   {"steps", t.steps},
          {"forward_m", t.forward_m},         {"lateral_m", t.lateral_m}};
}

TunnelNumbers tunnel_from_json(const nlohmann::json& j) {
  return {j.at("deviation_deg"), j.at("passed"),    j.at("touched_wall"),
          j.at("steps"),         j.at("forward_m"), j.at("lateral_m")};
}

std::vector<ScenarioNumbers> scenarios_from_json(const nlohmann::json& j) {
  std::vector<ScenarioNumbers> out;
  for (const nlohmann::json& s : j) {
    ScenarioNumbers n{s.at("scenario"), s.at("periods"), {}};
    for (const nlohmann::json& t : s.at("starts")) n.starts.push_back(tunnel_from_json(t));
    out.push_back(std::move(n));
  }
  return out;
}

SearchedParam param_from_json(const nlohmann::json& j) {
  return {j.at("key"), j.at("lo"), j.at("hi"), j.at("log_scale")};
}

}  // namespace

nlohmann::json to_json(const std::vector<ScenarioNumbers>& scenarios) {
  nlohmann::json out = nlohmann::json::array();
  for (const ScenarioNumbers& s : scenarios) {
    nlohmann::json starts = nlohmann::json::array();
    for (const TunnelNumbers& t : s.starts) starts.push_back(to_json(t));
    out.push_back({{"scenario", s.name},
                   {"periods", s.periods},
                   {"mean_deg", s.mean_deg()},
                   {"passed", s.passed()},
                   {"starts", starts}});
  }
  return out;
}

nlohmann::json to_json(const CandidateNumbers& n) {
  nlohmann::json j{{"failure", n.failure},
                   {"fit", to_json(n.fit)},
                   {"paper_periods", to_json(n.paper_periods)},
                   {"mirrors", to_json(n.mirrors)},
                   {"intact_yaw_deg", n.intact_yaw_deg},
                   {"intact_speed_m_s", n.intact_speed_m_s},
                   {"score_deg", n.score_deg},
                   {"violation", n.violation}};
  return j;
}

CandidateNumbers numbers_from_json(const nlohmann::json& j) {
  CandidateNumbers n;
  n.failure = j.at("failure");
  n.fit = scenarios_from_json(j.at("fit"));
  n.paper_periods = scenarios_from_json(j.at("paper_periods"));
  n.mirrors = scenarios_from_json(j.at("mirrors"));
  n.intact_yaw_deg = j.at("intact_yaw_deg").get<std::vector<double>>();
  n.intact_speed_m_s = j.at("intact_speed_m_s").get<std::vector<double>>();
  n.score_deg = j.at("score_deg");
  n.violation = j.at("violation");
  return n;
}

nlohmann::json to_json(const SearchedParam& p) {
  return {{"key", p.key}, {"lo", p.lo}, {"hi", p.hi}, {"log_scale", p.log_scale}};
}

}  // namespace calibration_detail

using namespace calibration_detail;

nlohmann::json calibration_json(const Calibration& cal) {
  nlohmann::json candidates = nlohmann::json::array();
  for (const Candidate& c : cal.candidates) {
    nlohmann::json values = nlohmann::json::object();
    for (const SearchedParam& p : cal.spec.params) {
      values[p.key] = robot::number_param(p.key).get(c.body);
    }
    candidates.push_back({{"id", c.id},
                          {"stage", c.stage},
                          {"u", c.u},
                          {"values", values},
                          {"body", c.body},
                          {"numbers", to_json(c.numbers)}});
  }
  nlohmann::json params = nlohmann::json::array();
  for (const SearchedParam& p : cal.spec.params) params.push_back(to_json(p));
  return {{"arguments", calibration_arguments(cal.spec)},
          {"sim", cal.spec.robot.sim},
          {"params", params},
          {"candidates", candidates},
          {"best", cal.candidates.empty() ? "" : cal.candidates[cal.best].id}};
}

Calibration read_calibration(const fs::path& path) {
  const std::string text =
      read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a calibration record");
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    Calibration cal;
    const nlohmann::json& args = j.at("arguments");
    cal.spec.target = parse_calibration_target(args.at("target").get<std::string>());
    cal.spec.robot.kind = robot::parse_robot(args.at("robot").get<std::string>());
    cal.spec.robot.sim = j.at("sim").get<sim::SimOptions>();
    for (const nlohmann::json& p : j.at("params")) cal.spec.params.push_back(param_from_json(p));
    cal.spec.budget = args.at("budget");
    cal.spec.seed = args.at("seed");
    cal.spec.warmups = args.at("warmups").get<std::vector<long>>();
    const std::string best = j.at("best");
    for (const nlohmann::json& c : j.at("candidates")) {
      Candidate cand{c.at("id"), c.at("stage"), c.at("u").get<std::vector<double>>(),
                     c.at("body").get<robot::BodyParams>(), numbers_from_json(c.at("numbers"))};
      if (cand.id == best) cal.best = cal.candidates.size();
      cal.candidates.push_back(std::move(cand));
    }
    if (cal.candidates.empty()) throw BadInput("no candidates");
    return cal;
  } catch (const nlohmann::json::exception& e) {
    throw BadInput("'" + path.string() + "' is not a calibration (" + e.what() + ")");
  } catch (const BadInput& e) {
    throw BadInput("'" + path.string() + "' is not a calibration (" + e.what() + ")");
  }
}

}  // namespace multicpg::experiments
