// Calibrating the body against Table 1 (calibration.h): a candidate walked and scored, the search.
#include "experiments/calibration.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>

#include "common/atomic_file.h"
#include "common/enum_names.h"
#include "common/errors.h"
#include "common/table.h"
#include "experiments/calibration_detail.h"
#include "experiments/paper.h"
#include "experiments/processes.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "experiments/tunnel.h"
#include "learning/compensation.h"
#include "robot/leg_sets.h"
#include "sim/json.h"
#include "sim/walk.h"

namespace multicpg::experiments {

using namespace calibration_detail;

namespace {

namespace fs = std::filesystem;

constexpr int kJsonIndent = 2;
constexpr double kCmPerM = 100.0;

constexpr auto kCalibrationTargetNames =
    enum_names<CalibrationTarget>({{CalibrationTarget::table1, "table1"}});

// --- numbers -----------------------------------------------------------------------------------

// The real robot's before-learning angle of each Table 1 scenario, + = left.
std::vector<double> targets() {
  std::vector<double> out;
  for (const paper::TunnelResult& r : paper::kTunnel) out.push_back(paper::signed_before_deg(r));
  return out;
}

double score(const std::vector<ScenarioNumbers>& fit) {
  const std::vector<double> t = targets();
  double sum = 0.0;
  for (std::size_t i = 0; i < fit.size(); ++i) {
    const double e = fit[i].mean_deg() - t[i];
    sum += e * e;
  }
  return std::sqrt(sum / static_cast<double>(fit.size()));
}

double violation(const CandidateNumbers& n) {
  double v = std::max(0.0, n.intact_max_yaw_deg() - kIntactStraightDeg);
  const double speed = n.intact_mean_speed_m_s();
  v += kCmPerM * std::max(0.0, kPlausibleSpeedMS.lo - speed);
  v += kCmPerM * std::max(0.0, speed - kPlausibleSpeedMS.hi);
  // Every run the real robot made before learning ended at the right wall; a fitted run cut at
  // kCalibrationFitSteps has stalled, and its angle so far is not Table 1's.
  for (const ScenarioNumbers& s : n.fit) {
    for (const TunnelNumbers& t : s.starts) {
      if (!t.touched_wall) v += kStalledRunViolation;
    }
  }
  return v;
}

// --- walking a candidate -----------------------------------------------------------------------

struct Scenario1 {
  std::string name;
  std::vector<std::size_t> disabled;
  std::vector<int> periods;
  std::string periods_text;
};

// Table 1's scenarios (paper.h): all periods 4; with the paper's periods; mirrored, all 4.
struct Scenarios {
  std::vector<Scenario1> fit, paper_periods, mirrors;
};

Scenarios table1_scenarios(const robot::Morphology& morph) {
  Scenarios s;
  const std::vector<int> all4(morph.size(), learning::kStartPeriod);
  for (const paper::TunnelResult& r : paper::kTunnel) {
    std::string legs(r.disabled);
    std::replace(legs.begin(), legs.end(), '+', ',');
    const std::vector<std::size_t> disabled = robot::parse_leg_set(morph, legs);
    const std::string name = robot::leg_set_name(morph, disabled);
    const std::string learned = paper::combination_text(r.learned);
    s.fit.push_back({name, disabled, all4, "all 4"});
    s.paper_periods.push_back(
        {name, disabled, robot::parse_period_map(morph, learned, learning::kStartPeriod), learned});
    const std::vector<std::size_t> mirrored = robot::mirror(morph, disabled);
    s.mirrors.push_back({robot::leg_set_name(morph, mirrored), mirrored, all4, "all 4"});
  }
  return s;
}

TunnelNumbers walk_tunnel(const sim::SimModel& corridor, const Scenario1& sc, long warmup,
                          long max_steps) {
  TunnelSpec t;
  t.max_steps = max_steps;
  t.start.periods = sc.periods;
  t.start.warmup = warmup;
  t.faults = body::fail_at(sc.disabled, 0);
  const TunnelRun run = run_tunnel(corridor, t);
  return {run.deviation_deg, run.passed_or_false(), run.touched_wall,
          run.steps,         run.forward_m,         run.lateral_m};
}

ScenarioNumbers walk_scenario(const sim::SimModel& corridor, const Scenario1& sc,
                              const std::vector<long>& warmups, long max_steps) {
  ScenarioNumbers out{sc.name, sc.periods_text, {}};
  for (long w : warmups) out.starts.push_back(walk_tunnel(corridor, sc, w, max_steps));
  return out;
}

// --- the search --------------------------------------------------------------------------------

std::string design_id(std::size_t i) {
  return fmt::format("d{:04}", i);
}

std::string round_name(int round) {
  return fmt::format("refine-{:02}", round);
}

// One stage: its candidates walked (or loaded) by the runner in OUT/<stage>.
std::vector<Candidate> run_stage(const CalibrationSpec& spec, const fs::path& out,
                                 const std::string& stage, std::vector<Candidate> candidates,
                                 const nlohmann::json& stage_info, int jobs, bool progress,
                                 int& loaded, int& ran) {
  RunnerOptions runner;
  runner.out_dir = out / stage;
  runner.jobs = jobs;
  runner.arguments = calibration_arguments(spec);
  runner.arguments["stage"] = stage_info;
  runner.progress = progress;
  validate(runner);
  std::vector<Task> tasks;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    Task t;
    t.key = candidates[i].id;
    t.group = stage;
    t.run = static_cast<int>(i);
    t.seed = derive_seed(spec.seed, t.key);
    t.params = {{"u", candidates[i].u}, {"body", candidates[i].body}};
    tasks.push_back(std::move(t));
  }
  const RunnerOutcome outcome = run_tasks(
      tasks,
      [&spec](const Task& task) {
        return to_json(measure_candidate(spec, task.params.at("body").get<robot::BodyParams>()));
      },
      runner);
  loaded += outcome.loaded;
  ran += outcome.ran;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    candidates[i].numbers = numbers_from_json(outcome.results[i]);
  }
  return candidates;
}

