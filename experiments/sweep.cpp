#include "experiments/sweep.h"

#include <algorithm>
#include <charconv>
#include <set>

#include "common/errors.h"
#include "common/interrupt.h"
#include "common/limits.h"
#include "experiments/document_scenarios.h"
#include "experiments/learner_table.h"
#include "experiments/run_json.h"
#include "experiments/scenarios.h"
#include "learning/choice_options.h"
#include "learning/default_learner.h"
#include "learning/json.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "sim/json.h"
#include "sim/robot_file.h"
#include "sim/sim.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using document::canonical_sim;
using document::child;
using document::join;
using document::merge_checked;
using document::options_from;
using document::pointer_in_section;
using document::value_text;
using document::whole;
using nlohmann::json;

// Keys each run sets itself: its disabled legs or fault timeline and its seed.
const std::set<std::string> kPerRunLearningKeys{"disabled", "faults", "seed"};
// The document's step at which a scenario's leg set fails (learning.fail_step): a key of the
// "learning" table, read by the sweep, not by the learner.
constexpr const char* kFailStepKey = "fail_step";

// The grid points: one value per axis, the first axis slowest.
std::vector<std::vector<json>> grid_points(const std::vector<GridAxis>& grid) {
  std::vector<std::vector<json>> points{{}};
  for (const GridAxis& axis : grid) {
    std::vector<std::vector<json>> next;
    for (const std::vector<json>& p : points) {
      for (const json& v : axis.values) {
        next.push_back(p);
        next.back().push_back(v);
      }
    }
    points = std::move(next);
  }
  return points;
}

// Short axis names for keys and groups: the last key part, the whole key when two share it.
std::vector<std::string> axis_names(const std::vector<GridAxis>& grid) {
  std::vector<std::string> names;
  for (const GridAxis& a : grid) names.push_back(a.key.substr(a.key.rfind('.') + 1));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::count(names.begin(), names.end(), names[i]) > 1) names[i] = grid[i].key;
  }
  return names;
}

// `factors` multiplied, and whether the product fits 64 bits.
struct Product {
  std::uint64_t value = 1;
  bool overflow = false;
  long double approximate = 1;  // for the message when it does not fit
};
Product multiply(const std::vector<std::uint64_t>& factors) {
  Product p;
  for (std::uint64_t f : factors) {
    p.overflow = p.overflow || __builtin_mul_overflow(p.value, f, &p.value);
    p.approximate *= static_cast<long double>(f);
  }
  return p;
}

// Refuses `product` (of `parts`, "learning.annealing.beta: 10 values x 2 scenarios x 5 runs")
// when it exceeds the limit, before a single run is made.
void check_count(const Product& product, const std::string& what, const std::string& parts,
                 const SweepLimits& limits) {
  if (!product.overflow && product.value <= static_cast<std::uint64_t>(limits.max_runs)) return;
  const std::string count =
      product.overflow ? fmt::format("about {:.2e}", static_cast<double>(product.approximate))
                       : std::to_string(product.value);
  throw BadInput(count + " " + what + " (" + parts + "), more than the " +
                 std::to_string(limits.max_runs) + " allowed (" + limits.max_runs_name + ")");
}

