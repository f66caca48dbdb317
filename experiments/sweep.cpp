#include "experiments/sweep.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/json_diff.h"
#include "common/limits.h"
#include "common/provenance.h"
#include "experiments/learning_run.h"
#include "experiments/processes.h"
#include "experiments/scenarios.h"
#include "learning/json.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "robot/terrain.h"
#include "sim/fault_spec.h"
#include "sim/json.h"
#include "sim/robot_file.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kJsonIndent = 2;
constexpr std::size_t kMaxScenarioLegs = 3;  // 1-3 disabled legs ("all"; paper Fig. 11)

// Keys each run sets itself: its disabled legs or fault timeline and its seed.
const std::set<std::string> kPerRunLearningKeys{"disabled", "faults", "seed"};
// The document's step at which a scenario's leg set fails (learning.fail_step): a key of the
// "learning" table, read by the sweep, not by the learner.
constexpr const char* kFailStepKey = "fail_step";

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string indexed(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

std::string type_name(const json& j) {
  if (j.is_boolean()) return "true or false";
  if (j.is_number_integer()) return "a whole number";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "a list";
  if (j.is_object()) return "a table";
  return "a value";
}

// Checks a single value against its default's type (no grid).
void check_type(const json& value, const json& def, const std::string& path) {
  const auto wrong = [&] {
    return OptionError(path, "must be " + type_name(def) + ", got " + value.dump());
  };
  if (def.is_null()) return;  // an optional: its from_json decides
  if (def.is_boolean() || def.is_string()) {
    if (value.type() != def.type()) throw wrong();
  } else if (def.is_number_integer()) {
    if (!value.is_number_integer()) throw wrong();
    if (def.is_number_unsigned() && value.get<std::int64_t>() < 0) {
      throw OptionError(path, "must be at least 0, got " + value.dump());
    }
  } else if (def.is_number()) {
    if (!value.is_number()) throw wrong();
  } else if (def.is_array()) {
    if (!value.is_array()) throw wrong();
    for (std::size_t i = 0; i < value.size() && !def.empty(); ++i) {
      check_type(value[i], def.front(), indexed(path, i));
    }
  } else if (def.is_object()) {
    if (!value.is_object()) throw wrong();  // an element of a list of tables
  }
}

// `value` as the default's number type: a whole number given for a fractional option is
// recorded as the fraction it means (1 -> 1.0), so equal documents record equal values.
json as_default_type(const json& value, const json& def) {
  if (def.is_number_float() && value.is_number_integer()) return value.get<double>();
  if (def.is_array() && value.is_array() && !def.empty()) {
    json out = json::array();
    for (const json& v : value) out.push_back(as_default_type(v, def.front()));
    return out;
  }
  return value;
}

// A list where the default is no list, or a list of lists where it is one: a grid axis.
bool is_grid(const json& value, const json& def) {
  if (!value.is_array()) return false;
  if (!def.is_array()) return true;
  return !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_array(); });
}

std::string known_keys(const json& def, const std::set<std::string>& except = {}) {
  std::vector<std::string> keys;
  for (const auto& item : def.items()) {
    if (!except.count(item.key())) keys.push_back(item.key());
  }
  return join(keys, ", ");
}

// `out` = the defaults `def` with the document's `value` put in, every key and type checked;
// grid lists go to `grid` (and stay lists in `out`).
void merge_checked(const json& value, const json& def, const std::string& path, json& out,
                   std::vector<GridAxis>& grid, const std::set<std::string>& forbidden = {}) {
  if (def.is_object()) {
    if (!value.is_object()) {
      throw OptionError(path, "must be a table, got " + value.dump());
    }
    for (const auto& item : value.items()) {
      const std::string key = child(path, item.key());
      if (forbidden.count(item.key())) {
        throw OptionError(key, "is set by each run (scenarios, seed), not here");
      }
      if (!def.contains(item.key())) {
        throw OptionError(key, "is not an option here (known: " + known_keys(def, forbidden) + ")");
      }
      merge_checked(item.value(), def.at(item.key()), key, out[item.key()], grid);
    }
    return;
  }
  if (is_grid(value, def)) {
    if (value.empty()) throw OptionError(path, "is an empty list");
    json values = json::array();
    for (std::size_t i = 0; i < value.size(); ++i) {
      check_type(value[i], def, indexed(path, i));
      values.push_back(as_default_type(value[i], def));
    }
    grid.push_back({path, values});
    out = values;
  } else {
    check_type(value, def, path);
    out = as_default_type(value, def);
  }
}

