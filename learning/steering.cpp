#include "learning/steering.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/errors.h"

namespace multicpg::learning {
namespace {

// The VRN's steering weight (docs/controller.md "VRN"): u1 = tanh(5 input).
constexpr double kSteerWeight = 5.0;
// Forward walking: input3 = input4 = -1 (docs/controller.md "Drive inputs").
constexpr double kForward = -1.0;

// The steering input that leaves `amplitude` (0..1) of a side's swing: u1 = -amplitude.
double input_for_amplitude(double amplitude) {
  const double full = std::tanh(kSteerWeight);  // what input -1 gives
  return -std::atanh(std::min(amplitude, full)) / kSteerWeight;
}

}  // namespace

void validate(const SteeringParams& p) {
  require_in("heading_gain", p.heading_gain, kSteeringGainLimits);
  require_in("lateral_gain", p.lateral_gain, kSteeringGainLimits);
  require_in("integral_gain", p.integral_gain, kSteeringGainLimits);
  require_in("max_heading_offset_deg", p.max_heading_offset_deg, kHeadingOffsetLimits);
  require_in("max_effort", p.max_effort, kMaxEffortLimits);
}

SteeringState start_steering(const body::Pose2& course) {
  return SteeringState{course, 0.0, 0.0};
}

std::optional<double> course_yaw_deg(const std::optional<SteeringState>& steering) {
  if (!steering) return std::nullopt;
  return steering->course.yaw_deg;
}

neural::DriveInputs steer(const SteeringParams& p, SteeringState& s, const body::Pose2& now,
                          neural::DriveInputs drive) {
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  const double heading = s.course.yaw_deg * kRadPerDeg;
  const double offset_m =
      -(now.x - s.course.x) * std::sin(heading) + (now.y - s.course.y) * std::cos(heading);
  s.offset_integral_m_steps += offset_m;
  const double wanted =
      std::clamp(-(p.lateral_gain * offset_m + p.integral_gain * s.offset_integral_m_steps),
                 -p.max_heading_offset_deg, p.max_heading_offset_deg);
  const double error = wrap_degrees(now.yaw_deg - s.course.yaw_deg) - wanted;  // + = too far left
  const double cut = std::clamp(p.heading_gain * error, -1.0, 1.0);
  s.last_cut = cut;
  const double reduced = input_for_amplitude(1.0 - std::abs(cut));
  drive.turn_left = cut < 0.0 ? reduced : kForward;   // turn left: the left side swings less
  drive.turn_right = cut > 0.0 ? reduced : kForward;  // turn right: the right side swings less
  return drive;
}

double steer_body(const SteeringParams& params, SteeringState& state, body::Body& body) {
  neural::ControllerState& c = body.controller();
  c.drive = steer(params, state, body.pose(), c.drive);
  return std::abs(state.last_cut);
}

}  // namespace multicpg::learning
