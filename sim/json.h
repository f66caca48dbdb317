// The simulation's options as JSON (nlohmann's type macros): keys are the member names, a missing
// key keeps its default. Recorded with every result and read from experiment files.
#pragma once

#include <nlohmann/json.hpp>

#include "body/course_json.h"
#include "neural/json.h"
#include "robot/body_json.h"
#include "sim/sim.h"

namespace multicpg::robot {

// A terrain is recorded as its spec text ("slope:5:0", robot/terrain.h), so experiment files
// write it as they would on the command line; an unreadable one throws BadInput.
inline void to_json(nlohmann::json& j, const Terrain& terrain) {
  j = terrain_text(terrain);
}
inline void from_json(const nlohmann::json& j, Terrain& terrain) {
  terrain = parse_terrain(j.get<std::string>());
}

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Scene, tunnel, tunnel_length, tunnel_width, terrain)

}  // namespace multicpg::robot

namespace multicpg::sim {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SimOptions, control_dt, physics_dt, servo_gain,
                                                scene, controller, model, body)

}  // namespace multicpg::sim
