#include "experiments/landscape.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/learning_run.h"
#include "experiments/processes.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "learning/compensation.h"
#include "learning/json.h"
#include "robot/leg_sets.h"
#include "sim/json.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace multicpg::experiments {
namespace {

constexpr int kJsonIndent = 2;

bool is_disabled(const std::vector<std::size_t>& disabled, std::size_t leg) {
  return std::find(disabled.begin(), disabled.end(), leg) != disabled.end();
}

bool in_period_set(const LandscapeSpec& spec, int period) {
  return std::find(spec.period_set.begin(), spec.period_set.end(), period) != spec.period_set.end();
}

std::vector<std::size_t> working_legs(const robot::Morphology& morph,
                                      const std::vector<std::size_t>& disabled) {
  std::vector<std::size_t> out;
  for (std::size_t leg = 0; leg < morph.size(); ++leg) {
    if (!is_disabled(disabled, leg)) out.push_back(leg);
  }
  return out;
}

nlohmann::json periods_json(const robot::Morphology& morph,
                            const std::vector<std::size_t>& disabled,
                            const learning::Periods& periods) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t leg : working_legs(morph, disabled)) out[morph.legs[leg].name] = periods[leg];
  return out;
}

nlohmann::json arguments(const LandscapeSpec& spec) {
  // The simulation options whole (sim/json.h), so a changed controller parameter is refused on
  // resume like any other option; a robot file by its record, so a changed file is too.
  nlohmann::json args{{"experiment", "landscape"},
                      {"robot", robot::to_string(spec.robot.kind)},
                      {"disabled", robot::leg_set_json(morphology(spec.robot), spec.disabled)},
                      {"period_set", spec.period_set},
                      {"windows", spec.windows},
                      {"window_steps", spec.window_steps},
                      {"threshold_deg", spec.threshold_deg},
                      {"controller_warmup", body::kControllerWarmup},
                      {"sim", spec.robot.sim}};
  // Only a reflex landscape names its walk, so landscapes walked before there was one resume.
  if (spec.steering == learning::Steering::reflex) {
    const learning::CompensationOptions o = landscape_options(spec);
    args["steering"] = learning::to_string(o.steering);
    args["steering_params"] = o.steering_params;
    args["monitor_windows"] = o.monitor_windows;
  }
  record_robot_file(args, spec.robot);
  return args;
}

nlohmann::json window_json(const body::WindowMeasure& w, learning::Steering steering) {
  nlohmann::json j{{"yaw_deg", w.yaw_deg},
                   {"path_deg", w.path_deg},
                   {"forward_m", w.forward_m},
                   {"lateral_m", w.lateral_m}};
  if (steering == learning::Steering::reflex) j["steering_effort"] = w.steering_effort;
  return j;
}