// "learning.annealing.beta" -> "/annealing/beta" within its section.
json::json_pointer pointer_in_section(const std::string& key) {
  std::string p = key.substr(key.find('.'));
  std::replace(p.begin(), p.end(), '.', '/');
  return json::json_pointer(p);
}

// `j` read into a T by its from_json (found by argument-dependent lookup).
template <typename T>
T decode(const json& j) {
  T t;
  from_json(j, t);
  return t;
}

// Which top-level key of `point` its from_json refuses (an unknown enum name throws without
// naming its key): each tried alone on the defaults; `section` when none alone fails.
template <typename T>
std::string failing_key(const json& point, const std::string& section) {
  for (const auto& item : point.items()) {
    json alone = T{};
    alone[item.key()] = item.value();
    try {
      decode<T>(alone);
    } catch (const std::exception&) {
      return child(section, item.key());
    }
  }
  return section;
}

// The options of one grid point, checked to read back as given (an unknown enum name, a
// whole number given for a fractional one, ...).
template <typename T>
T options_from(const json& point, const std::string& section) {
  T options;
  try {
    options = decode<T>(point);
  } catch (const OptionError& e) {
    throw OptionError(child(section, e.key()), e.what());
  } catch (const std::exception& e) {
    throw OptionError(failing_key<T>(point, section), e.what());
  }
  const json full = options;
  json readback = full;
  for (const auto& item : full.items()) {
    if (!point.contains(item.key())) readback.erase(item.key());  // set by each run
  }
  if (const std::vector<std::string> at = json_differences(point, readback, section); !at.empty()) {
    const json::json_pointer ptr = pointer_in_section(at.front());
    throw OptionError(at.front(),
                      "is not a valid value" +
                          (point.contains(ptr) ? ": " + point.at(ptr).dump() : std::string()));
  }
  return options;
}

// The simulation options of a point with its terrain written as robot::terrain_text writes it
// ("slope:5" -> "slope:5:0"), so that options_from's read-back compares like with like.
json canonical_sim(json point) {
  const json::json_pointer at("/scene/terrain");
  if (!point.contains(at) || !point.at(at).is_string()) return point;
  try {
    point[at] = robot::terrain_text(robot::parse_terrain(point.at(at).get<std::string>()));
  } catch (const BadInput& e) {
    throw OptionError("sim.scene.terrain", e.what());
  }
  return point;
}

// A grid point's value of one axis as a short text ("0.1", "paper", "4-5-6").
std::string value_text(const json& v) {
  if (v.is_number_float()) return format_number(v.get<double>());
  if (v.is_string()) {
    // ':' (a terrain's "slope:5") as '_', so the value can name a run file
    std::string text = v.get<std::string>();
    std::replace(text.begin(), text.end(), ':', '_');
    return text;
  }
  if (v.is_array()) {
    std::vector<std::string> parts;
    for (const json& e : v) parts.push_back(value_text(e));
    return join(parts, "-");
  }
  return v.dump();
}

struct ScenarioSpec {
  std::string name;
  json resolved;  // the name of a leg set or fault, or {name, faults} of a timeline
  std::vector<std::size_t> disabled;      // a leg set that fails at the document's fail_step
  std::optional<sim::Fault> malfunction;  // another fault that comes at the fail_step
  sim::FaultTimeline faults;              // a timeline
  std::string path = "scenarios";         // where the document gives it ("scenarios[2]")
};

// A leg set given as "R1+R3" or ["R1", "R3"] (robot/leg_sets.h), at least one leg.
robot::LegSet parse_legs(const robot::Morphology& morph, const json& legs,
                         const std::string& path) {
  robot::LegSet out;
  try {
    if (legs.is_string()) {
      out = robot::parse_leg_set(morph, legs.get<std::string>());
    } else if (legs.is_array()) {
      out = robot::leg_set_from_json(morph, legs);
    }
  } catch (const BadInput& e) {
    throw OptionError(path, e.what());
  }
  if (out.empty()) {
    throw OptionError(path, "must name legs (\"R1+R3\" or [\"R1\", \"R3\"]), got " + legs.dump());
  }
  return out;
}

