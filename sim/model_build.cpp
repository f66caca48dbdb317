#include "sim/model_build.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/errors.h"
#include "robot/joint_map.h"
#include "sim/mujoco_guard.h"

namespace multicpg::sim {
namespace {

using robot::LegAngles;

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

}  // namespace

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

bool is_ground_plane(const mjModel* m, int g) {
  return m->geom_bodyid[g] == 0 && m->geom_type[g] == mjGEOM_PLANE;
}

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

}  // namespace multicpg::sim
