// The simulated robot: a MuJoCo model driven by the neural controller (docs/robots.md).
//
// SimModel is what the simulation is (the mjModel, index tables, time steps, the controller's
// model): immutable after make_sim_model and shareable read-only by any number of threads.
// SimState is what one run is doing (mjData, controller state, step counter); each thread owns
// its own. Same model, same inputs -> bit-identical trajectories.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "common/angles.h"
#include "common/limits.h"
#include "neural/controller.h"
#include "robot/body.h"
#include "robot/body_models.h"
#include "robot/body_params.h"
#include "robot/mjcf.h"
#include "robot/robot_file.h"
#include "sim/fault_state.h"
#include "sim/servo.h"

namespace multicpg::sim {

// One controller step of simulated time: 0.037 s, the paper's 27 Hz (paper §4).
inline constexpr double kDefaultControlDt = 0.037;
// Largest default physics step (docs/robots.md "Integrator and time steps").
inline constexpr double kMaxDefaultPhysicsDt = 0.005;
// How close control_dt / physics_dt must be to a whole number (relative).
inline constexpr double kStepRatioTolerance = 1e-6;
// A foot touches the ground when its touch sensor reads more than this normal force.
inline constexpr double kContactThresholdN = 0.5;
// The controller step of the authors' simulation (docs/robots.md "Servos"), at which its servo gain
// K = maxVel / 2 was set.
inline constexpr double kReferenceControlDt = 0.1;

// The largest physics step <= kMaxDefaultPhysicsDt that divides control_dt exactly
// (0.037 s -> 0.037 / 8 = 0.004625 s).
double default_physics_dt(double control_dt);

// Most physics steps per controller step: 10^6 (a 0.037 s step at 37 ns), far beyond any useful
// ratio and well inside an int.
inline constexpr int kMaxSubsteps = 1'000'000;

// Physics steps per controller step. Throws BadInput unless both steps are positive and
// control_dt / physics_dt is a whole number within kStepRatioTolerance, at most kMaxSubsteps.
int physics_substeps(double control_dt, double physics_dt);

// Documented ranges. The controller step: 0.1 ms to 1 s around the paper's
// 37 ms; the physics step: down to 1 us (0 = default); servo gain up to 10^4 1/s (0 = default),
// past which a servo reaches its target within one 5 ms physics step anyway.
inline constexpr Limits<double> kControlDtLimits{1e-4, 1.0};
inline constexpr Limits<double> kPhysicsDtLimits{0.0, 0.1};
inline constexpr double kMinPhysicsDt = 1e-6;
inline constexpr Limits<double> kServoGainLimits{0.0, 1e4};
// The tunnel of the paper is 3 m x 1.2 m (paper §4); any other stays within a room's size.
inline constexpr Limits<double> kTunnelLengthLimits{0.1, 100.0};
inline constexpr Limits<double> kTunnelWidthLimits{0.1, 10.0};

struct SimOptions {
  double control_dt = kDefaultControlDt;  // s
  double physics_dt = 0.0;                // s; 0 = default_physics_dt(control_dt)
  // Servo gain K (1/s). 0 = lpzrobots' K scaled by kReferenceControlDt / control_dt, so a
  // servo closes the same share of its error per controller step as in lpzrobots
  // (14.15 1/s at 0.037 s; docs/robots.md).
  double servo_gain = 0.0;
  robot::Scene scene;
  neural::ControllerParams controller;
  // The physical parameters (robot/body_params.h), and the named model they started from
  // (robot/body_models.h; recorded, the values are what counts).
  robot::BodyModel model = robot::kDefaultBodyModel;
  robot::BodyParams body;
};

// Where one servo's joint lives in the mjModel.
// How a servo joint is driven (docs/robots.md "Your robot: robot files"): the servo law's torque
// through a motor (the built-in robots; a robot file's motors, and the motors added to its joints
// that have no actuator), or the model's own position or velocity actuator, which is given the
// servo's target angle or commanded velocity and acts with its own gains.
enum class Drive { servo, position, velocity };

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

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
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

// Throws OptionError (key "control_dt", "controller.cpg.w11", "body.total_mass", ...) for a value
// outside its range, a physics step below kMinPhysicsDt or one that does not divide the control
// step (physics_substeps).
void validate(const SimOptions& options);
// The same, and the body's leg postures name legs of `kind` ("body.leg_postures[0].leg").
void validate(const SimOptions& options, robot::RobotKind kind);

// Compiles MJCF text (through MuJoCo's in-memory file system). Throws RuntimeFailure if MuJoCo
// rejects it.
std::unique_ptr<mjModel, MjModelDeleter> compile_mjcf(
    const std::string& xml, const std::vector<robot::ModelFile>& files = {});

// The MJCF of a URDF, as MuJoCo's own loader reads it. Throws RuntimeFailure with MuJoCo's
// message if it refuses the URDF.
std::string urdf_as_mjcf(const std::string& urdf);

// Routes MuJoCo's warnings (kept for sim_step's error) and fatal errors (one line on stderr,
// exit 1) away from stdout, MUJOCO_LOG.TXT and its "Press Enter" prompt. Idempotent;
// make_sim_model calls it, the CLI calls it first thing.
void install_mujoco_handlers();

// Builds the MJCF from robot::robot_body(kind, options.body), compiles it and indexes it. Throws
// BadInput for bad options (validate), RuntimeFailure if MuJoCo rejects the model.
SimModel make_sim_model(robot::RobotKind kind, const SimOptions& options = {});

// The robot of a robot file (sim/robot_file.h load_robot_file) with its layout's controller,
// servos and fault geometry. Its model is walked as written on its flat ground or options'
// terrain, inside the tunnel's walls with options.scene.tunnel, at options' physics step. Throws
// OptionError ("scene.terrain") for other ground under a model with contact pairs, and with the
// file's key ("legs[0].TC.joint", "yaw", ...) for a name of the
// leg map that its model lacks; RuntimeFailure if MuJoCo rejects the model.
SimModel make_sim_model(const robot::RobotFile& file, const SimOptions& options = {});

// The MJCF make_sim_model compiles (what `multicpg model` prints).
std::string model_xml(robot::RobotKind kind, const SimOptions& options = {});

struct SimState {
  std::unique_ptr<mjData, MjDataDeleter> data;
  neural::ControllerState controller;
  std::vector<robot::LegAngles> targets;   // joint targets of the current controller step, rad
  long step = 0;                           // controller steps done
  std::array<int, mjNWARNING> warnings{};  // MuJoCo warning counts already seen
  FaultEffects faults;                     // what the faults in force do to the physics
};

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
// controller (the hardware emulator, hw/emulator.h, moves the robot to targets it received).
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
