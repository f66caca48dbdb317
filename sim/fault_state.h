// A run's faults as state (part of sim::SimState): what has come and what is in force (its
// FaultSchedule, the one book of them), and what they do to the physics and the sensors
// (sim/fault_effects.h changes that): each joint's servo (driven, locked or off, and its torque
// limit), the run's own MuJoCo model while a fault reshapes the robot, and the yaw sensor's error.
#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <memory>
#include <random>
#include <vector>

#include "body/events.h"
#include "robot/morphology.h"

namespace multicpg::sim {

struct JointCondition {
  enum class Servo {
    driven,   // the servo law (sim/servo.h)
    locked,   // seized: no torque, the joint held at its lock angle by its limits
    passive,  // no torque: the joint swings freely
  };
  Servo servo = Servo::driven;
  double torque_scale = 1.0;  // a weak motor's share of its torque limit
};

// The yaw sensor's error: a drift that grows from its fault on, and noise drawn once per step.
struct SensorCondition {
  double drift_deg_per_s = 0.0;
  double drift_deg = 0.0;  // accumulated since the drift started
  double noise_sigma_deg = 0.0;
  double noise_deg = 0.0;  // this step's draw
  std::mt19937_64 random;  // seeded with the run's seed (body::StartSpec::seed)
};

struct FaultState {
  // The run's timeline, what of it has come and the faults in force (sim::Stepper applies them).
  body::FaultSchedule schedule;
  std::vector<std::array<JointCondition, robot::kJointsPerLeg>> joints;  // per leg
  // While a fault reshapes the robot (a locked joint's range, a short tibia, a slippery foot):
  // the run's own model, never changed once made (a change makes a new one), so a film may draw
  // from it while the run goes on. Null: the shared model.
  std::shared_ptr<const mjModel> model;
  SensorCondition sensor;
};

}  // namespace multicpg::sim