// One fault of a timeline table: {step, legs, recover} and, for kinds other than a whole leg,
// {kind, joint, value} (sim/faults.h; the yaw sensor's kinds name no legs).
sim::Fault timeline_fault(const robot::Morphology& morph, const json& f, const std::string& path) {
  if (!f.is_object()) throw OptionError(path, "must be a table {step, legs, recover, kind, ...}");
  const json defaults{{"step", 0},  {"legs", json::array()}, {"recover", false},
                      {"kind", ""}, {"joint", ""},           {"value", 0.0}};
  for (const auto& item : f.items()) {
    if (!defaults.contains(item.key())) {
      throw OptionError(child(path, item.key()),
                        "is not a fault key (known: step, legs, recover, kind, joint, value)");
    }
    // legs may be a leg set's text or a list; parse_legs names either kind of mistake
    if (item.key() != "legs") {
      check_type(item.value(), defaults.at(item.key()), child(path, item.key()));
    }
  }
  sim::Fault fault;
  fault.step = f.value("step", 0L);
  require_in(child(path, "step"), fault.step, Limits<long>{0, sim::kMaxSteps});
  fault.recover = f.value("recover", false);
  try {
    std::optional<double> value;
    if (f.contains("value")) value = f.at("value").get<double>();
    fault.kind =
        sim::make_kind(f.value("kind", std::string(sim::LegFault::kName)), value, fault.recover);
  } catch (const BadInput& e) {
    throw OptionError(child(path, f.contains("value") ? "value" : "kind"), e.what());
  }
  if (f.contains("joint")) {
    try {
      fault.joint = robot::parse_joint(f.at("joint").get<std::string>());
    } catch (const BadInput& e) {
      throw OptionError(child(path, "joint"), e.what());
    }
  }
  if (sim::strikes(fault.kind) != sim::Strikes::sensor || f.contains("legs")) {
    fault.legs = parse_legs(morph, f.value("legs", json()), child(path, "legs"));
  }
  return fault;
}

// A timeline fault as the resolved document records it: leg names, and kind, joint and value
// only for kinds other than a whole leg.
json timeline_fault_json(const robot::Morphology& morph, const sim::Fault& fault) {
  json j{{"step", fault.step},
         {"legs", robot::leg_set_json(morph, fault.legs)},
         {"recover", fault.recover}};
  if (std::holds_alternative<sim::LegFault>(fault.kind) && !fault.joint) return j;
  j["kind"] = sim::kind_name(fault.kind);
  if (fault.joint) j["joint"] = robot::to_string(*fault.joint);
  if (const std::optional<double> v = sim::value_of(fault.kind)) j["value"] = *v;
  return j;
}

ScenarioSpec timeline_scenario(const robot::Morphology& morph, const json& s,
                               const std::string& path) {
  const json defaults{{"name", ""}, {"faults", json::array()}};
  for (const auto& item : s.items()) {
    if (!defaults.contains(item.key())) {
      throw OptionError(child(path, item.key()), "is not a scenario key (known: name, faults)");
    }
  }
  if (!s.contains("name") || !s.at("name").is_string()) {
    throw OptionError(child(path, "name"), "must name the scenario (a string)");
  }
  ScenarioSpec out;
  out.name = s.at("name").get<std::string>();
  if (!key_names_a_file(out.name)) {
    throw OptionError(child(path, "name"),
                      "must be letters, digits and + - _ . =, got \"" + out.name + "\"");
  }
  const std::string faults_path = child(path, "faults");
  if (!s.contains("faults") || !s.at("faults").is_array() || s.at("faults").empty()) {
    throw OptionError(faults_path, "must list at least one fault ({step, legs, recover})");
  }
  json faults = json::array();
  for (std::size_t i = 0; i < s.at("faults").size(); ++i) {
    const sim::Fault fault = timeline_fault(morph, s.at("faults")[i], indexed(faults_path, i));
    out.faults.push_back(fault);
    faults.push_back(timeline_fault_json(morph, fault));
  }
  try {
    sim::validate(morph, out.faults);
  } catch (const BadInput& e) {
    throw OptionError(faults_path, e.what());
  }
  out.resolved = {{"name", out.name}, {"faults", faults}};
  return out;
}

// A scenario written as one fault without its step ("R1+R3", "R2.CTr:locked", "L1:weak=0.3";
// sim/fault_spec.h): it comes at the document's fail_step. A leg set is named as before; any
// other fault by its text with ':' as '_', so it names a run file.
ScenarioSpec fault_scenario(const robot::Morphology& morph, const json& text,
                            const std::string& path) {
  sim::Fault fault;
  try {
    fault = sim::parse_malfunction(morph, text.get<std::string>(), false);
  } catch (const BadInput& e) {
    throw OptionError(path, e.what());
  }
  if (std::holds_alternative<sim::LegFault>(fault.kind) && !fault.joint) {
    const std::vector<std::size_t> legs = parse_legs(morph, text, path);
    const std::string name = robot::leg_set_name(morph, legs);
    return {name, name, legs, std::nullopt, {}};
  }
  try {
    sim::validate(morph, {fault});
  } catch (const BadInput& e) {
    throw OptionError(path, e.what());
  }
  const std::string spec = sim::malfunction_text(morph, fault);
  std::string name = spec;
  std::replace(name.begin(), name.end(), ':', '_');
  return {name, spec, {}, fault, {}};
}