double share(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

void validate(const LandscapeSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  std::set<std::size_t> seen;
  for (std::size_t leg : spec.disabled) {
    if (leg >= morph.size()) {
      throw BadInput("the " + morph.name + " has no leg number " + std::to_string(leg));
    }
    if (!seen.insert(leg).second) {
      throw BadInput("leg " + morph.legs[leg].name + " is disabled twice");
    }
  }
  if (seen.size() == morph.size()) {
    throw BadInput("every leg of the " + morph.name + " is disabled: there is no landscape");
  }
  learning::AnnealingParams params;
  params.period_set = spec.period_set;
  params.threshold_deg = spec.threshold_deg;
  learning::validate(params);  // also refuses periods that give no gait
  if (spec.windows < 1) {
    throw BadInput("windows must be at least 1, got " + std::to_string(spec.windows));
  }
  if (spec.window_steps < 1) {
    throw BadInput("window steps must be at least 1, got " + std::to_string(spec.window_steps));
  }
}

CombinationMeasure measure_combination(const sim::SimModel& model,
                                       const std::vector<std::size_t>& disabled,
                                       const learning::Periods& periods, int windows,
                                       long window_steps, double threshold_deg) {
  if (windows < 1) throw BadInput("windows must be at least 1, got " + std::to_string(windows));
  // A robot already walking on its remaining legs: locked controller, full delay lines.
  body::FaultTimeline faults;
  if (!disabled.empty()) faults.push_back({0, disabled, false});
  sim::Stepper stepper(model, {}, std::move(faults));
  neural::ControllerState& controller = stepper.state().controller;

  // Learning tries every candidate with the clients free (docs/controller.md "Synchronisation");
  // equal periods stay locked because set_periods resets every CPG together.
  CombinationMeasure m;
  m.periods = periods;
  neural::set_periods(model.controller, controller, periods);
  neural::set_synchronised(controller, false);
  m.settle_steps = learning::locked_settle_steps(model.controller, periods);
  stepper.steps(m.settle_steps);

  m.holds = true;
  for (int w = 0; w < windows; ++w) {
    const body::Pose2 start = stepper.pose();
    stepper.steps(window_steps);
    const body::WindowMeasure window = body::measure_window(start, stepper.pose());
    m.worst_deg = std::max(m.worst_deg, window.worst_deg());
    m.holds = m.holds && body::holds(window.worst_deg(), threshold_deg);
    m.windows.push_back(window);
  }
  m.first_window_passes = body::holds(std::abs(m.windows.front().yaw_deg), threshold_deg);
  return m;
}

learning::CompensationOptions landscape_options(const LandscapeSpec& spec) {
  learning::CompensationOptions o;
  o.mode = learning::Mode::robust;
  o.steering = spec.steering;
  o.search.period_set = spec.period_set;
  o.search.threshold_deg = spec.threshold_deg;
  o.window_steps = spec.window_steps;
  o.hold_windows = spec.windows;
  return o;
}

LandscapeStart walk_landscape_start(const sim::SimModel& model, const LandscapeSpec& spec) {
  if (spec.steering != learning::Steering::reflex) {
    throw std::logic_error("walk_landscape_start: a landscape of periods alone has no start walk");
  }
  const learning::CompensationOptions options = landscape_options(spec);
  body::FaultTimeline faults;
  if (!spec.disabled.empty()) faults.push_back({0, spec.disabled, false});
  sim::Stepper stepper(model, learning_start(options.mode), std::move(faults));
  sim::SimBody body(stepper);
  learning::CourseWalk walk(body, options);
  LandscapeStart start;
  start.windows = learning::watch_until_deviation(walk, options);
  start.body = stepper.checkpoint();
  start.walk = walk.state();
  return start;
}

CombinationMeasure measure_from_start(const sim::SimModel& model, const LandscapeSpec& spec,
                                      const LandscapeStart& start,
                                      const learning::Periods& periods) {
  const learning::CompensationOptions options = landscape_options(spec);
  sim::Stepper stepper = sim::Stepper::resume(model, start.body);
  sim::SimBody body(stepper);
  learning::CourseWalk walk(body, options, start.walk);
  neural::set_synchronised(stepper.state().controller, false);  // paper §2.3, as a detection
  CombinationMeasure m;
  m.periods = periods;
  m.settle_steps = learning::locked_settle_steps(model.controller, periods);
  const learning::Measurement trial = learning::robust_trial(walk, options, periods, spec.windows);
  m.windows = trial.windows;
  m.worst_deg = trial.deviation_deg;
  m.holds = static_cast<int>(m.windows.size()) == spec.windows &&
            body::holds(m.worst_deg, spec.threshold_deg);
  m.first_window_passes = body::holds(std::abs(m.windows.front().yaw_deg), spec.threshold_deg);
  return m;
}

std::vector<learning::Periods> landscape_combinations(const LandscapeSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  const std::vector<std::size_t> working = working_legs(morph, spec.disabled);
  std::vector<std::size_t> digit(working.size(), 0);
  std::vector<learning::Periods> out;
  for (;;) {
    learning::Periods periods(morph.size(), learning::kStartPeriod);
    for (std::size_t i = 0; i < working.size(); ++i) {
      periods[working[i]] = spec.period_set[digit[i]];
    }
    out.push_back(periods);
    // Odometer: the last working leg varies fastest.
    std::size_t i = working.size();
    while (i > 0 && ++digit[i - 1] == spec.period_set.size()) digit[--i] = 0;
    if (i == 0) return out;
  }
}

std::string combination_key(const robot::Morphology& morph,
                            const std::vector<std::size_t>& disabled,
                            const learning::Periods& periods) {
  std::string out;
  for (std::size_t leg : working_legs(morph, disabled)) {
    if (!out.empty()) out += '_';
    out += morph.legs[leg].name + "-" + std::to_string(periods[leg]);
  }
  return out;
}

nlohmann::json to_json(const CombinationMeasure& m, const robot::Morphology& morph,
                       learning::Steering steering) {
  nlohmann::json windows = nlohmann::json::array();
  for (const body::WindowMeasure& w : m.windows) windows.push_back(window_json(w, steering));
  return {{"periods", robot::period_map_json(morph, m.periods)},
          {"settle_steps", m.settle_steps},
          {"windows", windows},
          {"worst_deg", m.worst_deg},
          {"holds", m.holds},
          {"first_window_passes", m.first_window_passes}};
}

CombinationMeasure combination_from_json(const nlohmann::json& j, const robot::Morphology& morph) {
  CombinationMeasure m;
  m.periods = robot::period_map_from_json(morph, j.at("periods"));
  m.settle_steps = j.at("settle_steps");
  for (const nlohmann::json& w : j.at("windows")) {
    m.windows.push_back({w.at("yaw_deg"), w.at("path_deg"), w.at("forward_m"), w.at("lateral_m"),
                         w.value("steering_effort", 0.0)});
  }
  m.worst_deg = j.at("worst_deg");
  m.holds = j.at("holds");
  m.first_window_passes = j.at("first_window_passes");
  return m;
}

std::vector<std::size_t> ranked_combinations(const Landscape& landscape) {
  const std::vector<CombinationMeasure>& c = landscape.combinations;
  std::vector<std::size_t> order(c.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return c[a].worst_deg < c[b].worst_deg; });
  return order;
}