// The runs a learning sweep will make: every grid point x scenario x run.
void check_run_count(const std::vector<GridAxis>& grid, std::size_t scenarios, int runs,
                     const SweepLimits& limits) {
  std::vector<std::uint64_t> factors;
  std::vector<std::string> parts;
  for (const GridAxis& axis : grid) {
    factors.push_back(axis.values.size());
    parts.push_back(axis.key + ": " + std::to_string(axis.values.size()) + " values");
  }
  const auto counted = [](std::uint64_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  factors.push_back(scenarios);
  parts.push_back(counted(scenarios, "scenario"));
  factors.push_back(static_cast<std::uint64_t>(runs));
  parts.push_back(counted(static_cast<std::uint64_t>(runs), "run"));
  check_count(multiply(factors), "runs", join(parts, " x "), limits);
}

// The defaults [sim] is merged onto: the simulation's, with the body of the document's
// sim.model (a model supplies the body, [sim.body] keys override it).
json sim_defaults(const json& doc) {
  sim::SimOptions defaults;
  const json section = doc.value("sim", json::object());
  if (section.is_object() && section.contains("model")) {
    const json& name = section.at("model");
    if (name.is_array()) {
      throw OptionError("sim.model",
                        "takes one model per experiment (one file per model), got " + name.dump());
    }
    if (!name.is_string()) {
      throw OptionError("sim.model", "must be a model name (a string), got " + name.dump());
    }
    try {
      defaults.model = robot::parse_body_model(name.get<std::string>());
    } catch (const BadInput& e) {
      throw OptionError("sim.model", e.what());
    }
    defaults.body = robot::body_params(defaults.model);
  }
  return defaults;
}

// What a run file records of its run (Task::params; merge_sweeps checks it again): the robot,
// its label, the failing legs' names, the learning options with the run's faults in the form
// every learning record has (learning_record, run_json.h), the simulation options and what is
// recorded.
json run_params(const RunSpec& spec, const RunLabel& label) {
  json params{
      {"robot", robot::to_string(spec.robot.kind)},
      {"scenario", label.scenario},
      {"disabled", robot::leg_set_json(morphology(spec.robot), body::failing_legs(spec.faults))},
      {"grid", label.grid},
      {"learning", learning_record(*spec.learning, spec.faults)},
      {"sim", spec.robot.sim},
      {"record", {{"check_windows", spec.record.check_windows}, {"trace", spec.record.trace}}}};
  record_robot_file(params, spec.robot);
  return params;
}

const std::set<std::string> kDocumentKeys{"kind",   "robot",    "robot_file", "scenarios",
                                          "runs",   "seed",     "learning",   "sim",
                                          "record", "landscape"};
const std::set<std::string> kLandscapeKeys{"kind",      "robot",     "robot_file",
                                           "scenarios", "landscape", "sim"};

// The document's robot: a built-in robot by name, or a robot file, as `robot = "FILE.toml"` or as
// the record a resolved document keeps (`robot` its layout, `robot_file`), whose file must still
// hold what was recorded.
struct DocumentRobot {
  robot::RobotKind kind = robot::RobotKind::hexapod;
  std::shared_ptr<const RunRobotFile> file;
};

std::shared_ptr<const RunRobotFile> load_document_robot(const std::string& key,
                                                        const fs::path& path) {
  try {
    // Absolute, so the record finds it again from any working directory (rerun, resume).
    return load_run_robot_file(fs::absolute(path).lexically_normal());
  } catch (const BadInput& e) {
    throw OptionError(key, e.what());
  }
}

DocumentRobot resolve_robot(const json& doc) {
  const json name = doc.value("robot", json("hexapod"));
  if (!name.is_string()) throw OptionError("robot", "must be a string, got " + name.dump());
  const std::string text = name.get<std::string>();
  DocumentRobot robot;
  if (doc.contains("robot_file")) {
    robot.file = recorded_robot_file(doc);
    if (text != robot::to_string(robot.file->file.layout)) {
      throw OptionError("robot", "must be the robot file's layout, " +
                                     std::string(robot::to_string(robot.file->file.layout)) +
                                     ", got " + name.dump());
    }
  } else if (sim::is_robot_file(text)) {
    robot.file = load_document_robot("robot", text);
  }
  try {
    robot.kind = robot.file ? robot.file->file.layout : robot::parse_robot(text);
  } catch (const BadInput& e) {
    throw OptionError("robot", e.what());
  }
  return robot;
}

// The resolved document's robot: its layout's name, and the robot file's record.
void add_robot(json& resolved, const DocumentRobot& robot) {
  resolved["robot"] = robot::to_string(robot.kind);
  record_robot_file(resolved, robot.file);
}

json landscape_json(const LandscapeSpec& spec) {
  return {{"period_set", spec.period_set},
          {"windows", spec.windows},
          {"window_steps", spec.window_steps},
          {"threshold_deg", spec.threshold_deg},
          {"steering", learning::to_string(spec.steering)}};
}

// Options of a kind that takes no grid: a list where one value belongs is refused.
void refuse_grid(const std::vector<GridAxis>& grid) {
  if (!grid.empty()) {
    throw OptionError(grid.front().key, "takes one value here (a landscape has no grid)");
  }
}

Sweep resolve_landscape(const json& doc, const DocumentRobot& robot, const SweepLimits& limits) {
  const robot::RobotKind kind = robot.kind;
  for (const auto& item : doc.items()) {
    if (!kLandscapeKeys.count(item.key())) {
      throw OptionError(item.key(), "is not a landscape key (known: " +
                                        join({kLandscapeKeys.begin(), kLandscapeKeys.end()}, ", ") +
                                        ")");
    }
  }
  const std::vector<ScenarioSpec> scenarios = resolve_scenarios(kind, doc);
  for (const ScenarioSpec& s : scenarios) {
    if (!s.faults.empty() || s.malfunction) {
      throw OptionError(s.path, "a landscape takes disabled leg sets, e.g. [\"R1\"] or \"every\"");
    }
  }
  LandscapeSpec spec;
  spec.robot.kind = kind;
  spec.robot.file = robot.file;
  spec.disabled = scenarios.front().disabled;
  std::vector<GridAxis> grid;
  const json defaults = landscape_json(spec);
  json landscape = defaults;
  merge_checked(doc.value("landscape", json::object()), defaults, "landscape", landscape, grid);
  refuse_grid(grid);
  spec.period_set = landscape.at("period_set").get<std::vector<int>>();
  spec.windows = landscape.at("windows").get<int>();
  spec.window_steps = landscape.at("window_steps").get<long>();
  spec.threshold_deg = landscape.at("threshold_deg").get<double>();
  try {
    spec.steering = learning::parse_steering(landscape.at("steering").get<std::string>());
  } catch (const BadInput& e) {
    throw OptionError("landscape.steering", e.what());
  }
  const json sim_default = sim_defaults(doc);
  json sim_doc = sim_default;
  merge_checked(doc.value("sim", json::object()), sim_default, "sim", sim_doc, grid);
  refuse_grid(grid);
  spec.robot.sim = options_from<sim::SimOptions>(canonical_sim(sim_doc), "sim");
  try {
    validate(spec);
  } catch (const OptionError& e) {
    throw OptionError(child("landscape", e.key()), e.what());
  } catch (const BadInput& e) {
    throw OptionError("landscape", e.what());
  }
  validate(spec.robot);  // its options, and a robot file's body, as for any run of it
  Sweep sweep;
  sweep.robot = kind;
  sweep.robot_file = robot.file;
  json names = json::array();
  const auto working_legs = [&](const ScenarioSpec& s) {
    return robot::morphology(kind).size() - s.disabled.size();
  };
  Product combinations{0, false, 0};
  for (const ScenarioSpec& s : scenarios) {
    spec.disabled = s.disabled;
    try {
      validate(spec);
    } catch (const BadInput& e) {
      throw OptionError(s.path, e.what());
    }
    const Product p = multiply(std::vector<std::uint64_t>(working_legs(s), spec.period_set.size()));
    combinations.overflow =
        combinations.overflow || p.overflow ||
        __builtin_add_overflow(combinations.value, p.value, &combinations.value);
    combinations.approximate += p.approximate;
    sweep.landscapes.push_back(spec);
    names.push_back(s.name);
  }
  std::string parts = std::to_string(spec.period_set.size()) + " periods ^ ";
  const bool same_count = std::all_of(
      scenarios.begin(), scenarios.end(),
      [&](const ScenarioSpec& s) { return working_legs(s) == working_legs(scenarios.front()); });
  parts += same_count ? std::to_string(working_legs(scenarios.front())) + " working legs"
                      : "working legs";
  if (scenarios.size() > 1)
    parts += ", summed over " + std::to_string(scenarios.size()) + " scenarios";
  check_count(combinations, "combinations", parts, limits);
  sweep.resolved = {{"kind", "landscape"},
                    {"scenarios", names},
                    {"landscape", landscape_json(spec)},
                    {"sim", sim_doc}};
  add_robot(sweep.resolved, robot);
  return sweep;
}

}  // namespace