std::vector<ScenarioSpec> resolve_scenarios(robot::RobotKind kind, const json& doc) {
  const robot::Morphology& morph = robot::morphology(kind);
  if (!doc.contains("scenarios")) {
    throw OptionError("scenarios",
                      "is missing: \"paper\", \"all\", \"every\" or a list of leg sets");
  }
  const json& s = doc.at("scenarios");
  std::vector<ScenarioSpec> out;
  if (s.is_string()) {
    std::vector<Scenario> named;
    try {
      if (s == "paper") {
        named = paper_scenarios(kind);
      } else if (s == "all") {
        named = mirror_scenarios(morph, kMaxScenarioLegs);
      } else if (s == "every") {
        named = every_leg_loss(morph, kMaxScenarioLegs);
      } else {
        throw OptionError("scenarios",
                          "must be \"paper\", \"all\", \"every\" or a list, got " + s.dump());
      }
    } catch (const OptionError&) {
      throw;
    } catch (const BadInput& e) {
      throw OptionError("scenarios", e.what());
    }
    for (const Scenario& n : named) out.push_back({n.name, n.name, n.disabled, std::nullopt, {}});
  } else if (s.is_array()) {
    if (s.empty()) throw OptionError("scenarios", "is an empty list");
    for (std::size_t i = 0; i < s.size(); ++i) {
      const std::string path = indexed("scenarios", i);
      if (s[i].is_object()) {
        out.push_back(timeline_scenario(morph, s[i], path));
        out.back().path = path;
      } else if (s[i].is_string()) {
        out.push_back(fault_scenario(morph, s[i], path));
        out.back().path = path;
      } else {
        throw OptionError(path,
                          "must be a leg set (\"R1+R3\"), a fault (\"R2.CTr:locked\") or a "
                          "fault timeline table, got " +
                              s[i].dump());
      }
      for (std::size_t j = 0; j + 1 < out.size(); ++j) {
        if (out[j].name == out.back().name) {
          throw OptionError(path, "repeats the scenario " + out.back().name);
        }
      }
    }
  } else {
    throw OptionError("scenarios",
                      "must be \"paper\", \"all\", \"every\" or a list, got " + s.dump());
  }
  return out;
}

// A whole number at `key` of `doc` in [lo, hi], or `fallback` when absent.
template <class T>
T whole(const json& doc, const std::string& key, T fallback, const Limits<T>& limits,
        const std::string& path) {
  if (!doc.contains(key)) return fallback;
  const json& v = doc.at(key);
  if (!v.is_number_integer()) {
    throw OptionError(path, "must be a whole number, got " + v.dump());
  }
  const std::int64_t n = v.get<std::int64_t>();
  if (n < static_cast<std::int64_t>(limits.lo) || n > static_cast<std::int64_t>(limits.hi)) {
    throw OptionError(path, "must be in " + limits.text() + ", got " + std::to_string(n));
  }
  return static_cast<T>(n);
}

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