std::optional<std::size_t> best_combination(const Landscape& landscape) {
  for (std::size_t i : ranked_combinations(landscape)) {
    if (landscape.combinations[i].holds) return i;
  }
  return std::nullopt;
}

namespace {

RunnerOptions landscape_runner(const LandscapeSpec& spec, const std::filesystem::path& out,
                               int jobs, bool progress, const std::string& progress_label) {
  RunnerOptions runner;
  runner.out_dir = out;
  runner.jobs = jobs;
  runner.arguments = arguments(spec);
  runner.progress = progress;
  runner.progress_label = progress_label;
  validate(runner);
  return runner;
}

std::vector<Task> landscape_tasks(const LandscapeSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  const std::vector<learning::Periods> combinations = landscape_combinations(spec);
  std::vector<Task> tasks;
  for (std::size_t i = 0; i < combinations.size(); ++i) {
    Task task;
    task.key = combination_key(morph, spec.disabled, combinations[i]);
    task.group = "landscape";
    task.run = static_cast<int>(i);
    task.params = {{"periods", combinations[i]}};
    tasks.push_back(std::move(task));
  }
  return tasks;
}

}  // namespace

Landscape run_landscape(const LandscapeSpec& spec, const std::filesystem::path& out, int jobs,
                        bool progress, const std::vector<learning::Periods>& learned,
                        const std::string& progress_label) {
  validate(spec);
  const robot::Morphology& morph = morphology(spec.robot);
  const RunnerOptions runner = landscape_runner(spec, out, jobs, progress, progress_label);
  const std::vector<Task> tasks = landscape_tasks(spec);
  const sim::SimModel model = make_model(spec.robot);  // shared, read-only
  // A reflex landscape's one start, walked by every process (it is the same for all).
  std::optional<LandscapeStart> start;
  if (spec.steering == learning::Steering::reflex) start = walk_landscape_start(model, spec);
  const RunnerOutcome outcome = run_tasks(
      tasks,
      [&](const Task& task) {
        const learning::Periods periods = task.params.at("periods");
        const CombinationMeasure m =
            start ? measure_from_start(model, spec, *start, periods)
                  : measure_combination(model, spec.disabled, periods, spec.windows,
                                        spec.window_steps, spec.threshold_deg);
        return to_json(m, morph, spec.steering);
      },
      runner);

  Landscape landscape{spec, {}, start ? start->windows : std::vector<body::WindowMeasure>{}};
  for (const nlohmann::json& result : outcome.results) {
    landscape.combinations.push_back(combination_from_json(result, morph));
  }
  if (!is_primary_process()) return landscape;  // the primary writes OUT
  write_file_atomic(out / "landscape.csv", landscape_csv(landscape));
  write_file_atomic(out / "summary.json",
                    landscape_summary(landscape, learned).dump(kJsonIndent) + "\n");
  return landscape;
}

