#include "sim/sim.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <numbers>
#include <sstream>

#include "common/errors.h"
#include "common/limits.h"
#include "robot/joint_map.h"
#include "sim/mujoco_guard.h"
#include "sim/robot_file.h"

namespace multicpg::sim {
namespace {

using robot::Joint;
using robot::LegAngles;

// MuJoCo reports instability through mjData's warning counters, which sim_step checks; its
// default handler would also print to stdout and append to MUJOCO_LOG.TXT. Keep the last message
// of this thread for the error instead.
thread_local std::string last_warning;

void keep_warning(const char* message) {
  last_warning = message;
}

// MuJoCo's fatal errors (e.g. an offscreen buffer larger than OpenGL allows). The default handler
// prints to stdout, appends to MUJOCO_LOG.TXT and waits for Enter. mju_error must not return to
// MuJoCo (2.2.2 carries on with the broken state if the handler returns). Inside mujoco_call of a
// process that recovers (sim/mujoco_guard.h) it jumps back there. Otherwise the ways to leave it
// early are unsound here: a C++ exception would unwind through MuJoCo's C frames (undefined
// behaviour, and its mjData stack would stay half-allocated); longjmp would skip the destructors
// of our C++ frames. So: one line on stderr, then _Exit(1). _Exit, not exit: other runner threads
// may still be simulating and must not see static destructors run. A temporary output file it
// leaves (*.tmp<pid>) is removed by the next experiment in that folder.
std::atomic<bool> recovering{false};

[[noreturn]] void fatal_error(const char* message) {
  if (MujocoJump* jump = armed_mujoco_jump(); jump != nullptr) {
    // Nothing with a destructor is made on this path (it is skipped by the jump).
    std::snprintf(jump->message.data(), jump->message.size(), "%s", message);
    std::longjmp(jump->buffer, 1);
  }
  std::string line = std::string("multicpg: MuJoCo error: ") + message;
  std::replace(line.begin(), line.end(), '\n', ' ');
  line += '\n';
  std::fwrite(line.data(), 1, line.size(), stderr);
  std::fflush(stderr);
  std::_Exit(1);
}

const char* warning_name(int warning) {
  switch (warning) {
    case mjWARN_INERTIA:
      return "singular inertia";
    case mjWARN_CONTACTFULL:
      return "contact buffer full";
    case mjWARN_CNSTRFULL:
      return "constraint buffer full";
    case mjWARN_VGEOMFULL:
      return "visual geom buffer full";
    case mjWARN_BADQPOS:
      return "bad qpos";
    case mjWARN_BADQVEL:
      return "bad qvel";
    case mjWARN_BADQACC:
      return "bad qacc";
    case mjWARN_BADCTRL:
      return "bad ctrl";
    default:
      break;
  }
  return "warning";
}

// The start pose: every leg in mid-stance (docs/controller.md "Motor mapping and joint windows"):
// TC and FTi at the centre of their windows (pre-motor signal 0), CTr fully depressed (-1, the
// stance value of docs/controller.md "Post-delay shaping").
std::vector<LegAngles> start_pose(const neural::ControllerModel& controller,
                                  const robot::RobotFile& map) {
  std::vector<LegAngles> pose;
  for (std::size_t i = 0; i < map.legs.size(); ++i) {
    const neural::MotorCommands m = controller.legs[i].map({0.0, -1.0, 0.0});
    const auto& w = map.legs[i].joints;
    pose.push_back({robot::joint_angle(w[0].window, m.tc), robot::joint_angle(w[1].window, m.ctr),
                    robot::joint_angle(w[2].window, m.fti)});
  }
  return pose;
}

robot::MjcfOptions mjcf_options(const SimOptions& options, double physics_dt,
                                const std::vector<LegAngles>& pose) {
  robot::MjcfOptions o;
  o.physics_dt = physics_dt;
  o.scene = options.scene;
  o.start_pose = pose;
  return o;
}

double resolved_physics_dt(const SimOptions& options) {
  return options.physics_dt == 0.0 ? default_physics_dt(options.control_dt) : options.physics_dt;
}

// Where a leg map's names are in a model. Each throws OptionError with the robot file's key.
int id_of(const mjModel* m, mjtObj type, const std::string& name, const std::string& key,
          const char* what) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0) throw OptionError(key, fmt::format("the model has no {} '{}'", what, name));
  return id;
}

