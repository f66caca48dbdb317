// Linear maps from pre-motor signals to motor commands m in [-1, 1] (docs/controller.md "Motor
// mapping and joint windows", docs/robots.md Joint angles).
#pragma once

#include "neural/motor_neurons.h"
#include "robot/morphology.h"

namespace multicpg::neural {

// Maps [from_lo, from_hi] linearly onto [to_lo, to_hi].
struct LinearMap {
  double from_lo, from_hi, to_lo, to_hi;
  double operator()(double v) const {
    return (v - from_lo) / (from_hi - from_lo) * (to_hi - to_lo) + to_lo;
  }
};

// One leg's commands, m in [-1, 1]: + = forward (TC), elevation (CTr), extension (FTi).
struct MotorCommands {
  double tc = 0.0;
  double ctr = 0.0;
  double fti = 0.0;
};

// Maps of one leg (docs/controller.md "Motor mapping and joint windows").
struct LegMotorMap {
  LinearMap tc, ctr, fti;
  MotorCommands operator()(const MotorNeuronOutputs& pre) const {
    return {tc(pre.tc), ctr(pre.ctr), fti(pre.fti)};
  }
};

// The TC window depends on the robot and the leg design; CTr and FTi windows are shared. A body
// lift of `lift_body_deg` takes that many degrees off the CTr window and adds them to the FTi
// window (docs/robots.md Body parameters, the authors' real-robot lift_body_up), so the legs
// stand taller.
LegMotorMap leg_motor_map(robot::RobotKind kind, robot::LegType type, double lift_body_deg = 0.0);

}  // namespace multicpg::neural
