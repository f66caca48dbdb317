// Fault timelines and window measures as JSON (nlohmann's type macros; keys are the member
// names). No MuJoCo here, so the learner's records can use them (sim/CMakeLists.txt).
#pragma once

#include <nlohmann/json.hpp>

#include "sim/deviation.h"
#include "sim/events.h"

namespace multicpg::sim {

// A fault as {step, legs (indices), recover}, the form leg faults have always been recorded in,
// with "kind" (its name), "joint" and "value" for every other kind.
void to_json(nlohmann::json& j, const Fault& fault);
// Throws BadInput for an unknown kind or joint, or a value its kind does not take.
void from_json(const nlohmann::json& j, Fault& fault);

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Pose2, x, y, yaw_deg)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(WindowMeasure, yaw_deg, path_deg, forward_m,
                                                lateral_m, steering_effort)

}  // namespace multicpg::sim