std::size_t best_of(const std::vector<Candidate>& c) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < c.size(); ++i) {
    if (better(c[i].numbers, c[best].numbers)) best = i;
  }
  return best;
}

}  // namespace

// --- public ------------------------------------------------------------------------------------

std::string_view to_string(CalibrationTarget target) {
  return kCalibrationTargetNames.name(target);
}

CalibrationTarget parse_calibration_target(std::string_view text) {
  if (const std::optional<CalibrationTarget> target = kCalibrationTargetNames.find(text)) {
    return *target;
  }
  throw BadInput("no calibration target '" + std::string(text) + "' (known: " +
                 kCalibrationTargetNames.list() + ", paper §5 Table 1 before learning)");
}

std::vector<SearchedParam> default_searched_params() {
  return {
      // A dead leg's joints: any command (docs/robots.md Body parameters: the authors hold 0,
      // 0.7, -0.7; the probe's fit
      // needs the leg raised, CTr 1), but the leg never pressed into the ground (CTr below 0
      // props the body, which the paper's dead legs "touched ... intermittently" do not) nor
      // stretched out past the authors' walking range of FTi (-1..-0.82) by more than 0.82.
      {"disabled_posture.tc", -1.0, 1.0, false},
      {"disabled_posture.ctr", 0.0, 1.0, false},
      {"disabled_posture.fti", -1.0, 0.0, false},
      // The probe's strongest knob for R1; two decades, so searched on a log scale.
      {"slip", robot::kSlipLimits.lo, robot::kSlipLimits.hi, true},
      {"foot_friction", robot::kFrictionLimits.lo, robot::kFrictionLimits.hi, false},
      // Up to 0.1 rad per N m: the probe's 0.2 turns erratic and stalls.
      {"joint_compliance", robot::kJointComplianceLimits.lo, 0.1, false},
      // From 10 N m: below it the robot cannot carry itself at a plausible speed (the probe: 6 N m
      // walks 4.1 cm/s and stalls in the tunnel, 3 N m 0.4 cm/s).
      {"servo_torque", 10.0, robot::kServoTorqueLimits.hi, false},
  };
}