// Refuses a document nested deeper than kMaxExperimentDepth or with a list longer than
// kMaxListValues, naming the key, before anything else looks at it (a document from Python is
// not bounded by a file's size). Iterative: the depth is what is being checked.
void check_bounds(const json& doc) {
  struct Item {
    const json* value;
    std::string path;
    int depth;
  };
  std::vector<Item> todo{{&doc, "", 0}};
  while (!todo.empty()) {
    const Item item = std::move(todo.back());
    todo.pop_back();
    if (item.depth > kMaxExperimentDepth) {
      throw OptionError(
          item.path, "is nested more than " + std::to_string(kMaxExperimentDepth) + " levels deep");
    }
    if (item.value->is_array()) {
      if (item.value->size() > kMaxListValues) {
        throw OptionError(item.path, "has " + std::to_string(item.value->size()) +
                                         " values, more than the " +
                                         std::to_string(kMaxListValues) + " a list may have");
      }
      for (std::size_t i = 0; i < item.value->size(); ++i) {
        todo.push_back({&(*item.value)[i], indexed(item.path, i), item.depth + 1});
      }
    } else if (item.value->is_object()) {
      for (const auto& entry : item.value->items()) {
        todo.push_back({&entry.value(), child(item.path, entry.key()), item.depth + 1});
      }
    }
  }
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

void check_sim(const sim::SimOptions& options, robot::RobotKind kind) {
  within("sim", [&] { sim::validate(options, kind); });
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

// OUT/experiment.json's arguments, if OUT holds an experiment. A landscape's directory is
// refused: its runs are combinations, not runs of a sweep, and it resumes by running again.
std::optional<json> stored_arguments(const fs::path& out) {
  const fs::path path = out / "experiment.json";
  const std::optional<json> sealed = read_sealed(path);
  if (!sealed) return std::nullopt;
  const json& record = *sealed;
  if (!record.contains("arguments")) {
    throw BadInput("'" + path.string() + "' records no experiment arguments");
  }
  if (record.at("arguments").value("experiment", json()) == "landscape") {
    throw BadInput("'" + out.string() +
                   "' holds a landscape, which is not rerun or merged: run the same landscape "
                   "again into it to resume it");
  }
  std::optional<json> arguments;
  arguments.emplace(record.at("arguments"));
  return arguments;
}

json arguments_of(const Sweep& sweep, const Shard& shard) {
  json args = sweep.resolved;
  if (shard.count > 1) args["shard"] = to_string(shard);
  return args;
}

// Each distinct simulation of the runs, made once and shared read-only by the threads.
class Models {
 public:
  explicit Models(const std::vector<const RunSpec*>& specs) {
    for (const RunSpec* spec : specs) {
      const std::string key = key_of(*spec);
      if (!models_.count(key)) models_.emplace(key, make_run_model(*spec));
    }
  }
  const sim::SimModel& of(const RunSpec& spec) const { return models_.at(key_of(spec)); }

 private:
  // The robot and every simulation option, as recorded: equal records, equal models.
  static std::string key_of(const RunSpec& spec) {
    return std::string(robot::to_string(spec.robot)) + json(spec.sim).dump();
  }
  std::map<std::string, sim::SimModel> models_;
};

json task_result(const sim::SimModel& model, const RunSpec& spec, sim::Observer* observer) {
  const robot::Morphology& morph = model.controller.morphology;
  const learning::CompensationOptions& options = *spec.learning;
  const long check_windows = spec.record.check_windows;
  const LearningRun run = run_learning(model, spec, check_windows * options.window_steps, observer);
  json out = learning::to_json(run.result, morph, sim::failing_legs(spec.faults));
  if (check_windows > 0) {
    json windows = json::array();
    bool holds = true;
    for (const sim::WindowMeasure& m : run.after_windows) {
      windows.push_back({{"yaw_deg", m.yaw_deg}, {"path_deg", m.path_deg}});
      holds = holds && sim::holds(m.worst_deg(), options.annealing.threshold_deg);
    }
    out["after_windows"] = windows;
    out["holds_after"] = holds;
  }
  if (!spec.record.trace) out.erase("trace");
  return out;
}

std::string cell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) return shortest(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array()) return value_text(v);
  return v.dump();
}

// The columns every CSV row of a run starts with: key, scenario, run, seed, grid values.
std::vector<std::string> run_columns(const Sweep& sweep) {
  std::vector<std::string> cols{"key", "scenario", "run", "seed"};
  for (const GridAxis& a : sweep.grid) cols.push_back(a.key);
  return cols;
}

std::vector<std::string> run_cells(const Sweep& sweep, const Task& t) {
  std::vector<std::string> cells{t.key, t.params.at("scenario").get<std::string>(),
                                 std::to_string(t.run), std::to_string(t.seed)};
  for (const GridAxis& a : sweep.grid) cells.push_back(cell(t.params.at("grid").at(a.key)));
  return cells;
}

ExperimentTable write_results(const Sweep& sweep, const fs::path& out,
                              const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  ExperimentTable table{sweep.table, std::string(robot::to_string(sweep.robot)),
                        summarize(morph, sweep.tasks, results)};
  Table data;
  Table shown;
  if (sweep.table == ExperimentKind::beta) {
    data = beta_data(table.rows);
    shown = beta_table(table.rows);
  } else if (sweep.table == ExperimentKind::grid) {
    data = scenario_data(table.rows, "group");
    shown = scenario_table(table.rows, "Grid point");
  } else {
    data = scenario_data(table.rows);
    shown = scenario_table(table.rows);
  }
  write_file_atomic(out / "table.csv", to_csv(data));
  write_file_atomic(out / "table.md", to_markdown(shown));
  write_file_atomic(out / "runs.csv", to_csv(runs_table(sweep, results)));
  write_file_atomic(out / "trials.csv", to_csv(trials_table(sweep, results)));
  json rows = json::array();
  for (const GroupSummary& row : table.rows) rows.push_back(to_json(row));
  json summary{{"experiment", to_string(table.experiment)},
               {"robot", table.robot},
               {"arguments", sweep.resolved},
               {"rows", rows}};
  if (sweep.robot_file) summary["robot_file"] = sweep.robot_file->record;
  write_file_atomic(out / "summary.json", summary.dump(kJsonIndent) + "\n");
  return table;
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
    RobotFileRecord recorded;
    try {
      recorded = doc.at("robot_file").get<RobotFileRecord>();
    } catch (const json::exception&) {
      throw OptionError("robot_file",
                        "must be a table of path, name, checksum_toml and checksum_model");
    }
    robot.file = load_document_robot("robot_file.path", recorded.path);
    const RobotFileRecord& now = robot.file->record;
    for (const auto& [key, was, is] :
         {std::tuple{"name", recorded.name, now.name},
          {"checksum_toml", recorded.checksum_toml, now.checksum_toml},
          {"checksum_model", recorded.checksum_model, now.checksum_model}}) {
      if (was != is) {
        throw OptionError(
            child("robot_file", key),
            "'" + now.path + "' has changed since it was recorded (" + was + ", now " + is + ")");
      }
    }
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
  if (robot.file) resolved["robot_file"] = robot.file->record;
}