// The servo joint `map` names: a limited hinge that a motor drives, whose range holds the
// window (up to kWindowTolerance, as the MJCF writes angles to 12 digits, robot/mjcf.cpp).
constexpr double kWindowTolerance = 1e-9;  // rad

// What kind of actuator `a` is (MuJoCo's shortcuts are general actuators with these parameters):
// a motor (no bias), a position servo (bias -kp * length) or a velocity servo (bias
// -kv * velocity), each without activation dynamics so that its force follows its control at once.
Drive actuator_drive(const mjModel* m, int a, const std::string& key) {
  const char* name = mj_id2name(m, mjOBJ_ACTUATOR, a);
  const std::string what = fmt::format("actuator '{}'", name != nullptr ? name : std::to_string(a));
  if (m->actuator_dyntype[a] != mjDYN_NONE || m->actuator_gaintype[a] != mjGAIN_FIXED ||
      m->actuator_gainprm[mjNGAIN * a] == 0.0 || m->actuator_gear[6 * a] == 0.0) {
    throw OptionError(key, what + " is not a motor, position or velocity actuator");
  }
  if (m->actuator_biastype[a] == mjBIAS_NONE) return Drive::servo;
  const double* bias = m->actuator_biasprm + mjNBIAS * a;
  if (m->actuator_biastype[a] == mjBIAS_AFFINE && bias[0] == 0.0) {
    if (bias[1] != 0.0) return Drive::position;
    if (bias[2] != 0.0) return Drive::velocity;
  }
  throw OptionError(key, what + " is not a motor, position or velocity actuator");
}

JointSlot joint_slot(const mjModel* m, const robot::JointMap& map, const std::string& key,
                     robot::ServoSpec spec, double gain) {
  const int j = id_of(m, mjOBJ_JOINT, map.name, key + ".joint", "joint");
  if (m->jnt_type[j] != mjJNT_HINGE) {
    throw OptionError(key + ".joint", "joint '" + map.name + "' is not a hinge");
  }
  if (m->jnt_limited[j] == 0) {
    throw OptionError(key + ".joint",
                      "joint '" + map.name + "' has no range (limited=\"true\" range=\"lo hi\")");
  }
  const double lo = std::min(map.sign * map.window.lo, map.sign * map.window.hi);
  const double hi = std::max(map.sign * map.window.lo, map.sign * map.window.hi);
  if (lo < m->jnt_range[2 * j] - kWindowTolerance ||
      hi > m->jnt_range[2 * j + 1] + kWindowTolerance) {
    throw OptionError(
        key + ".window",
        fmt::format("[{}, {}] rad leaves joint '{}''s range [{}, {}] rad", map.window.lo,
                    map.window.hi, map.name, m->jnt_range[2 * j], m->jnt_range[2 * j + 1]));
  }
  JointSlot slot;
  slot.joint = j;
  slot.qpos = m->jnt_qposadr[j];
  slot.dof = m->jnt_dofadr[j];
  slot.sign = map.sign;
  for (int a = 0; a < m->nu; ++a) {
    if (m->actuator_trntype[a] == mjTRN_JOINT && m->actuator_trnid[2 * a] == j) slot.actuator = a;
  }
  if (slot.actuator < 0) {
    throw OptionError(key + ".joint", "no actuator drives joint '" + map.name + "'");
  }
  slot.drive = actuator_drive(m, slot.actuator, key + ".joint");
  slot.gear = m->actuator_gear[6 * slot.actuator];
  const int coupling = mj_name2id(m, mjOBJ_JOINT, robot::coupling_joint(map.name).c_str());
  if (coupling >= 0) slot.coupling_qpos = m->jnt_qposadr[coupling];
  spec.gain = gain;
  slot.servo = {spec, map.window.hi - map.window.lo};
  return slot;
}

