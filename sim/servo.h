// The compliant velocity servo of the lpzrobots AMOSII model (docs/robots.md "Servos",
// lpzrobots OneAxisServoVel), for one physics step.
//
// lpzrobots drives an ODE velocity motor: a constraint that reaches the commanded velocity
// unless that needs more than fmax, and then pushes with fmax. MuJoCo has no such constraint, so
// the servo is a torque from a velocity loop, clamped to fmax: Kv (commanded - actual velocity),
// Kv = ServoSpec::loop_gain (docs/robots.md).
//
// lpzrobots' gain K = maxVel / 2 belongs to its 0.1 s controller step; SimOptions scales it
// to the controller step used (sim/sim.h).
#pragma once

#include "robot/body.h"

namespace multicpg::sim {

// What one servo is: lpzrobots' constants (gain already scaled to the controller step)
// and its joint range.
struct ServoModel {
  robot::ServoSpec spec;
  double range;  // rad, max - min of the joint (scales the torque limit)
};

// Velocity the servo asks for: K (target - angle), capped at the maximum velocity and so that
// one physics step of length dt cannot overshoot the target.
double commanded_velocity(const robot::ServoSpec& spec, double error, double dt);

// Torque bound: P tanh(|2 error / range| + damp), small near the target (compliance).
double torque_limit(const ServoModel& servo, double error);

// Torque for one physics step of length dt (N m), within `limit_scale` times the torque bound (a
// weak motor's share, body/faults.h).
double servo_torque(const ServoModel& servo, double target, double angle, double velocity,
                    double dt, double limit_scale = 1.0);

}  // namespace multicpg::sim
