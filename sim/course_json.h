// Fault timelines and window measures as JSON (nlohmann's type macros; keys are the member
// names). No MuJoCo here, so the learner's records can use them (sim/CMakeLists.txt).
#pragma once

#include <nlohmann/json.hpp>

#include "sim/deviation.h"
#include "sim/events.h"

namespace multicpg::sim {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Fault, step, legs, recover)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Pose2, x, y, yaw_deg)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(WindowMeasure, yaw_deg, path_deg, forward_m,
                                                lateral_m, steering_effort)

}  // namespace multicpg::sim