// A leg's foot: its geom, the body it moves with and that body's parent (the tibia), and if the
// model has them the touch sensor on a site of the foot's body and the foot's contact pair with
// the ground.
void index_foot(const mjModel* m, const std::string& foot, const std::string& key,
                LegSlots& slots) {
  slots.foot_geom = mj_name2id(m, mjOBJ_GEOM, foot.c_str());
  if (slots.foot_geom < 0) {
    const int body = mj_name2id(m, mjOBJ_BODY, foot.c_str());
    if (body < 0 || m->body_geomnum[body] == 0) {
      throw OptionError(key, fmt::format("the model has no geom '{}', nor a body of that name with "
                                         "a geom (a URDF's fixed links are fused into their "
                                         "parents unless its <mujoco><compiler fusestatic="
                                         "\"false\"/></mujoco>)",
                                         foot));
    }
    slots.foot_geom = m->body_geomadr[body];
  }
  slots.foot_body = m->geom_bodyid[slots.foot_geom];
  slots.tibia_body = m->body_parentid[slots.foot_body];
  if (m->body_geomnum[slots.tibia_body] == 0) {
    throw OptionError(key, "the body above foot '" + foot + "' (the tibia) has no geom");
  }
  slots.tibia_geom = m->body_geomadr[slots.tibia_body];
  for (int s = 0; s < m->nsensor && slots.touch < 0; ++s) {
    if (m->sensor_type[s] == mjSENS_TOUCH &&
        m->site_bodyid[m->sensor_objid[s]] == slots.foot_body) {
      slots.touch = m->sensor_adr[s];
    }
  }
  for (int p = 0; p < m->npair; ++p) {
    if (m->pair_geom2[p] == slots.foot_geom || m->pair_geom1[p] == slots.foot_geom) {
      slots.foot_pair = p;
    }
  }
}

// The yaw frame `name`, a body or a site: the sensordata address of its framequat sensor, or
// without one the frame itself.
void index_yaw(const mjModel* m, const std::string& name, SimModel& model) {
  const int body = mj_name2id(m, mjOBJ_BODY, name.c_str());
  const int site = mj_name2id(m, mjOBJ_SITE, name.c_str());
  if (body < 0 && site < 0)
    throw OptionError("yaw", "the model has no body or site '" + name + "'");
  for (int s = 0; s < m->nsensor; ++s) {
    if (m->sensor_type[s] != mjSENS_FRAMEQUAT) continue;
    const int type = m->sensor_objtype[s];
    const int id = m->sensor_objid[s];
    if (((type == mjOBJ_XBODY || type == mjOBJ_BODY) && id == body) ||
        (type == mjOBJ_SITE && id == site)) {
      model.yaw_sensor = m->sensor_adr[s];
      return;
    }
  }
  model.yaw_body = body;
  model.yaw_site = body < 0 ? site : -1;
}

// The lowest point of geom `g` in the pose of `d` (its frame computed): exact for spheres,
// capsules, cylinders, boxes and ellipsoids; other shapes by their bounding sphere.
double lowest_point(const mjModel* m, const mjData* d, int g) {
  const double* size = m->geom_size + 3 * g;
  const double* r = d->geom_xmat + 9 * g;  // row 2: the world z of the geom's local axes
  const double z = d->geom_xpos[3 * g + 2];
  const double az = std::abs(r[8]);
  switch (m->geom_type[g]) {
    case mjGEOM_SPHERE:
      return z - size[0];
    case mjGEOM_CAPSULE:
      return z - az * size[1] - size[0];
    case mjGEOM_CYLINDER:
      return z - az * size[1] - size[0] * std::sqrt(std::max(0.0, 1.0 - az * az));
    case mjGEOM_BOX:
      return z - std::abs(r[6]) * size[0] - std::abs(r[7]) * size[1] - az * size[2];
    case mjGEOM_ELLIPSOID:
      return z - std::hypot(r[6] * size[0], r[7] * size[1], r[8] * size[2]);
    default:
      return z - m->geom_rbound[g];
  }
}