json landscape_json(const LandscapeSpec& spec) {
  return {{"period_set", spec.period_set},
          {"windows", spec.windows},
          {"window_steps", spec.window_steps},
          {"threshold_deg", spec.threshold_deg}};
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
  spec.kind = kind;
  spec.robot_file = robot.file;
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
  const json sim_default = sim_defaults(doc);
  json sim_doc = sim_default;
  merge_checked(doc.value("sim", json::object()), sim_default, "sim", sim_doc, grid);
  refuse_grid(grid);
  spec.sim = options_from<sim::SimOptions>(canonical_sim(sim_doc), "sim");
  try {
    validate(spec);
  } catch (const OptionError& e) {
    throw OptionError(child("landscape", e.key()), e.what());
  } catch (const BadInput& e) {
    throw OptionError("landscape", e.what());
  }
  check_sim(spec.sim, kind);
  if (robot.file) {
    RunSpec walk;
    walk.robot = kind;
    walk.robot_file = robot.file;
    walk.sim = spec.sim;
    validate(walk);  // its body and ground, as for any run of the robot file
  }
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
           {"robot", robot::to_string(spec.kind)},
           {"scenarios", {robot::leg_set_name(robot::morphology(spec.kind), spec.disabled)}},
           {"landscape", landscape_json(spec)},
           {"sim", spec.sim}};
  if (spec.robot_file) doc["robot_file"] = spec.robot_file->record;
  return doc;
}

nlohmann::json learning_document(const learning::CompensationOptions& options, long fail_step) {
  json j = options;
  for (const std::string& key : kPerRunLearningKeys) j.erase(key);
  j[kFailStepKey] = fail_step;
  return j;
}

Sweep resolve_sweep(const json& doc, const SweepLimits& limits) {
  if (!doc.is_object()) throw OptionError("", "an experiment must be a table of keys");
  check_bounds(doc);
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
  const robot::Morphology& morph = robot::morphology(sweep.robot);
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
  merge_checked(doc.value("learning", json::object()), json(learning), "learning", learning,
                sweep.grid, kPerRunLearningKeys);
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
  std::set<std::string> sims_checked;
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
    require_in(std::string("learning.") + kFailStepKey, fail_step, sim::kStepLimits);
    learning_point.erase(kFailStepKey);
    check_interrupted();  // a large sweep takes seconds to resolve
    const auto base = options_from<learning::CompensationOptions>(learning_point, "learning");
    const auto sim_options = options_from<sim::SimOptions>(canonical_sim(sim_point), "sim");
    if (sims_checked.insert(json(sim_options).dump()).second) check_sim(sim_options, sweep.robot);
    for (const ScenarioSpec& s : scenarios) {
      RunSpec spec;
      spec.robot = sweep.robot;
      spec.robot_file = sweep.robot_file;
      spec.sim = sim_options;
      spec.learning = base;
      spec.start = learning_start(base.mode);
      spec.faults = s.faults;
      if (s.malfunction) {
        spec.faults = {*s.malfunction};
        spec.faults.front().step = fail_step;
      } else if (s.faults.empty()) {
        spec.faults = sim::fail_at(s.disabled, fail_step);
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
        Task task;
        task.key = run_key(group_key, run);
        task.group = join(gp, " ");
        task.run = run;
        task.seed = derive_seed(seed, task.key);
        spec.learning->seed = task.seed;
        // The run file's record of its options (the form earlier versions wrote).
        json options = *spec.learning;
        options["disabled"] = s.disabled;
        options[kFailStepKey] = fail_step;
        options["faults"] = s.malfunction ? spec.faults : s.faults;
        task.params = {{"robot", robot::to_string(sweep.robot)},
                       {"scenario", s.name},
                       {"disabled", robot::leg_set_json(morph, sim::failing_legs(spec.faults))},
                       {"grid", grid_values},
                       {"learning", options},
                       {"sim", sim_options},
                       {"record", record}};
        if (sweep.robot_file) task.params["robot_file"] = sweep.robot_file->record;
        sweep.tasks.push_back(std::move(task));
        sweep.specs.push_back(spec);
      }
    }
  }
  return sweep;
}

