#include "sim/sim.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "common/errors.h"
#include "robot/joint_map.h"
#include "sim/model_build.h"
#include "sim/mujoco_guard.h"

namespace multicpg::sim {
namespace {

using robot::Joint;
using robot::LegAngles;

robot::MjcfOptions mjcf_options(const SimOptions& options, double physics_dt,
                                const std::vector<LegAngles>& pose) {
  robot::MjcfOptions o;
  o.physics_dt = physics_dt;
  o.scene = options.scene;
  o.start_pose = pose;
  return o;
}

// The control that makes the model's own actuator of `slot` exert no force at the joint's
// present state: its force is gain * ctrl + bias0 + bias1 * length + bias2 * velocity, its length
// gear * the joint's angle (a joint transmission).
double zero_force_ctrl(const mjModel* m, const mjData* d, const JointSlot& slot) {
  const double* bias = m->actuator_biasprm + mjNBIAS * slot.actuator;
  return -(bias[0] + bias[1] * slot.gear * d->qpos[slot.qpos] +
           bias[2] * slot.gear * d->qvel[slot.dof]) /
         m->actuator_gainprm[mjNGAIN * slot.actuator];
}

void drive(const SimModel& model, const mjModel* m, mjData* d, const JointSlot& slot, double target,
           const JointCondition& condition = {}) {
  double& ctrl = d->ctrl[slot.actuator];
  if (slot.drive == Drive::servo) {
    ctrl = condition.servo == JointCondition::Servo::driven
               ? slot.sign *
                     servo_torque(slot.servo, target, slot.sign * d->qpos[slot.qpos],
                                  slot.sign * d->qvel[slot.dof], model.physics_dt,
                                  condition.torque_scale) /
                     slot.gear
               : 0.0;
    return;
  }
  // The model's own servo: the target angle, or the servo law's commanded velocity, in the
  // actuator's units; a weak motor exerts its share of that force, a locked or passive one none.
  const double idle = zero_force_ctrl(m, d, slot);
  if (condition.servo != JointCondition::Servo::driven) {
    ctrl = idle;
    return;
  }
  const double wanted =
      slot.drive == Drive::position
          ? slot.gear * slot.sign * target
          : slot.gear * slot.sign *
                commanded_velocity(slot.servo.spec, target - slot.sign * d->qpos[slot.qpos],
                                   model.physics_dt);
  ctrl = idle + condition.torque_scale * (wanted - idle);
}

[[noreturn]] void unstable(const SimState& state, double time, const std::string& why) {
  std::ostringstream msg;
  msg << "physics became unstable at step " << state.step << " (t = " << time << " s): " << why;
  throw RuntimeFailure(msg.str());
}

// Limits no real robot of this size reaches; beyond them the simulation has exploded even when
// every number is finite (a too large --physics-dt can throw the trunk kilometres in one step).
// Measured: the trunk moves at most 0.3 m/s within one physics step (walk, tunnel, every robot);
// falling from its own height (0.1 m) gives 1.4 m/s, so 10 m/s is far out of reach.
constexpr double kMaxTrunkSpeed = 10.0;  // m/s
// A contact deeper than the trunk is high (0.065 m, robot/body.cpp kTrunkHeight) means a body
// has passed into the ground or a wall. Measured: feet start up to 0.035 m deep in the first
// physics step (then the contacts push them out); walking stays shallower (walk, tunnel, every
// robot, control step 0.037 and 0.1 s).
constexpr double kMaxPenetration = 0.065;  // m

// The name of the body geom `geom` belongs to ("world" for the ground and walls).
std::string body_name(const mjModel* m, int geom) {
  const int body = m->geom_bodyid[geom];
  const char* name = mj_id2name(m, mjOBJ_BODY, body);
  return name != nullptr ? name : "body " + std::to_string(body);
}

void check_physics(const SimModel& model, const SimState& state, double previous_time,
                   const Position& previous) {
  const mjModel* m = model.mj.get();
  const mjData* d = state.data.get();
  for (int w = 0; w < mjNWARNING; ++w) {
    if (d->warning[w].number != state.warnings[w]) {
      unstable(state, previous_time, mujoco_warning(w));
    }
  }
  // MuJoCo resets the state (time back to 0) when it meets a bad number.
  if (!(d->time > previous_time)) unstable(state, previous_time, "MuJoCo reset the simulation");
  for (int i = 0; i < m->nq; ++i) {
    if (!std::isfinite(d->qpos[i])) {
      unstable(state, previous_time, "qpos[" + std::to_string(i) + "] not finite");
    }
  }
  for (int i = 0; i < m->nv; ++i) {
    if (!std::isfinite(d->qvel[i])) {
      unstable(state, previous_time, "qvel[" + std::to_string(i) + "] not finite");
    }
  }
  const Position now = trunk_position(model, state);
  const double moved = std::hypot(now.x - previous.x, now.y - previous.y, now.z - previous.z);
  const double speed = std::max(moved / (d->time - previous_time), 0.0);
  if (speed > kMaxTrunkSpeed) {
    std::ostringstream why;
    why << "the trunk moved " << moved << " m in one physics step (" << speed << " m/s, limit "
        << kMaxTrunkSpeed << " m/s)";
    unstable(state, previous_time, why.str());
  }
  for (int c = 0; c < d->ncon; ++c) {
    if (d->contact[c].dist < -kMaxPenetration) {
      std::ostringstream why;
      why << body_name(m, d->contact[c].geom1) << " and " << body_name(m, d->contact[c].geom2)
          << " interpenetrate by " << -d->contact[c].dist << " m (limit " << kMaxPenetration
          << " m)";
      unstable(state, previous_time, why.str());
    }
  }
}

// Rough ground and steps cover a square around the start (robot/terrain.h): a robot past its edge
// walks on what it was not asked to walk on.
void check_on_terrain(const SimModel& model, const SimState& state) {
  if (!robot::bounded(model.scene.terrain)) return;
  const Position p = trunk_position(model, state);
  const double half = robot::kTerrainSide / 2.0;
  if (std::abs(p.x) > half || std::abs(p.y) > half) {
    throw RuntimeFailure(fmt::format(
        "the robot walked off the {} terrain at step {} (x = {:.2f} m, y = {:.2f} m; it covers "
        "{} m around the start)",
        robot::terrain_text(model.scene.terrain), state.step, p.x, p.y, half));
  }
}

}  // namespace

SimModel make_sim_model(robot::RobotKind kind, const SimOptions& options) {
  const robot::RobotFile map = robot::builtin_robot_file(kind, {});
  SimModel model = new_model(kind, options, map);
  model.xml =
      robot::make_mjcf(model.body, mjcf_options(options, model.physics_dt, model.start_pose));
  model.files = robot::scene_files(options.scene);
  model.mj = compile_mjcf(model.xml, model.files);
  index_model(model, map, options);
  return model;
}

std::string model_xml(robot::RobotKind kind, const SimOptions& options) {
  const SimModel model = new_model(kind, options, robot::builtin_robot_file(kind, {}));
  return robot::make_mjcf(model.body, mjcf_options(options, model.physics_dt, model.start_pose));
}

void reset_to_start(const SimModel& model, mjData* d) {
  const mjModel* m = model.mj.get();
  if (model.start_key >= 0) {
    mj_resetDataKeyframe(m, d, model.start_key);
  } else {
    mj_resetData(m, d);
    std::copy(model.start_qpos.begin(), model.start_qpos.end(), d->qpos);
  }
}

SimState make_sim_state(const SimModel& model, int period) {
  const mjModel* m = model.mj.get();
  SimState state;
  state.data.reset(mj_makeData(m));
  if (!state.data) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  reset_to_start(model, state.data.get());
  mj_forward(m, state.data.get());  // sensors and contacts of the start pose
  for (int w = 0; w < mjNWARNING; ++w) state.warnings[w] = state.data->warning[w].number;
  state.controller = neural::make_controller_state(model.controller, period);
  state.targets = model.start_pose;
  state.faults.schedule = body::FaultSchedule(model.controller.morphology, {});
  state.faults.joints.resize(model.legs.size());
  return state;
}

const mjModel* physics_model(const SimModel& model, const SimState& state) {
  return state.faults.model ? state.faults.model.get() : model.mj.get();
}

SimState copy_sim_state(const SimModel& model, const SimState& state) {
  SimState copy;
  copy.data.reset(mj_makeData(model.mj.get()));
  if (!copy.data) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  mj_copyData(copy.data.get(), physics_model(model, state), state.data.get());
  copy.controller = state.controller;
  copy.targets = state.targets;
  copy.step = state.step;
  copy.warnings = state.warnings;
  copy.faults = state.faults;  // the run's own model is never changed in place: shared safely
  return copy;
}

void sim_step(const SimModel& model, SimState& state) {
  neural::controller_step(model.controller, state.controller);
  for (std::size_t i = 0; i < model.legs.size(); ++i) {
    const neural::MotorCommands& c = state.controller.legs[i].command;
    const auto& w = model.legs[i].windows;
    state.targets[i] = {robot::joint_angle(w[0], c.tc), robot::joint_angle(w[1], c.ctr),
                        robot::joint_angle(w[2], c.fti)};
  }
  physics_step(model, state);
}

void physics_step(const SimModel& model, SimState& state) {
  const mjModel* m = physics_model(model, state);
  mjData* d = state.data.get();
  for (int s = 0; s < model.substeps; ++s) {
    for (std::size_t i = 0; i < model.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        drive(model, m, d, model.legs[i].joints[j], state.targets[i][j], state.faults.joints[i][j]);
      }
    }
    for (const JointSlot& slot : model.backbone) drive(model, m, d, slot, 0.0);  // held at 0
    const double previous_time = d->time;
    const Position previous = trunk_position(model, state);
    try {
      mujoco_call([m, d] { mj_step(m, d); });
    } catch (const RuntimeFailure&) {
      d->pstack = 0;  // the failed step's stack allocations; nothing else holds the stack now
      throw;
    }
    check_physics(model, state, previous_time, previous);
  }
  check_on_terrain(model, state);
  ++state.step;
}