// The height of the ground: the highest plane of the world body (0 without one).
double ground_height(const mjModel* m) {
  double height = 0.0;
  bool found = false;
  for (int g = 0; g < m->ngeom; ++g) {
    if (!is_ground_plane(m, g)) continue;
    const double z = m->geom_pos[3 * g + 2];
    height = found ? std::max(height, z) : z;
    found = true;
  }
  return height;
}

// Feet above the trunk's lowest point by more than this stand on the trunk, not their legs.
constexpr double kStartTolerance = 1e-3;  // m

// The start pose of a model without a "start" keyframe: its qpos0 with the servo joints at
// model.start_pose and the trunk lowered or raised until its lowest foot rests on the ground.
// Throws OptionError ("legs") if a geom of the trunk's body hangs below the feet.
std::vector<double> start_qpos(const SimModel& model, int trunk) {
  const mjModel* m = model.mj.get();
  const std::unique_ptr<mjData, MjDataDeleter> d(mj_makeData(m));
  if (!d) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  for (std::size_t i = 0; i < model.legs.size(); ++i) {
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const JointSlot& slot = model.legs[i].joints[j];
      d->qpos[slot.qpos] = slot.sign * model.start_pose[i][j];
    }
  }
  mj_kinematics(m, d.get());
  double lowest = std::numeric_limits<double>::infinity();
  for (const LegSlots& leg : model.legs) {
    lowest = std::min(lowest, lowest_point(m, d.get(), leg.foot_geom));
  }
  // The legs must hold the trunk up: no geom of the trunk's body below the feet.
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != trunk) continue;
    const double below = lowest - lowest_point(m, d.get(), g);
    if (below > kStartTolerance) {
      const char* name = mj_id2name(m, mjOBJ_GEOM, g);
      throw OptionError("legs", fmt::format("the feet do not reach the ground in the start pose: "
                                            "the trunk's geom '{}' hangs {:.3f} m below them",
                                            name != nullptr ? name : std::to_string(g), below));
    }
  }
  d->qpos[model.root_qpos + 2] += ground_height(m) - lowest;
  return {d->qpos, d->qpos + m->nq};
}

// Every name of the leg map found in the model's tables.
void index_model(SimModel& model, const robot::RobotFile& map, const SimOptions& options) {
  const mjModel* m = model.mj.get();
  const robot::RobotBody& body = model.body;
  const auto gain = [&](const robot::ServoSpec& spec) {
    return options.servo_gain > 0.0 ? options.servo_gain
                                    : spec.gain * kReferenceControlDt / model.control_dt;
  };
  const std::array<const robot::ServoSpec*, robot::kJointsPerLeg> specs{
      &body.tc_servo, &body.ctr_servo, &body.fti_servo};
  for (std::size_t i = 0; i < map.legs.size(); ++i) {
    const robot::LegMap& leg = map.legs[i];
    const std::string key = "legs[" + std::to_string(i) + "]";
    LegSlots slots{body.morphology.legs[i].type, {}, {}};
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      const std::string joint_key = key + "." + std::string(robot::to_string(robot::kJoints[j]));
      slots.joints[j] = joint_slot(m, leg.joints[j], joint_key, *specs[j], gain(*specs[j]));
      slots.windows[j] = leg.joints[j].window;
    }
    index_foot(m, leg.foot, key + ".foot", slots);
    model.legs.push_back(slots);
  }
  if (map.backbone) {
    model.backbone.push_back(
        joint_slot(m, *map.backbone, "backbone", body.backbone_servo, gain(body.backbone_servo)));
  }
  const int trunk = id_of(m, mjOBJ_BODY, map.trunk, "trunk", "body");
  if (m->body_jntnum[trunk] == 0 || m->jnt_type[m->body_jntadr[trunk]] != mjJNT_FREE) {
    throw OptionError("trunk", "body '" + map.trunk + "' has no free joint (<freejoint/>)");
  }
  model.root_qpos = m->jnt_qposadr[m->body_jntadr[trunk]];
  index_yaw(m, map.yaw, model);
  model.start_key = mj_name2id(m, mjOBJ_KEY, "start");
  if (model.start_key < 0) model.start_qpos = start_qpos(model, trunk);
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
      unstable(state, previous_time,
               std::string("MuJoCo warning '") + warning_name(w) + "': " + last_warning);
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