void validate(const CalibrationSpec& spec) {
  if (spec.robot.kind != robot::RobotKind::hexapod) {
    throw OptionError("robot", "Table 1 is the hexapod's; got the " +
                                   std::string(robot::to_string(spec.robot.kind)));
  }
  if (spec.robot.file) {
    throw OptionError("robot", "Table 1 is the built-in hexapod's; got the robot file '" +
                                   spec.robot.file->record.path + "'");
  }
  validate(spec.robot);
  if (spec.params.empty()) throw OptionError("params", "search at least one parameter");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    const SearchedParam& p = spec.params[i];
    const std::string at = fmt::format("params[{}].", i);
    const robot::NumberParam* param = nullptr;
    try {
      param = &robot::number_param(p.key);
    } catch (const BadInput& e) {
      throw OptionError(at + "key", e.what());
    }
    if (!seen.insert(p.key).second) throw OptionError(at + "key", p.key + " is named twice");
    require_in(at + "lo", p.lo, param->limits);
    require_in(at + "hi", p.hi, param->limits);
    if (!(p.lo < p.hi)) {
      throw OptionError(at + "hi", fmt::format("must exceed lo {}, got {}", p.lo, p.hi));
    }
    if (p.log_scale && p.lo <= 0.0) {
      throw OptionError(at + "lo", fmt::format("a log scale needs lo > 0, got {}", p.lo));
    }
  }
  require_in("budget", spec.budget, kCalibrationBudgetLimits);
  if (spec.warmups.empty()) throw OptionError("warmups", "name at least one start");
  std::set<long> starts;
  for (std::size_t i = 0; i < spec.warmups.size(); ++i) {
    require_in(fmt::format("warmups[{}]", i), spec.warmups[i], kCalibrationWarmupLimits);
    if (!starts.insert(spec.warmups[i]).second) {
      throw OptionError(fmt::format("warmups[{}]", i), "repeats an earlier start");
    }
  }
}

robot::BodyParams body_at(const CalibrationSpec& spec, const std::vector<double>& u) {
  robot::BodyParams body = spec.robot.sim.body;
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    const SearchedParam& p = spec.params[i];
    const double t = std::clamp(u.at(i), 0.0, 1.0);
    const double v = p.log_scale ? std::exp(std::log(p.lo) + t * (std::log(p.hi) - std::log(p.lo)))
                                 : p.lo + t * (p.hi - p.lo);
    robot::number_param(p.key).set(body, std::clamp(v, p.lo, p.hi));
  }
  return body;
}

double ScenarioNumbers::mean_deg() const {
  double s = 0.0;
  for (const TunnelNumbers& t : starts) s += t.deviation_deg;
  return starts.empty() ? 0.0 : s / static_cast<double>(starts.size());
}

int ScenarioNumbers::passed() const {
  return static_cast<int>(
      std::count_if(starts.begin(), starts.end(), [](const TunnelNumbers& t) { return t.passed; }));
}

double CandidateNumbers::intact_max_yaw_deg() const {
  double m = 0.0;
  for (double y : intact_yaw_deg) m = std::max(m, std::abs(y));
  return m;
}

double CandidateNumbers::intact_mean_speed_m_s() const {
  return mean(intact_speed_m_s);
}

CandidateNumbers measure_candidate(const CalibrationSpec& spec, const robot::BodyParams& body) {
  CandidateNumbers n;
  RobotSpec candidate = spec.robot;
  candidate.sim.body = body;
  try {
    candidate.sim.scene.tunnel = false;
    const sim::SimModel open = make_model(candidate);
    for (long w : spec.warmups) {
      sim::WalkSpec walk;
      walk.start.warmup = w;
      walk.settle = kIntactSettleSteps;
      walk.steps = kIntactSteps;
      walk.record = false;
      const sim::WalkResult r = sim::walk(open, walk);
      for (const body::WindowMeasure& m : r.windows) n.intact_yaw_deg.push_back(m.yaw_deg);
      n.intact_speed_m_s.push_back(r.speed_m_s);
    }
    candidate.sim.scene.tunnel = true;
    const sim::SimModel corridor = make_model(candidate);
    const Scenarios sc = table1_scenarios(open.controller.morphology);
    for (const Scenario1& s : sc.fit) {
      n.fit.push_back(walk_scenario(corridor, s, spec.warmups, kCalibrationFitSteps));
    }
    for (const Scenario1& s : sc.paper_periods) {
      n.paper_periods.push_back(walk_scenario(corridor, s, spec.warmups, kCalibrationCheckSteps));
    }
    for (const Scenario1& s : sc.mirrors) {
      n.mirrors.push_back(walk_scenario(corridor, s, spec.warmups, kCalibrationFitSteps));
    }
  } catch (const RuntimeFailure& e) {
    // A body the physics cannot walk (it blew up): a candidate that ranks last, not a failed
    // calibration.
    CandidateNumbers failed;
    failed.failure = e.what();
    return failed;
  }
  n.score_deg = score(n.fit);
  n.violation = violation(n);
  return n;
}