Position trunk_position(const SimModel& model, const SimState& state) {
  const double* q = state.data->qpos + model.root_qpos;
  return {q[0], q[1], q[2]};
}

double trunk_yaw_deg(const SimModel& model, const SimState& state) {
  // Yaw of the front trunk's frame: heading of its x axis in the ground plane.
  std::array<double, 4> frame{};  // w x y z
  const double* q = frame.data();
  if (model.yaw_sensor >= 0) {
    q = state.data->sensordata + model.yaw_sensor;
  } else if (model.yaw_body >= 0) {
    q = state.data->xquat + 4 * model.yaw_body;
  } else {
    mju_mat2Quat(frame.data(), state.data->site_xmat + 9 * model.yaw_site);
  }
  const double yaw =
      std::atan2(2.0 * (q[0] * q[3] + q[1] * q[2]), 1.0 - 2.0 * (q[2] * q[2] + q[3] * q[3]));
  return wrap_degrees(yaw * 180.0 / std::numbers::pi);
}

double joint_angle(const SimModel& model, const SimState& state, std::size_t leg, Joint joint) {
  const JointSlot& slot = model.legs[leg].joints[static_cast<std::size_t>(joint)];
  const double* q = state.data->qpos;
  return slot.sign * (slot.coupling_qpos < 0 ? q[slot.qpos] : q[slot.qpos] + q[slot.coupling_qpos]);
}

double foot_force(const SimModel& model, const SimState& state, std::size_t leg) {
  const LegSlots& slots = model.legs[leg];
  if (slots.touch >= 0) return state.data->sensordata[slots.touch];
  const mjModel* m = physics_model(model, state);
  const mjData* d = state.data.get();
  double force = 0.0;
  for (int c = 0; c < d->ncon; ++c) {
    if (d->contact[c].geom1 != slots.foot_geom && d->contact[c].geom2 != slots.foot_geom) continue;
    std::array<mjtNum, 6> f{};  // normal, then tangential, in the contact's frame
    mj_contactForce(m, d, c, f.data());
    force += f[0];
  }
  return force;
}

bool foot_contact(const SimModel& model, const SimState& state, std::size_t leg) {
  return foot_force(model, state, leg) > kContactThresholdN;
}

}  // namespace multicpg::sim
