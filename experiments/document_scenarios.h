// The scenarios of an experiment document (sweep.h): "paper", "all", "every", or a list of leg
// sets ("R1+R3"), single faults without their step ("R2.CTr:locked", docs/faults.md) and fault
// timelines ({name, faults = [{step, legs, recover, kind, joint, value}]}), each checked and
// named, with the form the resolved document records it in.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "body/events.h"
#include "robot/morphology.h"

namespace multicpg::experiments {

struct ScenarioSpec {
  std::string name;
  nlohmann::json resolved;  // the name of a leg set or fault, or {name, faults} of a timeline
  std::vector<std::size_t> disabled;       // a leg set that fails at the document's fail_step
  std::optional<body::Fault> malfunction;  // another fault that comes at the fail_step
  body::FaultTimeline faults;              // a timeline
  std::string path = "scenarios";          // where the document gives it ("scenarios[2]")
};

// The document's scenarios, in its order. Throws OptionError at the scenario's path
// ("scenarios[2].faults[0].legs") for a missing or bad scenario, a repeated name or a fault
// timeline that cannot happen.
std::vector<ScenarioSpec> resolve_scenarios(robot::RobotKind kind, const nlohmann::json& doc);

}  // namespace multicpg::experiments