const RunSpec& spec_of(const Sweep& sweep, const Task& task) {
  for (std::size_t i = 0; i < sweep.tasks.size(); ++i) {
    if (sweep.tasks[i].key == task.key) return sweep.specs.at(i);
  }
  throw std::invalid_argument("spec_of: no run " + task.key + " in the sweep");
}

SweepOutcome run_sweep(const Sweep& sweep, const SweepRunOptions& options) {
  const json arguments = arguments_of(sweep, options.shard);
  if (is_primary_process()) ensure_writable_dir(options.out);
  std::vector<Task> tasks;
  std::map<std::string, const RunSpec*> specs;
  std::vector<const RunSpec*> shard_specs;
  for (std::size_t i = 0; i < sweep.tasks.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(options.shard.count)) ==
        options.shard.index) {
      tasks.push_back(sweep.tasks[i]);
      shard_specs.push_back(&sweep.specs[i]);
      specs.emplace(sweep.tasks[i].key, &sweep.specs[i]);
    }
  }
  RunnerOptions runner;
  runner.out_dir = options.out;
  runner.jobs = options.jobs;
  runner.arguments = arguments;
  runner.progress = options.progress;
  runner.progress_label = options.progress_label;
  runner.provenance = provenance(mj_versionString());
  validate(runner);
  const Models models(shard_specs);
  const RunnerOutcome outcome = run_tasks(
      tasks,
      [&](const Task& task) {
        const RunSpec& spec = *specs.at(task.key);
        return task_result(models.of(spec), spec, nullptr);
      },
      runner);
  SweepOutcome result;
  result.tasks = tasks.size();
  result.loaded = outcome.loaded;
  result.ran = outcome.ran;
  if (options.shard.count > 1) return result;
  // Every process of an MPI job gets here; the primary writes OUT (processes.h).
  result.table = is_primary_process()
                     ? write_results(sweep, options.out, outcome.results)
                     : ExperimentTable{sweep.table, std::string(robot::to_string(sweep.robot)), {}};
  return result;
}

json run_sweep_task(const RunSpec& spec, sim::Observer* observer) {
  return task_result(make_run_model(spec), spec, observer);
}

RecordedSweep read_sweep(const fs::path& dir) {
  std::optional<json> arguments = stored_arguments(dir);
  if (!arguments) {
    throw BadInput("no experiment in '" + dir.string() + "' (missing experiment.json)");
  }
  RecordedSweep out;
  if (arguments->contains("shard")) {
    out.shard = parse_shard(arguments->at("shard").get<std::string>());
    arguments->erase("shard");
  }
  // It ran, so it was within some --max-runs: the most that flag allows.
  const SweepLimits recorded{kMaxRunsLimits.hi, "--max-runs"};
  try {
    out.sweep = resolve_sweep(*arguments, recorded);
  } catch (const OptionError& e) {
    throw BadInput("'" + (dir / "experiment.json").string() + "': " + e.key() + " " + e.what());
  }
  return out;
}