bool better(const CandidateNumbers& a, const CandidateNumbers& b) {
  if (a.failure.empty() != b.failure.empty()) return a.failure.empty();
  if (!a.failure.empty()) return false;
  if (a.violation != b.violation) return a.violation < b.violation;
  return a.score_deg < b.score_deg;
}

nlohmann::json calibration_arguments(const CalibrationSpec& spec) {
  // The searched values of the base body never reach a candidate: recorded as paper-sim's, so
  // that a base body differing only in them is the same calibration.
  sim::SimOptions base = spec.robot.sim;
  const robot::BodyParams reference;
  for (const SearchedParam& p : spec.params) {
    const robot::NumberParam& param = robot::number_param(p.key);
    param.set(base.body, param.get(reference));
  }
  nlohmann::json params = nlohmann::json::array();
  for (const SearchedParam& p : spec.params) params.push_back(to_json(p));
  const std::vector<double> t = targets();
  return {{"target", to_string(spec.target)},
          {"target_deg", t},
          {"robot", robot::to_string(spec.robot.kind)},
          {"sim", base},
          {"params", params},
          {"budget", spec.budget},
          {"seed", spec.seed},
          {"warmups", spec.warmups},
          {"design_share", kDesignShare},
          {"compass_steps", {kCompassFirstStep, kCompassLastStep}},
          {"design_draws", kDesignDraws},
          {"tunnel_steps", {{"fit", kCalibrationFitSteps}, {"checks", kCalibrationCheckSteps}}},
          {"intact",
           {{"straight_deg", kIntactStraightDeg},
            {"settle_steps", kIntactSettleSteps},
            {"steps", kIntactSteps},
            {"speed_m_s", {kPlausibleSpeedMS.lo, kPlausibleSpeedMS.hi}}}}};
}

Calibration run_calibration(const CalibrationSpec& spec, const fs::path& out, int jobs,
                            bool progress) {
  validate(spec);
  Calibration cal;
  cal.spec = spec;
  const std::size_t d = spec.params.size();
  const auto budget = static_cast<std::size_t>(spec.budget);
  const std::size_t n_design =
      std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(kDesignShare * spec.budget)),
                              std::min<std::size_t>(2, budget), budget);

  std::vector<Candidate> design;
  const std::vector<Point> pts = maximin_design(n_design, d, spec.seed);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    design.push_back({design_id(i), "design", pts[i], body_at(spec, pts[i]), {}});
  }
  cal.candidates = run_stage(spec, out, "design", std::move(design), "design", jobs, progress,
                             cal.loaded, cal.ran);

  // Compass search: poll +-step along each axis around the best so far; move to the best poll
  // point if it beats the centre, else halve the step.
  std::set<Point> walked;
  for (const Candidate& c : cal.candidates) walked.insert(c.u);
  double step = kCompassFirstStep;
  int round = 0;
  while (cal.candidates.size() < budget && step >= kCompassLastStep) {
    const std::size_t centre = best_of(cal.candidates);
    const Point& u0 = cal.candidates[centre].u;
    std::vector<Candidate> poll;
    const std::string stage = round_name(round + 1);
    for (std::size_t j = 0; j < d && cal.candidates.size() + poll.size() < budget; ++j) {
      for (double sign : {1.0, -1.0}) {
        if (cal.candidates.size() + poll.size() >= budget) break;
        Point u = u0;
        u[j] = std::clamp(u[j] + sign * step, 0.0, 1.0);
        if (walked.contains(u)) continue;
        walked.insert(u);
        poll.push_back(
            {fmt::format("r{:02}-{:02}", round + 1, poll.size()), stage, u, body_at(spec, u), {}});
      }
    }
    if (poll.empty()) {
      step /= 2.0;
      continue;
    }
    ++round;
    const nlohmann::json info{
        {"name", stage}, {"centre", cal.candidates[centre].id}, {"step", step}};
    std::vector<Candidate> done =
        run_stage(spec, out, stage, std::move(poll), info, jobs, progress, cal.loaded, cal.ran);
    const std::size_t best_poll = best_of(done);
    const bool moved = better(done[best_poll].numbers, cal.candidates[centre].numbers);
    cal.candidates.insert(cal.candidates.end(), done.begin(), done.end());
    if (!moved) step /= 2.0;
  }
  cal.best = best_of(cal.candidates);
  if (!is_primary_process()) return cal;
  write_file_atomic(out / "candidates.json", calibration_json(cal).dump(kJsonIndent) + "\n");
  write_file_atomic(out / "candidates.csv", to_csv(candidates_table(cal)));
  const Candidate& best = cal.candidates[cal.best];
  nlohmann::json summary = calibration_arguments(spec);
  summary["candidates"] = cal.candidates.size();
  summary["feasible"] = std::count_if(cal.candidates.begin(), cal.candidates.end(),
                                      [](const Candidate& c) { return c.numbers.feasible(); });
  summary["best"] = {{"id", best.id},
                     {"body", best.body},
                     {"score_deg", best.numbers.score_deg},
                     {"violation", best.numbers.violation},
                     {"fit", to_json(best.numbers.fit)},
                     {"paper_periods", to_json(best.numbers.paper_periods)},
                     {"mirrors", to_json(best.numbers.mirrors)},
                     {"intact_max_yaw_deg", best.numbers.intact_max_yaw_deg()},
                     {"intact_speed_m_s", best.numbers.intact_mean_speed_m_s()}};
  write_file_atomic(out / "summary.json", summary.dump(kJsonIndent) + "\n");
  return cal;
}

