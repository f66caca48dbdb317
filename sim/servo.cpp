#include "sim/servo.h"

#include <algorithm>
#include <cmath>

namespace multicpg::sim {

double commanded_velocity(const robot::ServoSpec& spec, double error, double dt) {
  const double speed =
      std::min({spec.gain * std::abs(error), spec.max_velocity, std::abs(error) / dt});
  return std::copysign(speed, error);
}

double torque_limit(const ServoModel& servo, double error) {
  return servo.spec.power * std::tanh(std::abs(2.0 * error / servo.range) + servo.spec.damp);
}

double servo_torque(const ServoModel& servo, double target, double angle, double velocity,
                    double dt, double limit_scale) {
  const double error = target - angle;
  const double fmax = limit_scale * torque_limit(servo, error);
  const double wanted =
      servo.spec.loop_gain * (commanded_velocity(servo.spec, error, dt) - velocity);
  return std::clamp(wanted, -fmax, fmax);
}

}  // namespace multicpg::sim