Shard parse_shard(std::string_view text) {
  const auto bad = [&] {
    return BadInput("--shard must be i/N with 0 <= i < N, got '" + std::string(text) + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) throw bad();
  Shard s;
  const auto read = [&](std::string_view part, int& v) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (ec != std::errc() || end != part.data() + part.size() || part.empty()) throw bad();
  };
  read(text.substr(0, slash), s.index);
  read(text.substr(slash + 1), s.count);
  if (s.count < 1 || s.index < 0 || s.index >= s.count) throw bad();
  return s;
}

std::string to_string(const Shard& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

nlohmann::json landscape_document(const LandscapeSpec& spec) {
  json doc{{"kind", "landscape"},
           {"robot", robot::to_string(spec.robot.kind)},
           {"scenarios", {robot::leg_set_name(morphology(spec.robot), spec.disabled)}},
           {"landscape", landscape_json(spec)},
           {"sim", spec.robot.sim}};
  record_robot_file(doc, spec.robot);
  return doc;
}

nlohmann::json learning_document(const learning::CompensationOptions& options, long fail_step) {
  json j = options;
  for (const std::string& key : kPerRunLearningKeys) j.erase(key);
  j[kFailStepKey] = fail_step;
  return j;
}

namespace {

// The annealing named with its beta as a learner option, `learner = { name = "annealing",
// options = { beta = B } }`, written as its record writes it: beta under "annealing", the learner
// left out when nothing else is left.
void canonical_annealing(json& learning_point) {
  if (!learning_point.contains("learner")) return;
  json& learner = learning_point["learner"];
  if (!learner.is_object() || learner.value("name", json()) != learning::kPaperLearner) return;
  json* options = learner.contains("options") ? &learner["options"] : nullptr;
  if (options && options->is_object() && options->contains("beta")) {
    const json beta = options->at("beta");
    json& annealing = learning_point["annealing"];
    if (annealing.is_object() && annealing.contains("beta") &&
        annealing.at("beta") != json(learning::kDefaultBeta) && annealing.at("beta") != beta) {
      throw OptionError("learning.learner.options.beta",
                        "and learning.annealing.beta give the annealing two betas");
    }
    annealing["beta"] = beta;
    options->erase("beta");
  }
  if (learner == json(learning::LearnerChoice{})) learning_point.erase("learner");
}

// A switch its record writes only when off (learning/json.h) reads back as given only without
// its key when on.
void canonical_switches(json& learning_point) {
  static const json record = learning::CompensationOptions{};
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    const std::string key(option.key);
    if (!record.contains(key) && learning_point.value(key, json()) == json(true)) {
      learning_point.erase(key);
    }
  }
}

}  // namespace