namespace {

// The XML parser is not documented as thread-safe, and it keeps the last model it read (for
// mj_saveLastXML), so loads are serialised.
std::mutex& loader_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Loads `main` (MJCF or URDF, by its root element) with `files` beside it from MuJoCo's in-memory
// file system. Call with loader_mutex() held.
mjModel* load_in_memory(const std::string& name, const std::string& main,
                        const std::vector<robot::ModelFile>& files) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const auto add = [&](const std::string& file, const std::string& bytes) {
    if (mj_makeEmptyFileVFS(vfs.get(), file.c_str(), static_cast<int>(bytes.size())) != 0) {
      mj_deleteVFS(vfs.get());
      throw RuntimeFailure("MuJoCo: cannot make the in-memory model file " + file);
    }
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file.c_str())], bytes.data(), bytes.size());
  };
  add(name, main);
  for (const robot::ModelFile& f : files) add(f.name, f.bytes);
  std::array<char, 1000> error{};
  mjModel* m = mj_loadXML(name.c_str(), vfs.get(), error.data(), static_cast<int>(error.size()));
  mj_deleteVFS(vfs.get());
  if (m == nullptr) throw RuntimeFailure(std::string("MuJoCo rejected the model: ") + error.data());
  return m;
}

}  // namespace

std::unique_ptr<mjModel, MjModelDeleter> compile_mjcf(const std::string& xml,
                                                      const std::vector<robot::ModelFile>& files) {
  const std::lock_guard<std::mutex> lock(loader_mutex());
  return std::unique_ptr<mjModel, MjModelDeleter>(load_in_memory("multicpg.xml", xml, files));
}

std::string urdf_as_mjcf(const std::string& urdf) {
  const std::lock_guard<std::mutex> lock(loader_mutex());
  const std::unique_ptr<mjModel, MjModelDeleter> m(load_in_memory("multicpg.urdf", urdf, {}));
  // MuJoCo writes the model it read last only to a file.
  static std::atomic<unsigned> count{0};
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     fmt::format("multicpg-urdf-{}-{}.xml", ::getpid(), count++);
  std::array<char, 1000> error{};
  const int saved =
      mj_saveLastXML(path.string().c_str(), m.get(), error.data(), static_cast<int>(error.size()));
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  if (saved == 0 || !in) {
    throw RuntimeFailure(std::string("MuJoCo cannot write the URDF as MJCF: ") + error.data());
  }
  return text.str();
}

double default_physics_dt(double control_dt) {
  if (!(control_dt > 0.0)) throw OptionError("control_dt", "must be positive");
  // Tolerance so that 0.037 / 0.004625 = 8 exactly is not rounded up to 9.
  const double n = std::ceil(control_dt / kMaxDefaultPhysicsDt - kStepRatioTolerance);
  return control_dt / n;
}