std::filesystem::path landscape_set_dir(const std::filesystem::path& out,
                                        const LandscapeSpec& spec) {
  return out / robot::leg_set_name(morphology(spec.robot), spec.disabled);
}

std::filesystem::path landscape_set_dataset(const std::filesystem::path& out) {
  return out / "landscapes";
}

std::vector<Landscape> run_landscape_set(const std::vector<LandscapeSpec>& specs,
                                         const std::filesystem::path& out, int jobs,
                                         bool progress) {
  // Every scenario's saved runs checked before any resumes: a damaged one is refused first.
  for (const LandscapeSpec& spec : specs) {
    validate(spec);
    check_out_dir(landscape_tasks(spec),
                  landscape_runner(spec, landscape_set_dir(out, spec), jobs, progress, ""));
  }
  std::vector<Landscape> landscapes;
  for (const LandscapeSpec& spec : specs) {
    landscapes.push_back(run_landscape(spec, landscape_set_dir(out, spec), jobs, progress));
  }
  if (is_primary_process()) {
    learning::write_landscape_dataset(landscape_dataset(landscapes), landscape_set_dataset(out));
  }
  return landscapes;
}

learning::LandscapeDataset landscape_dataset(const std::vector<Landscape>& landscapes) {
  learning::LandscapeDataset d;
  if (landscapes.empty()) return d;
  const LandscapeSpec& first = landscapes.front().spec;
  d.robot = first.robot.kind;
  d.period_set = first.period_set;
  d.windows = first.windows;
  d.window_steps = first.window_steps;
  d.threshold_deg = first.threshold_deg;
  d.sim = first.robot.sim;
  if (first.robot.file) d.robot_file = first.robot.file->record;
  if (first.steering == learning::Steering::reflex) {
    const learning::CompensationOptions o = landscape_options(first);
    d.reflex = o.steering_params;
    d.monitor_windows = o.monitor_windows;
  }
  for (const Landscape& l : landscapes) {
    learning::ScenarioLandscape s;
    s.failed = l.spec.disabled;
    s.start_windows = l.start_windows;
    for (const CombinationMeasure& m : l.combinations) {
      s.points.push_back({m.periods, m.windows, m.worst_deg, m.holds});
    }
    d.scenarios.push_back(std::move(s));
  }
  return d;
}

std::string landscape_csv(const Landscape& landscape) {
  const LandscapeSpec& spec = landscape.spec;
  const robot::Morphology& morph = morphology(spec.robot);
  const std::vector<std::size_t> working = working_legs(morph, spec.disabled);
  const bool reflex = spec.steering == learning::Steering::reflex;
  std::string out;
  for (std::size_t leg : working) out += morph.legs[leg].name + ",";
  for (int w = 1; w <= spec.windows; ++w) {
    const std::string n = std::to_string(w);
    out += "w" + n + "_yaw_deg,w" + n + "_path_deg,";
    if (reflex) out += "w" + n + "_steering_effort,";
  }
  out += "worst_deg,holds,first_window_passes\n";
  for (const CombinationMeasure& m : landscape.combinations) {
    for (std::size_t leg : working) out += std::to_string(m.periods[leg]) + ",";
    for (std::size_t w = 0; w < static_cast<std::size_t>(spec.windows); ++w) {
      // A window not walked (after the first over the threshold) is an empty cell.
      if (w < m.windows.size()) {
        out +=
            format_number(m.windows[w].yaw_deg) + "," + format_number(m.windows[w].path_deg) + ",";
        if (reflex) out += format_number(m.windows[w].steering_effort) + ",";
      } else {
        out += reflex ? ",,," : ",,";
      }
    }
    out += format_number(m.worst_deg) + "," + (m.holds ? "1," : "0,") +
           (m.first_window_passes ? "1\n" : "0\n");
  }
  return out;
}

