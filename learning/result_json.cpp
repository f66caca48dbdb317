// The learning result as JSON (compensation.h to_json, result_from_json) and read back.
#include <string>
#include <utility>

#include "body/course_json.h"
#include "common/errors.h"
#include "learning/compensation.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {

namespace {

// The neutral fields of a trial, then the learner's own details beside them.
nlohmann::json trial_json(const TrialRecord& t, const robot::Morphology& morph) {
  nlohmann::json j = t.details;
  j["trial"] = t.trial;
  j["periods"] = robot::period_map_json(morph, t.periods);
  j["deviation_deg"] = t.deviation_deg;
  j["accepted"] = t.accepted;
  return j;
}

nlohmann::json episodes_json(const LearningResult& result, const robot::Morphology& morph) {
  nlohmann::json out = nlohmann::json::array();
  for (const Episode& e : result.episodes) {
    out.push_back({{"detection_step", e.detection_step},
                   {"detection_deg", e.detection_deg},
                   {"trials", e.trials},
                   {"held", e.held},
                   {"interrupted", e.interrupted},
                   {"reason", e.reason ? nlohmann::json(std::string(to_string(*e.reason)))
                                       : nlohmann::json(nullptr)},
                   {"periods", robot::period_map_json(morph, e.periods)},
                   {"final_deviation_deg", e.final_deviation_deg}});
  }
  return out;
}

}  // namespace

nlohmann::json to_json(const LearningResult& result, const robot::Morphology& morph,
                       const std::vector<std::size_t>& disabled) {
  nlohmann::json trace = nlohmann::json::array();
  for (const TrialRecord& t : result.trace) trace.push_back(trial_json(t, morph));
  nlohmann::json disabled_names = nlohmann::json::array();
  for (std::size_t leg : disabled) disabled_names.push_back(morph.legs.at(leg).name);
  nlohmann::json j{{"converged", result.converged()},
                   {"status", to_string(result.outcome)},
                   {"reason", result.reason ? nlohmann::json(std::string(to_string(*result.reason)))
                                            : nlohmann::json(nullptr)},
                   {"trials", result.trials},
                   {"initial_deviation_deg", result.initial_deviation_deg},
                   {"final_deviation_deg", result.final_deviation_deg},
                   {"periods", robot::period_map_json(morph, result.periods)},
                   {"disabled", disabled_names},
                   {"steps_walked", result.steps_walked},
                   {"detection_step", result.detection_step ? nlohmann::json(*result.detection_step)
                                                            : nlohmann::json(nullptr)},
                   {"settle_steps", result.settle_steps},
                   {"mode", to_string(result.mode)},
                   {"episodes", episodes_json(result, morph)},
                   {"final_windows", nlohmann::json(result.final_windows)},
                   {"steering_effort", result.steering_effort},
                   {"trace", trace}};
  // Only a learner with data of its own records them: the records of the others stay as they were.
  if (result.learned_from) j["learned_from"] = *result.learned_from;
  return j;
}

namespace {

std::optional<StopReason> reason_from_json(const nlohmann::json& j) {
  if (j.is_null()) return std::nullopt;
  return parse_stop_reason(j.get<std::string>());
}

}  // namespace

LearningResult result_from_json(const nlohmann::json& j, const robot::Morphology& morph) {
  try {
    LearningResult r;
    r.outcome = parse_outcome(j.at("status").get<std::string>());
    if (j.at("converged").get<bool>() != r.converged()) {
      throw BadInput("converged and status disagree");
    }
    r.reason = reason_from_json(j.at("reason"));
    r.trials = j.at("trials").get<int>();
    r.initial_deviation_deg = j.at("initial_deviation_deg").get<double>();
    r.final_deviation_deg = j.at("final_deviation_deg").get<double>();
    r.periods = robot::period_map_from_json(morph, j.at("periods"));
    r.steps_walked = j.at("steps_walked").get<long>();
    if (!j.at("detection_step").is_null()) r.detection_step = j.at("detection_step").get<long>();
    r.settle_steps = j.at("settle_steps").get<long>();
    r.mode = parse_mode(j.at("mode").get<std::string>());
    for (const nlohmann::json& e : j.at("episodes")) {
      r.episodes.push_back(Episode{
          e.at("detection_step").get<long>(), e.at("detection_deg").get<double>(),
          e.at("trials").get<int>(), e.at("held").get<bool>(), reason_from_json(e.at("reason")),
          e.at("interrupted").get<bool>(), robot::period_map_from_json(morph, e.at("periods")),
          e.at("final_deviation_deg").get<double>()});
    }
    r.final_windows = j.at("final_windows").get<std::vector<body::WindowMeasure>>();
    r.steering_effort = j.at("steering_effort").get<double>();
    if (j.contains("learned_from")) r.learned_from = j.at("learned_from").get<LearnedFrom>();
    // An experiment may record its runs without their trace ([record] trace = false,
    // docs/experiments.md): such a result reads with an empty trace.
    for (const nlohmann::json& t : j.value("trace", nlohmann::json::array())) {
      nlohmann::json details = t;
      for (const char* neutral : {"trial", "periods", "deviation_deg", "accepted"}) {
        details.erase(neutral);
      }
      r.trace.push_back(TrialRecord{
          t.at("trial").get<int>(), robot::period_map_from_json(morph, t.at("periods")),
          t.at("deviation_deg").get<double>(), t.at("accepted").get<bool>(), std::move(details)});
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(std::string("not a learning result: ") + e.what());
  } catch (const BadInput& e) {
    throw BadInput(std::string("not a learning result: ") + e.what());
  }
}

}  // namespace multicpg::learning
