// What a simulation is and what one run of it is doing, as types (docs/robots.md).
//
// SimModel is what the simulation is (the mjModel, index tables, time steps, the controller's
// model): immutable after make_sim_model (sim/sim.h, sim/robot_file.h) and shareable read-only by
// any number of threads. SimState is what one run is doing (mjData, controller state, step
// counter, faults); each thread owns its own. Same model, same inputs -> bit-identical
// trajectories.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "neural/controller.h"
#include "robot/body.h"
#include "robot/mjcf.h"
#include "sim/fault_state.h"
#include "sim/mujoco_load.h"
#include "sim/servo.h"
#include "sim/sim_options.h"

namespace multicpg::sim {

// How a servo joint is driven (docs/robots.md "Your robot: robot files"): the servo law's torque
// through a motor (the built-in robots; a robot file's motors, and the motors added to its joints
// that have no actuator), or the model's own position or velocity actuator, which is given the
// servo's target angle or commanded velocity and acts with its own gains.
enum class Drive { servo, position, velocity };

// Where one servo's joint lives in the mjModel.
struct JointSlot {
  int joint = -1;
  int qpos = -1;
  int dof = -1;
  int actuator = -1;
  int coupling_qpos = -1;  // the passive coupling behind the servo, if the joints are compliant
  double sign = 1.0;       // the paper's angle is sign * the joint's (robot::JointMap)
  ServoModel servo{};
  Drive drive = Drive::servo;
  double gear = 1.0;  // the actuator's transmission: its length is gear * the joint's angle
};

struct LegSlots {
  robot::LegType type;
  std::array<JointSlot, robot::kJointsPerLeg> joints;  // TC, CTr, FTi
  // The angles commands -1..1 span (robot::JointMap::window).
  std::array<robot::AngleRange, robot::kJointsPerLeg> windows{};
  // sensordata address of the foot's touch sensor; -1: the normal forces of the foot geom's
  // contacts (a robot file whose model has no touch sensor there)
  int touch = -1;
  // The parts a fault reshapes (sim/fault_effects.h): the tibia's body and capsule, the foot's
  // body and capsule, and the foot's contact pair with the ground.
  int tibia_body = -1;
  int tibia_geom = -1;
  int foot_body = -1;
  int foot_geom = -1;
  int foot_pair = -1;
};

struct SimModel {
  robot::RobotKind kind;
  robot::RobotBody body;  // the paper's body with SimOptions::body applied
  neural::ControllerModel controller;
  std::vector<robot::LegAngles> start_pose;  // joint angles of the "start" keyframe
  robot::Scene scene;
  std::string xml;  // the MJCF the mjModel was compiled from
  std::unique_ptr<mjModel, MjModelDeleter> mj;
  double control_dt;
  double physics_dt;
  int substeps;  // physics steps per controller step
  std::vector<LegSlots> legs;
  std::vector<JointSlot> backbone;  // the backbone servo, if the robot has one
  int root_qpos = -1;               // free joint: x y z, then quaternion
  // sensordata address of the yaw frame's quaternion (a framequat sensor); without one (a robot
  // file), the frame's orientation itself: the body yaw_body or the site yaw_site.
  int yaw_sensor = -1;
  int yaw_body = -1;
  int yaw_site = -1;
  // The keyframe "start", or without one (a robot file) start_qpos: the start pose with the lowest
  // foot on the ground (make_sim_model).
  int start_key = -1;
  std::vector<double> start_qpos{};
  std::vector<robot::ModelFile> files{};  // the files beside the MJCF (robot::scene_files)
};

struct SimState {
  std::unique_ptr<mjData, MjDataDeleter> data;
  neural::ControllerState controller;
  std::vector<robot::LegAngles> targets;   // joint targets of the current controller step, rad
  long step = 0;                           // controller steps done
  std::array<int, mjNWARNING> warnings{};  // MuJoCo warning counts already seen
  FaultState faults;  // the faults that came, those in force and what they do to the physics
};

}  // namespace multicpg::sim