ExperimentTable merge_sweeps(const fs::path& out, const std::vector<fs::path>& dirs,
                             bool progress) {
  if (dirs.empty()) throw BadInput("name at least one shard directory to merge");
  std::optional<json> base;
  std::map<std::string, fs::path> where;  // run key -> the shard directory holding it
  std::set<int> shards;
  int count = 0;
  for (const fs::path& dir : dirs) {
    std::optional<json> args = stored_arguments(dir);
    if (!args) throw BadInput("no experiment in '" + dir.string() + "' (missing experiment.json)");
    const Shard shard =
        args->contains("shard") ? parse_shard(args->at("shard").get<std::string>()) : Shard{};
    args->erase("shard");
    if (!base) {
      base = *args;
      count = shard.count;
    } else if (const std::vector<std::string> keys = json_differences(*base, *args);
               !keys.empty()) {
      throw BadInput("'" + dir.string() + "' is not a shard of the experiment in '" +
                     dirs.front().string() + "' (" + keys.front() + " differs)");
    }
    if (shard.count != count || !shards.insert(shard.index).second) {
      throw BadInput("'" + dir.string() + "' holds shard " + to_string(shard) +
                     ", which repeats or does not fit shards of " + std::to_string(count));
    }
    for (const auto& run : fs::directory_iterator(dir / "runs")) {
      if (run.path().extension() == ".json") where.emplace(run.path().stem().string(), dir);
    }
  }
  const Sweep sweep = read_sweep(dirs.front()).sweep;
  for (const Task& t : sweep.tasks) {
    if (!where.count(t.key)) {
      throw BadInput("run " + t.key + " is in none of the directories (a shard missing or " +
                     "not finished)");
    }
  }
  RunnerOptions runner;
  runner.out_dir = out;
  runner.arguments = sweep.resolved;
  runner.progress = progress;
  runner.provenance = provenance(mj_versionString());
  ensure_writable_dir(out);
  // The run files are taken as saved, after their checksum and their task are checked.
  const RunnerOutcome outcome = run_tasks(
      sweep.tasks,
      [&](const Task& t) {
        const fs::path path = where.at(t.key) / "runs" / (t.key + ".json");
        const std::optional<json> sealed = read_sealed(path);
        if (!sealed) throw BadInput("cannot read '" + path.string() + "'");
        const json& saved = *sealed;
        const json expected{{"key", t.key},
                            {"group", t.group},
                            {"run", t.run},
                            {"seed", t.seed},
                            {"params", t.params}};
        for (const auto& item : expected.items()) {
          if (saved.value(item.key(), json()) != item.value()) {
            throw BadInput("'" + path.string() + "' is not the run " + t.key + " (" + item.key() +
                           " differs)");
          }
        }
        return saved.at("result");
      },
      runner);
  return write_results(sweep, out, outcome.results);
}

Table runs_table(const Sweep& sweep, const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  Table t;
  for (const std::string& c : run_columns(sweep)) t.columns.push_back({c});
  const std::vector<std::string> outcome{"converged",
                                         "status",
                                         "reason",
                                         "trials",
                                         "initial_deviation_deg",
                                         "final_deviation_deg",
                                         "steps_walked",
                                         "detection_step",
                                         "settle_steps",
                                         "steering_effort"};
  for (const std::string& c : outcome) t.columns.push_back({c});
  for (const robot::Leg& leg : morph.legs) t.columns.push_back({"period_" + leg.name});
  const bool holds = sweep.resolved.at("record").at("check_windows").get<long>() > 0;
  if (holds) t.columns.push_back({"holds_after"});
  for (std::size_t i = 0; i < results.size(); ++i) {
    const json& r = results[i];
    std::vector<std::string> cells = run_cells(sweep, sweep.tasks[i]);
    for (const std::string& c : outcome) cells.push_back(cell(r.value(c, json())));
    for (const robot::Leg& leg : morph.legs) cells.push_back(cell(r.at("periods").at(leg.name)));
    if (holds) cells.push_back(cell(r.value("holds_after", json())));
    t.add_row(std::move(cells));
  }
  return t;
}

Table trials_table(const Sweep& sweep, const std::vector<json>& results) {
  const robot::Morphology& morph = robot::morphology(sweep.robot);
  Table t;
  for (const std::string& c : run_columns(sweep)) t.columns.push_back({c});
  t.columns.push_back({"trial"});
  for (const robot::Leg& leg : morph.legs) t.columns.push_back({"period_" + leg.name});
  // The neutral fields of a trial, then every learner's own details (learning/learner.h).
  std::set<std::string> details;
  for (const json& r : results) {
    for (const json& trial : r.value("trace", json::array())) {
      for (const auto& item : trial.items()) details.insert(item.key());
    }
  }
  std::vector<std::string> fields{"deviation_deg", "accepted"};
  for (const char* neutral : {"trial", "periods", "deviation_deg", "accepted"}) {
    details.erase(neutral);
  }
  fields.insert(fields.end(), details.begin(), details.end());
  for (const std::string& c : fields) t.columns.push_back({c});
  for (std::size_t i = 0; i < results.size(); ++i) {
    for (const json& trial : results[i].value("trace", json::array())) {
      std::vector<std::string> cells = run_cells(sweep, sweep.tasks[i]);
      cells.push_back(cell(trial.at("trial")));
      for (const robot::Leg& leg : morph.legs) {
        cells.push_back(cell(trial.at("periods").at(leg.name)));
      }
      for (const std::string& c : fields) cells.push_back(cell(trial.value(c, json())));
      t.add_row(std::move(cells));
    }
  }
  return t;
}

}  // namespace multicpg::experiments