Sweep resolve_sweep(const json& doc, const SweepLimits& limits) {
  if (!doc.is_object()) throw OptionError("", "an experiment must be a table of keys");
  document::check_bounds(doc);
  for (const auto& item : doc.items()) {
    if (!kDocumentKeys.count(item.key())) {
      throw OptionError(item.key(), "is not an experiment key (known: " +
                                        join({kDocumentKeys.begin(), kDocumentKeys.end()}, ", ") +
                                        ")");
    }
  }
  Sweep sweep;
  const json kind_value = doc.value("kind", json("learning"));
  const std::string kind = kind_value.is_string() ? kind_value.get<std::string>() : "";
  if (kind != "learning" && kind != "landscape") {
    throw OptionError("kind", "must be \"learning\" or \"landscape\", got " + kind_value.dump());
  }
  const DocumentRobot robot = resolve_robot(doc);
  sweep.robot = robot.kind;
  sweep.robot_file = robot.file;
  if (kind == "landscape") return resolve_landscape(doc, robot, limits);
  if (doc.contains("landscape")) {
    throw OptionError("landscape", "belongs to kind = \"landscape\" files");
  }
  const std::vector<ScenarioSpec> scenarios = resolve_scenarios(sweep.robot, doc);
  const int runs = whole(doc, "runs", kScenarioRuns, kRunsLimits, "runs");
  std::uint64_t seed = 1;
  if (doc.contains("seed")) {
    const json& s = doc.at("seed");
    if (!s.is_number_integer()) {
      throw OptionError("seed",
                        "must be a whole number in " + kSeedLimits.text() + ", got " + s.dump());
    }
    if (!s.is_number_unsigned() && s.get<std::int64_t>() < 0) {
      throw OptionError("seed", "must be in " + kSeedLimits.text() + ", got " + s.dump());
    }
    seed = s.get<std::uint64_t>();
    require_in("seed", seed, kSeedLimits);
  }

  // Learning and sim: defaults, the document's values, the grid.
  json learning = learning_document(learning::CompensationOptions{}, 0);
  // A switch a record writes only when off (learning/json.h) is a document's option all the same.
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    learning.emplace(std::string(option.key), true);
  }
  json learning_given = doc.value("learning", json::object());
  const std::optional<json> learner_given = take_learner(learning_given);
  // A document that sets the annealing's beta asks for the annealing (default_learner).
  const json annealing_given = learning_given.is_object()
                                   ? learning_given.value("annealing", json::object())
                                   : json::object();
  const bool beta_given = annealing_given.is_object() && annealing_given.contains("beta");
  merge_checked(learning_given, json(learning), "learning", learning, sweep.grid,
                kPerRunLearningKeys);
  if (learner_given) add_learner(*learner_given, learning, sweep.grid);
  const json sim_default = sim_defaults(doc);
  json sim_doc = sim_default;
  merge_checked(doc.value("sim", json::object()), sim_default, "sim", sim_doc, sweep.grid);

  const json record_in = doc.value("record", json::object());
  if (!record_in.is_object()) throw OptionError("record", "must be a table");
  for (const auto& item : record_in.items()) {
    if (item.key() != "check_windows" && item.key() != "trace") {
      throw OptionError(child("record", item.key()),
                        "is not a record key (known: check_windows, trace)");
    }
  }
  const long check_windows =
      whole(record_in, "check_windows", 0L, kCheckWindowsLimits, "record.check_windows");
  const json trace = record_in.value("trace", json(true));
  if (!trace.is_boolean()) throw OptionError("record.trace", "must be true or false");
  const json record{{"check_windows", check_windows}, {"trace", trace}};

  check_run_count(sweep.grid, scenarios.size(), runs, limits);

  json resolved_scenarios = json::array();
  for (const ScenarioSpec& s : scenarios) resolved_scenarios.push_back(s.resolved);
  sweep.resolved = {{"kind", kind},         {"scenarios", resolved_scenarios},
                    {"runs", runs},         {"seed", seed},
                    {"learning", learning}, {"sim", sim_doc},
                    {"record", record}};
  add_robot(sweep.resolved, robot);

  // Tasks: grid point, scenario, run; each checked before any runs.
  const bool beta_table = sweep.grid.size() == 1 &&
                          sweep.grid.front().key == "learning.annealing.beta" &&
                          scenarios.size() == 1;
  sweep.table = sweep.grid.empty() ? ExperimentKind::table
                : beta_table       ? ExperimentKind::beta
                                   : ExperimentKind::grid;
  const bool name_scenario = sweep.grid.empty() || scenarios.size() > 1;
  const std::vector<std::string> names = axis_names(sweep.grid);
  std::vector<RobotSpec> checked;  // each distinct robot of the grid is validated once
  for (const std::vector<json>& point : grid_points(sweep.grid)) {
    json learning_point = learning;
    json sim_point = sim_doc;
    json grid_values = json::object();
    std::vector<std::string> key_parts;
    std::vector<std::string> group_parts;
    for (std::size_t a = 0; a < sweep.grid.size(); ++a) {
      const std::string& key = sweep.grid[a].key;
      json& section = key.rfind("learning.", 0) == 0 ? learning_point : sim_point;
      section[pointer_in_section(key)] = point[a];
      grid_values[key] = point[a];
      key_parts.push_back(names[a] + value_text(point[a]));
      group_parts.push_back(beta_table ? value_text(point[a])
                                       : names[a] + "=" + value_text(point[a]));
    }
    const long fail_step = learning_point.at(kFailStepKey).get<long>();
    require_in(std::string("learning.") + kFailStepKey, fail_step, body::kStepLimits);
    learning_point.erase(kFailStepKey);
    // The annealing's beta is recorded as annealing.beta and the default learner (the paper's
    // annealing, no other option) is left out (learning/json.h): a point reads back as given only
    // in that form.
    canonical_annealing(learning_point);
    canonical_switches(learning_point);
    check_interrupted();  // a large sweep takes seconds to resolve
    const auto base = options_from<learning::CompensationOptions>(learning_point, "learning");
    const auto sim_options = options_from<sim::SimOptions>(canonical_sim(sim_point), "sim");
    const RobotSpec robot_point{sweep.robot, sweep.robot_file, sim_options};
    if (std::find(checked.begin(), checked.end(), robot_point) == checked.end()) {
      validate(robot_point);
      checked.push_back(robot_point);
    }
    for (const ScenarioSpec& s : scenarios) {
      RunSpec spec;
      spec.robot = robot_point;
      spec.learning = base;
      spec.start = learning_start(base.mode);
      spec.faults = s.faults;
      if (s.malfunction) {
        spec.faults = {*s.malfunction};
        spec.faults.front().step = fail_step;
      } else if (s.faults.empty()) {
        spec.faults = body::fail_at(s.disabled, fail_step);
      }
      // Without a learner the run's default for its mode, robot and faults (docs/learning.md
      // "Which learner a run uses"), recorded with every run.
      if (!learner_given) {
        const learning::LearnerChoice chosen = learning::default_learner(
            {base, sweep.robot, sweep.robot_file != nullptr, beta_given, spec.faults});
        // The annealing keeps the options the document gave it (its beta).
        if (chosen.name != base.learner.name) spec.learning->learner = chosen;
      }
      spec.record.check_windows = check_windows;
      spec.record.trace = trace.get<bool>();
      try {
        validate(spec);
      } catch (const OptionError& e) {
        if (e.key() != "faults") throw;
        throw OptionError(s.path,
                          std::string("cannot happen: ") + e.what() + " (scenario " + s.name + ")");
      }
      std::vector<std::string> kp = key_parts;
      std::vector<std::string> gp = group_parts;
      if (name_scenario) {
        kp.push_back(s.name);
        gp.push_back(s.name);
      }
      const std::string group_key = join(kp, "_");
      for (int run = 0; run < runs; ++run) {
        PlannedRun planned{Task{}, spec, RunLabel{s.name, grid_values}};
        Task& task = planned.task;
        task.key = run_key(group_key, run);
        if (task.key.size() > max_key_length()) {
          throw OptionError(name_scenario ? child(s.path, "name") : "grid",
                            "makes run files named '" + task.key + ".json', " +
                                std::to_string(task.key.size()) +
                                " characters before '.json' where a file name holds at most " +
                                std::to_string(max_key_length()) +
                                ": shorten the scenario name or the grid values");
        }
        task.group = join(gp, " ");
        task.run = run;
        task.seed = derive_seed(seed, task.key);
        planned.spec.learning->seed = task.seed;
        task.params = run_params(planned.spec, planned.label);
        sweep.runs.push_back(std::move(planned));
      }
    }
  }
  return sweep;
}

std::vector<Task> tasks_of(const Sweep& sweep) {
  std::vector<Task> tasks;
  tasks.reserve(sweep.runs.size());
  for (const PlannedRun& run : sweep.runs) tasks.push_back(run.task);
  return tasks;
}

const PlannedRun* find_run(const Sweep& sweep, std::string_view key) {
  for (const PlannedRun& run : sweep.runs) {
    if (run.task.key == key) return &run;
  }
  return nullptr;
}

}  // namespace multicpg::experiments