nlohmann::json landscape_summary(const Landscape& landscape,
                                 const std::vector<learning::Periods>& learned) {
  const LandscapeSpec& spec = landscape.spec;
  const robot::Morphology& morph = morphology(spec.robot);
  const std::vector<CombinationMeasure>& c = landscape.combinations;
  const auto entry = [&](std::size_t i) {
    return nlohmann::json{{"periods", periods_json(morph, spec.disabled, c[i].periods)},
                          {"worst_deg", c[i].worst_deg},
                          {"holds", c[i].holds},
                          {"first_window_passes", c[i].first_window_passes}};
  };
  const std::size_t holding =
      std::count_if(c.begin(), c.end(), [](const CombinationMeasure& m) { return m.holds; });
  const std::size_t first = std::count_if(
      c.begin(), c.end(), [](const CombinationMeasure& m) { return m.first_window_passes; });

  const std::vector<std::size_t> ranked = ranked_combinations(landscape);
  std::vector<std::size_t> rank_of(c.size());
  for (std::size_t r = 0; r < ranked.size(); ++r) rank_of[ranked[r]] = r + 1;
  nlohmann::json top = nlohmann::json::array();
  for (std::size_t r = 0; r < std::min(kLandscapeTop, ranked.size()); ++r) {
    top.push_back(entry(ranked[r]));
  }
  nlohmann::json learned_json = nlohmann::json::array();
  for (const learning::Periods& periods : learned) {
    const auto it = std::find_if(c.begin(), c.end(),
                                 [&](const CombinationMeasure& m) { return m.periods == periods; });
    if (it == c.end()) throw std::logic_error("a learned combination is not in the landscape");
    nlohmann::json e = entry(static_cast<std::size_t>(it - c.begin()));
    e["rank"] = rank_of[static_cast<std::size_t>(it - c.begin())];
    learned_json.push_back(e);
  }
  const std::optional<std::size_t> best = best_combination(landscape);

  nlohmann::json summary = arguments(spec);
  if (spec.steering == learning::Steering::reflex) {
    nlohmann::json start = nlohmann::json::array();
    for (const body::WindowMeasure& w : landscape.start_windows) {
      start.push_back(window_json(w, spec.steering));
    }
    summary["start_windows"] = start;
  }
  summary["count"] = c.size();
  summary["holding"] = holding;
  summary["share_holding"] = share(holding, c.size());
  summary["first_window_passing"] = first;
  summary["share_first_window_passing"] = share(first, c.size());
  summary["best"] = best ? entry(*best) : nlohmann::json(nullptr);
  summary["top"] = top;
  summary["learned"] = learned_json;
  return summary;
}

bool in_landscape(const LandscapeSpec& spec, const learning::Periods& periods) {
  for (std::size_t leg = 0; leg < periods.size(); ++leg) {
    if (!is_disabled(spec.disabled, leg) && !in_period_set(spec, periods[leg])) return false;
  }
  return true;
}

std::vector<learning::Periods> parse_learned(const nlohmann::json& j, const LandscapeSpec& spec) {
  const robot::Morphology& morph = morphology(spec.robot);
  if (!j.is_array()) throw BadInput("learned combinations: expected a JSON array of {leg: period}");
  std::vector<learning::Periods> out;
  for (std::size_t n = 0; n < j.size(); ++n) {
    const std::string where = "learned combination " + std::to_string(n + 1);
    if (!j[n].is_object()) throw BadInput(where + " is not a {leg: period} object");
    learning::Periods periods(morph.size(), learning::kStartPeriod);
    std::vector<bool> named(morph.size(), false);
    for (const auto& [name, value] : j[n].items()) {
      const std::size_t leg = robot::leg_index(morph, name);
      named[leg] = true;
      if (is_disabled(spec.disabled, leg)) continue;
      if (!value.is_number_integer() || !in_period_set(spec, value.get<int>())) {
        throw BadInput(where + ": " + name + " = " + value.dump() + " is not in the period set");
      }
      periods[leg] = value.get<int>();
    }
    for (std::size_t leg : working_legs(morph, spec.disabled)) {
      if (!named[leg]) throw BadInput(where + " does not name leg " + morph.legs[leg].name);
    }
    out.push_back(periods);
  }
  return out;
}

}  // namespace multicpg::experiments