Table candidates_table(const Calibration& cal) {
  Table t;
  const auto column = [&t](std::string title) { t.columns.push_back({std::move(title)}); };
  column("id");
  column("stage");
  for (const SearchedParam& p : cal.spec.params) column(p.key);
  // A failed candidate has no scenarios: the names come from the scenarios of Table 1.
  const Scenarios sc = table1_scenarios(morphology(cal.spec.robot));
  const std::size_t starts = cal.spec.warmups.size();
  const auto scenario_columns = [&](const std::vector<Scenario1>& v, const std::string& prefix) {
    for (const Scenario1& s : v) {
      column(prefix + s.name + " mean_deg");
      for (std::size_t k = 0; k < starts; ++k) {
        column(prefix + s.name + " start" + std::to_string(k + 1) + "_deg");
      }
      column(prefix + s.name + " passed");
    }
  };
  scenario_columns(sc.fit, kFitPrefix);
  scenario_columns(sc.paper_periods, kPaperPrefix);
  scenario_columns(sc.mirrors, kMirrorPrefix);
  for (const char* h :
       {kIntactYawColumn, kSpeedColumn, kScoreColumn, "violation", "feasible", "failure"}) {
    column(h);
  }
  for (const Candidate& c : cal.candidates) {
    std::vector<std::string> row{c.id, c.stage};
    for (const SearchedParam& p : cal.spec.params) {
      row.push_back(format_number(robot::number_param(p.key).get(c.body)));
    }
    const auto cells = [&](const std::vector<ScenarioNumbers>& v, std::size_t count) {
      for (std::size_t i = 0; i < count; ++i) {
        if (i >= v.size()) {
          row.insert(row.end(), starts + 2, "");
          continue;
        }
        row.push_back(format_number(v[i].mean_deg()));
        for (const TunnelNumbers& n : v[i].starts) row.push_back(format_number(n.deviation_deg));
        row.push_back(std::to_string(v[i].passed()));
      }
    };
    cells(c.numbers.fit, sc.fit.size());
    cells(c.numbers.paper_periods, sc.paper_periods.size());
    cells(c.numbers.mirrors, sc.mirrors.size());
    const bool ok = c.numbers.failure.empty();
    row.push_back(ok ? format_number(c.numbers.intact_max_yaw_deg()) : "");
    row.push_back(ok ? format_number(kCmPerM * c.numbers.intact_mean_speed_m_s()) : "");
    row.push_back(ok ? format_number(c.numbers.score_deg) : "");
    row.push_back(ok ? format_number(c.numbers.violation) : "");
    row.push_back(c.numbers.feasible() ? "1" : "0");
    row.push_back(c.numbers.failure);
    t.add_row(std::move(row));
  }
  return t;
}

}  // namespace multicpg::experiments