int physics_substeps(double control_dt, double physics_dt) {
  if (!(control_dt > 0.0)) throw OptionError("control_dt", "must be positive");
  if (!(physics_dt > 0.0)) throw OptionError("physics_dt", "must be positive");
  const double ratio = control_dt / physics_dt;
  const double whole = std::round(ratio);
  if (!(whole <= static_cast<double>(kMaxSubsteps))) {
    std::ostringstream msg;
    msg << "gives " << ratio << " physics steps per control step of " << control_dt
        << " s; at most " << kMaxSubsteps;
    throw OptionError("physics_dt", msg.str());
  }
  if (whole < 1.0 || std::abs(ratio - whole) > kStepRatioTolerance * ratio) {
    std::ostringstream msg;
    msg << "must divide the control step " << control_dt << " s a whole number of times, got "
        << physics_dt << " s (ratio " << ratio << ")";
    throw OptionError("physics_dt", msg.str());
  }
  return static_cast<int>(whole);
}

void validate(const SimOptions& options) {
  require_in("control_dt", options.control_dt, kControlDtLimits);
  require_in("physics_dt", options.physics_dt, kPhysicsDtLimits);
  if (options.physics_dt != 0.0 && options.physics_dt < kMinPhysicsDt) {
    throw OptionError("physics_dt", fmt::format("must be 0 (default) or at least {}, got {}",
                                                kMinPhysicsDt, options.physics_dt));
  }
  require_in("servo_gain", options.servo_gain, kServoGainLimits);
  require_in("scene.tunnel_length", options.scene.tunnel_length, kTunnelLengthLimits);
  require_in("scene.tunnel_width", options.scene.tunnel_width, kTunnelWidthLimits);
  within("scene.terrain", [&] { robot::validate(options.scene.terrain); });
  within("controller", [&] { neural::validate(options.controller); });
  within("body", [&] { robot::validate(options.body); });
  physics_substeps(options.control_dt, resolved_physics_dt(options));
}

void validate(const SimOptions& options, robot::RobotKind kind) {
  validate(options);
  within("body", [&] { robot::disabled_postures(options.body, robot::morphology(kind)); });
}

std::string model_xml(robot::RobotKind kind, const SimOptions& options) {
  validate(options, kind);
  const double physics_dt = resolved_physics_dt(options);
  const neural::ControllerModel controller =
      neural::make_controller_model(kind, options.controller, options.body);
  const robot::RobotFile map = robot::builtin_robot_file(kind, {});
  return robot::make_mjcf(robot::robot_body(kind, options.body),
                          mjcf_options(options, physics_dt, start_pose(controller, map)));
}

void recover_mujoco_errors() {
  install_mujoco_handlers();
  recovering = true;
}

bool recovering_mujoco_errors() {
  return recovering;
}

MujocoJump*& armed_mujoco_jump() {
  thread_local MujocoJump* jump = nullptr;
  return jump;
}

void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = keep_warning;
    mju_user_error = fatal_error;
  });
}

