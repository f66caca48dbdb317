// The simulated robot: a MuJoCo model driven by the neural controller (docs/robots.md). A built-in
// robot's SimModel (a robot file's: sim/robot_file.h), a run's SimState (sim/sim_model.h), one
// controller step with its physics, and the readings of the sensors.
#pragma once

#include <mujoco/mujoco.h>

#include <cstddef>
#include <string>

#include "common/angles.h"
#include "robot/morphology.h"
#include "sim/sim_model.h"

namespace multicpg::sim {

// A foot touches the ground when its touch sensor reads more than this normal force.
inline constexpr double kContactThresholdN = 0.5;

// Builds the MJCF from robot::robot_body(kind, options.body), compiles it and indexes it. Throws
// BadInput for bad options (validate), RuntimeFailure if MuJoCo rejects the model.
SimModel make_sim_model(robot::RobotKind kind, const SimOptions& options = {});

// The MJCF make_sim_model compiles (what `multicpg model` prints).
std::string model_xml(robot::RobotKind kind, const SimOptions& options = {});

// Resets `d` to the model's start pose: its keyframe "start", or the computed start_qpos.
void reset_to_start(const SimModel& model, mjData* d);

// The model the run's physics steps now: its own while a fault reshapes the robot
// (sim/fault_effects.h), else the shared one.
const mjModel* physics_model(const SimModel& model, const SimState& state);

// The robot standing in its start pose at the origin, facing +x, every CPG at `period` and
// synchronised (neural::make_controller_state).
SimState make_sim_state(const SimModel& model, int period = 4);

// A deep copy of `state` (mjData through mj_copyData, the controller, targets, counters) that
// continues exactly as `state` would. `state` must belong to `model`.
SimState copy_sim_state(const SimModel& model, const SimState& state);

// One controller step: neural::controller_step, joint targets (robot::joint_angle), then
// model.substeps physics steps, each setting every servo's torque (sim/servo.h, as the faults in
// force allow: none for a locked or passive joint, a weak motor's share) before mj_step.
// Throws RuntimeFailure naming the step if the physics becomes unstable (a NaN or infinite state,
// a MuJoCo warning such as a bad acceleration, MuJoCo resetting the state, the trunk faster than
// any real robot or bodies deep inside each other).
void sim_step(const SimModel& model, SimState& state);
// The physics half of sim_step: model.substeps physics steps toward state.targets, without the
// controller (the hardware emulator, emulator/emulator.h, moves the robot to targets it received).
void physics_step(const SimModel& model, SimState& state);

// Readings. Positions and joint angles are of the current state (a segment's angle: its servo's
// plus the coupling's give); the yaw and touch sensors are as MuJoCo last evaluated them, at the
// start of the last physics step (one physics step old).
struct Position {
  double x, y, z;  // m
};
Position trunk_position(const SimModel& model, const SimState& state);
double trunk_yaw_deg(const SimModel& model, const SimState& state);  // (-180, 180]
double joint_angle(const SimModel& model, const SimState& state, std::size_t leg,
                   robot::Joint joint);
double foot_force(const SimModel& model, const SimState& state, std::size_t leg);  // N
bool foot_contact(const SimModel& model, const SimState& state, std::size_t leg);

}  // namespace multicpg::sim
