#include "experiments/document_scenarios.h"

#include <algorithm>

#include "body/course_json.h"
#include "body/fault_spec.h"
#include "common/errors.h"
#include "common/limits.h"
#include "experiments/document_schema.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {
namespace {

using document::check_type;
using document::child;
using document::indexed;
using nlohmann::json;

constexpr std::size_t kMaxScenarioLegs = 3;  // 1-3 disabled legs ("all"; paper Fig. 11)

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
// {kind, joint, value} (body/faults.h; the yaw sensor's kinds name no legs).
body::Fault timeline_fault(const robot::Morphology& morph, const json& f, const std::string& path) {
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
  body::Fault fault;
  fault.step = f.value("step", 0L);
  require_in(child(path, "step"), fault.step, Limits<long>{0, body::kMaxSteps});
  fault.recover = f.value("recover", false);
  try {
    std::optional<double> value;
    if (f.contains("value")) value = f.at("value").get<double>();
    fault.kind =
        body::make_kind(f.value("kind", std::string(body::LegFault::kName)), value, fault.recover);
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
  if (body::strikes(fault.kind) != body::Strikes::sensor || f.contains("legs")) {
    fault.legs = parse_legs(morph, f.value("legs", json()), child(path, "legs"));
  }
  return fault;
}

// A timeline fault as the resolved document records it: a fault's one shape (body/course_json.h)
// with its legs named, as the document names them.
json timeline_fault_json(const robot::Morphology& morph, const body::Fault& fault) {
  json j = fault;
  j["legs"] = robot::leg_set_json(morph, fault.legs);
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
  if (out.name.size() > max_key_length()) {
    throw OptionError(child(path, "name"), "names run files, but its " +
                                               std::to_string(out.name.size()) +
                                               " characters are more than a file name holds (" +
                                               std::to_string(max_key_length()) + ")");
  }
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
    const body::Fault fault = timeline_fault(morph, s.at("faults")[i], indexed(faults_path, i));
    out.faults.push_back(fault);
    faults.push_back(timeline_fault_json(morph, fault));
  }
  try {
    body::validate(morph, out.faults);
  } catch (const BadInput& e) {
    throw OptionError(faults_path, e.what());
  }
  out.resolved = {{"name", out.name}, {"faults", faults}};
  return out;
}

// A scenario written as one fault without its step ("R1+R3", "R2.CTr:locked", "L1:weak=0.3";
// body/fault_spec.h): it comes at the document's fail_step. A leg set is named as before; any
// other fault by its text with ':' as '_', so it names a run file.
ScenarioSpec fault_scenario(const robot::Morphology& morph, const json& text,
                            const std::string& path) {
  body::Fault fault;
  try {
    fault = body::parse_malfunction(morph, text.get<std::string>(), false);
  } catch (const BadInput& e) {
    throw OptionError(path, e.what());
  }
  if (std::holds_alternative<body::LegFault>(fault.kind) && !fault.joint) {
    const std::vector<std::size_t> legs = parse_legs(morph, text, path);
    const std::string name = robot::leg_set_name(morph, legs);
    return {name, name, legs, std::nullopt, {}};
  }
  try {
    body::validate(morph, {fault});
  } catch (const BadInput& e) {
    throw OptionError(path, e.what());
  }
  const std::string spec = body::malfunction_text(morph, fault);
  std::string name = spec;
  std::replace(name.begin(), name.end(), ':', '_');
  return {name, spec, {}, fault, {}};
}

}  // namespace

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

}  // namespace multicpg::experiments