namespace {

// A motor the servo law drives brings its servo's armature (docs/robots.md "Servos", departure 2)
// to a joint that has none: the explicit velocity loop is stable only with it.
void give_armature(SimModel& model, const std::vector<std::string>& servo_joints) {
  mjModel* m = model.mj.get();
  bool changed = false;
  for (const std::string& name : servo_joints) {
    const int dof = m->jnt_dofadr[mj_name2id(m, mjOBJ_JOINT, name.c_str())];
    if (m->dof_armature[dof] == 0.0) {
      m->dof_armature[dof] = model.body.tc_servo.armature;
      changed = true;
    }
  }
  if (!changed) return;
  // The constants MuJoCo derives from inertias at compile time.
  const std::unique_ptr<mjData, MjDataDeleter> scratch(mj_makeData(m));
  if (!scratch) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  mj_setConst(m, scratch.get());
}

// Other ground than a robot file's own flat one (robot::robot_file_mjcf): on a slope and rough
// ground its own planes no longer collide nor show. Throws OptionError ("scene.terrain") for a
// model whose contacts are only its <pair>s: they hold its feet to its own ground.
void leave_own_ground(mjModel* m, const robot::Terrain& terrain, const robot::RobotFile& file) {
  if (m->opt.collision == mjCOL_PAIR || m->npair > 0) {
    throw OptionError("scene.terrain",
                      fmt::format("{}: its model's <contact><pair>s hold the feet to its own "
                                  "ground: it walks only there, not on {} (docs/robots.md)",
                                  file.path.string(), robot::terrain_text(terrain)));
  }
  if (terrain.kind == robot::TerrainKind::steps) return;
  const int ours = mj_name2id(m, mjOBJ_GEOM, robot::kRobotFileGround);
  for (int g = 0; g < m->ngeom; ++g) {
    if (g == ours || !is_ground_plane(m, g)) continue;
    m->geom_contype[g] = 0;
    m->geom_conaffinity[g] = 0;
    m->geom_rgba[4 * g + 3] = 0.0F;
  }
}

// A robot file's start on other ground, as make_mjcf places the built-in robots: above rough
// ground's highest bump, or on a slope tilted with it about the start.
void place_on_terrain(SimModel& model, const robot::Terrain& terrain) {
  const mjModel* m = model.mj.get();
  std::vector<double> qpos = model.start_qpos;
  if (model.start_key >= 0) {
    qpos.assign(m->key_qpos + model.start_key * m->nq, m->key_qpos + (model.start_key + 1) * m->nq);
  }
  double* root = qpos.data() + model.root_qpos;
  if (terrain.kind == robot::TerrainKind::rough) root[2] += terrain.height_m;
  if (terrain.kind == robot::TerrainKind::slope) {
    const std::array<double, 4> q = robot::ground_rotation(terrain);
    const std::array<double, 3> p = robot::rotate(q, {root[0], root[1], root[2]});
    std::array<double, 4> tilted{};
    mju_mulQuat(tilted.data(), q.data(), root + 3);
    std::copy(p.begin(), p.end(), root);
    std::copy(tilted.begin(), tilted.end(), root + 3);
  }
  model.start_key = -1;
  model.start_qpos = std::move(qpos);
}

// The model of `kind` or of a robot file with the layout `kind`, before its MJCF is compiled.
SimModel new_model(robot::RobotKind kind, const SimOptions& options, const robot::RobotFile& map) {
  install_mujoco_handlers();
  validate(options, kind);
  SimModel model{kind,
                 robot::robot_body(kind, options.body),
                 neural::make_controller_model(kind, options.controller, options.body),
                 {},
                 options.scene,
                 {},
                 nullptr,
                 options.control_dt,
                 resolved_physics_dt(options),
                 0,
                 {},
                 {}};
  model.substeps = physics_substeps(model.control_dt, model.physics_dt);
  model.start_pose = start_pose(model.controller, map);
  return model;
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

SimModel make_sim_model(const robot::RobotFile& file, const SimOptions& options) {
  SimModel model = new_model(file.layout, options, file);
  const robot::Terrain& terrain = options.scene.terrain;
  const bool flat = terrain.kind == robot::TerrainKind::flat;
  if (options.scene.tunnel || !file.servo_joints.empty() || file.add_ground || !flat) {
    // Included as MJCF whatever it was (a URDF as MuJoCo's loader read it).
    const std::string name = file.model.stem().string() + ".xml";
    model.xml = robot::robot_file_mjcf(model.body, options.scene, file, name);
    model.files = robot::scene_files(options.scene);
    model.files.push_back({name, file.model_xml});
  } else {
    model.xml = file.model_xml;
  }
  model.mj = compile_mjcf(model.xml, model.files);
  give_armature(model, file.servo_joints);
  // The physics step and, in the tunnel, the wall contacts, as make_mjcf writes them.
  model.mj->opt.timestep = robot::mjcf_value(model.physics_dt);
  if (options.scene.tunnel) model.mj->opt.collision = mjCOL_ALL;
  if (!flat) leave_own_ground(model.mj.get(), terrain, file);
  index_model(model, file, options);
  if (!flat) place_on_terrain(model, terrain);
  return model;
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
