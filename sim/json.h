// The simulation's options as JSON (nlohmann's type macros): keys are the member names, a missing
// key keeps its default. Recorded with every result and read from experiment files.
#pragma once

#include <nlohmann/json.hpp>

#include "neural/json.h"
#include "robot/body_json.h"
#include "sim/course_json.h"
#include "sim/sim.h"

namespace multicpg::robot {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Scene, tunnel, tunnel_length, tunnel_width)

}  // namespace multicpg::robot

namespace multicpg::sim {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SimOptions, control_dt, physics_dt, servo_gain,
                                                scene, controller, model, body)

}  // namespace multicpg::sim
