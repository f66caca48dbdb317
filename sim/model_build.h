// The steps every SimModel is built by, a built-in robot's (sim/sim.h) and a robot file's
// (sim/robot_file.h): the model begun from its options and layout, then its compiled MuJoCo model
// searched for the names of its leg map (docs/robots.md "Your robot: robot files").
#pragma once

#include <mujoco/mujoco.h>

#include "robot/morphology.h"
#include "robot/robot_file.h"
#include "sim/sim_model.h"

namespace multicpg::sim {

// The model of `kind` or of a robot file with the layout `kind`, before its MJCF is compiled: the
// options checked (validate), MuJoCo's handlers installed, the body, the controller, the time
// steps and the start pose of `map`'s joint windows: every leg in mid-stance. Throws BadInput
// for bad options.
SimModel new_model(robot::RobotKind kind, const SimOptions& options, const robot::RobotFile& map);

// Finds every name of the leg map `map` in model.mj's tables: the servo joints and their
// actuators, the feet, the trunk's free joint, the yaw frame and the start keyframe; without a
// keyframe, the start pose with the lowest foot on the ground. Throws OptionError with the robot
// file's key ("legs[0].TC.joint", "yaw", "legs", ...) for a name the model lacks or a part it
// cannot use.
void index_model(SimModel& model, const robot::RobotFile& map, const SimOptions& options);

// Whether geom `g` of `m` is a ground plane: a plane of the world body (a robot file's ground).
bool is_ground_plane(const mjModel* m, int g);

}  // namespace multicpg::sim
