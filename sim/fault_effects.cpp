#include "sim/fault_effects.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/errors.h"
#include "common/variants.h"

namespace multicpg::sim {
namespace {

// The kinds that give a run its own model.
bool reshapes(const body::Fault& fault) {
  return std::holds_alternative<body::LockedJoint>(fault.kind) ||
         std::holds_alternative<body::ShortTibia>(fault.kind) ||
         std::holds_alternative<body::SlipperyFoot>(fault.kind);
}

// A new model for the run, copied from the one it uses now, for a fault to change: the model it
// replaces stays as it was (a film may still be drawing from it).
mjModel* new_model(const SimModel& model, SimState& state) {
  mjModel* copy = mj_copyModel(nullptr, physics_model(model, state));
  if (copy == nullptr) throw RuntimeFailure("MuJoCo: cannot copy the model");
  state.faults.model = std::shared_ptr<const mjModel>(copy, mj_deleteModel);
  return copy;
}

// The joints a fault strikes: its joint, or all three of a leg.
std::vector<std::size_t> joints_of(const body::Fault& fault) {
  if (fault.joint) return {static_cast<std::size_t>(*fault.joint)};
  return {0, 1, 2};
}

void set_servo(SimState& state, const body::Fault& fault, JointCondition::Servo servo) {
  for (std::size_t leg : fault.legs) {
    for (std::size_t j : joints_of(fault)) {
      state.faults.joints[leg][j].servo = fault.recover ? JointCondition::Servo::driven : servo;
    }
  }
}

// Closes (or reopens) the limits of the locked joints on their lock angles.
void lock(const SimModel& model, SimState& state, const body::Fault& fault,
          const body::LockedJoint& locked) {
  set_servo(state, fault, JointCondition::Servo::locked);
  mjModel* m = new_model(model, state);
  const mjModel* original = model.mj.get();
  for (std::size_t leg : fault.legs) {
    for (std::size_t j : joints_of(fault)) {
      const JointSlot& slot = model.legs[leg].joints[j];
      double* range = m->jnt_range + 2 * slot.joint;
      if (fault.recover) {
        std::copy_n(original->jnt_range + 2 * slot.joint, 2, range);
        continue;
      }
      // The locked angle is the paper's; the joint's own is its sign times that.
      const double angle = locked.value ? slot.sign * *locked.value * std::numbers::pi / 180.0
                                        : state.data->qpos[slot.qpos];
      range[0] = angle;
      range[1] = angle;
    }
  }
}

// Capsule inertia about its centre (radius r, cylinder length h, density rho): the cylinder and
// the two hemispherical caps (whose centres of mass sit 3r/8 from their flat faces). MuJoCo
// computes this when it compiles a model but has no function for it at run time.
struct CapsuleInertia {
  double mass, axial, transverse;
};
CapsuleInertia capsule_inertia(double r, double h, double rho) {
  const double pi = std::numbers::pi;
  const double cylinder = rho * pi * r * r * h;
  const double caps = rho * 4.0 / 3.0 * pi * r * r * r;
  const double axial = cylinder * r * r / 2.0 + caps * 2.0 * r * r / 5.0;
  const double transverse = cylinder * (r * r / 4.0 + h * h / 12.0) +
                            caps * (2.0 * r * r / 5.0 + h * h / 4.0 + 3.0 * h * r / 8.0);
  return {cylinder + caps, axial, transverse};
}

// Shortens (or restores) the tibiae: the capsule's cylinder times the fraction left, its mass and
// inertia with it, the foot moved in by what was lost.
void shorten(const SimModel& model, SimState& state, const body::Fault& fault, double fraction) {
  mjModel* m = new_model(model, state);
  const mjModel* original = model.mj.get();
  const double f = fault.recover ? 1.0 : fraction;
  for (std::size_t leg : fault.legs) {
    const LegSlots& slots = model.legs[leg];
    const int g = slots.tibia_geom;
    const int tibia = slots.tibia_body;
    const int foot = slots.foot_body;
    if (original->geom_type[g] != mjGEOM_CAPSULE || foot == tibia) {
      throw BadInput(
          "a short tibia needs the tibia to be a capsule (the first geom of the foot's "
          "parent body) and the foot a body of its own (docs/robots.md)");
    }
    const double r = original->geom_size[3 * g];
    const double h = 2.0 * original->geom_size[3 * g + 1];
    const double mass = original->body_mass[tibia];
    const double rho = mass / capsule_inertia(r, h, 1.0).mass;
    const CapsuleInertia now = capsule_inertia(r, f * h, rho);
    m->geom_size[3 * g + 1] = f * h / 2.0;
    m->geom_rbound[g] = f * h / 2.0 + r;
    m->body_mass[tibia] = f == 1.0 ? mass : now.mass;
    // The principal axis of least inertia is the capsule's own.
    const double* before = original->body_inertia + 3 * tibia;
    const std::size_t axis =
        static_cast<std::size_t>(std::min_element(before, before + 3) - before);
    for (std::size_t k = 0; k < 3; ++k) {
      m->body_inertia[3 * tibia + k] =
          f == 1.0 ? before[k] : (k == axis ? now.axial : now.transverse);
      // The capsule starts at the FTi joint: its centre (and the tibia's centre of mass) moves
      // in with the fraction, the foot by the length lost.
      m->geom_pos[3 * g + k] = f * original->geom_pos[3 * g + k];
      m->body_ipos[3 * tibia + k] = f * original->body_ipos[3 * tibia + k];
      m->body_pos[3 * foot + k] =
          original->body_pos[3 * foot + k] - (1.0 - f) * 2.0 * original->geom_pos[3 * g + k];
    }
  }
  // Masses and inertias feed constants MuJoCo derives at compile time (subtree masses, ...).
  const std::unique_ptr<mjData, MjDataDeleter> scratch(mj_makeData(m));
  if (!scratch) throw RuntimeFailure("MuJoCo: cannot allocate mjData");
  mj_setConst(m, scratch.get());
}

// Scales (or restores) the feet's friction: with the ground (its contact pair) and with anything
// else they meet (the tunnel's walls).
void make_slippery(const SimModel& model, SimState& state, const body::Fault& fault,
                   double factor) {
  mjModel* m = new_model(model, state);
  const mjModel* original = model.mj.get();
  const double k = fault.recover ? 1.0 : factor;
  for (std::size_t leg : fault.legs) {
    const LegSlots& slots = model.legs[leg];
    if (slots.foot_pair < 0) {
      throw BadInput(
          "a slippery foot needs the foot's contact pair with the ground (a <pair> in "
          "the robot file's model, docs/robots.md)");
    }
    for (int t = 0; t < 2; ++t) {  // the two tangential directions
      m->pair_friction[5 * slots.foot_pair + t] =
          k * original->pair_friction[5 * slots.foot_pair + t];
    }
    m->geom_friction[3 * slots.foot_geom] = k * original->geom_friction[3 * slots.foot_geom];
  }
}

}  // namespace

void apply_fault_effect(const SimModel& model, SimState& state, const body::Fault& fault) {
  SensorCondition& sensor = state.faults.sensor;
  std::visit(Overloaded{
                 [](const body::LegFault&) {},
                 [&](const body::LockedJoint& k) { lock(model, state, fault, k); },
                 [&](const body::PassiveJoint&) {
                   set_servo(state, fault, JointCondition::Servo::passive);
                 },
                 [&](const body::WeakMotor& k) {
                   for (std::size_t leg : fault.legs) {
                     for (std::size_t j : joints_of(fault)) {
                       state.faults.joints[leg][j].torque_scale = fault.recover ? 1.0 : k.value;
                     }
                   }
                 },
                 [&](const body::ShortTibia& k) { shorten(model, state, fault, k.value); },
                 [&](const body::SlipperyFoot& k) { make_slippery(model, state, fault, k.value); },
                 [&](const body::ImuDrift& k) {
                   sensor.drift_deg_per_s = fault.recover ? 0.0 : k.value;
                   sensor.drift_deg = 0.0;
                 },
                 [&](const body::ImuNoise& k) {
                   sensor.noise_sigma_deg = fault.recover ? 0.0 : k.value;
                   sensor.noise_deg = 0.0;
                 },
             },
             fault.kind);
  // Every reshaping fault recovered: the shared model again, exactly as before.
  const body::FaultTimeline& in_force = state.faults.schedule.in_force();
  if (std::none_of(in_force.begin(), in_force.end(), reshapes)) {
    state.faults.model.reset();
  }
}

void advance_sensor(const SimModel& model, SimState& state) {
  SensorCondition& sensor = state.faults.sensor;
  sensor.drift_deg += sensor.drift_deg_per_s * model.control_dt;
  sensor.noise_deg = 0.0;
  if (sensor.noise_sigma_deg > 0.0) {
    sensor.noise_deg = std::normal_distribution<double>(0.0, sensor.noise_sigma_deg)(sensor.random);
  }
}

double sensed_yaw_deg(const SimModel& model, const SimState& state) {
  const SensorCondition& sensor = state.faults.sensor;
  return wrap_degrees(trunk_yaw_deg(model, state) + sensor.drift_deg + sensor.noise_deg);
}

}  // namespace multicpg::sim
