// The orientation reflex on the VRN's steering inputs (beyond the paper). docs/controller.md
// "VRN": the VRN acts like u0 * u1 with u1 = tanh(5 input3/4), so a side's steering
// input scales that side's TC swing from full (-1) to none (0). The paper names these inputs as
// the place for sensory feedback; this reflex feeds them the orientation sensor and odometry.
//
// A cascade, chosen with measurements (docs/learning.md): an outer loop turns the lateral offset
// from the course line (and its integral, which removes the steady offset that a sideways crab
// would leave) into a wanted heading; an inner loop cuts the swing of the side toward which the
// robot must turn in proportion to the heading error. A heading loop alone leaves the crab
// (-6 to -11 deg between heading and path); a loop on the path direction alone oscillates, since
// a steering change reaches the legs only through the delay lines (up to 126 steps).
#pragma once

#include <optional>

#include "body/body.h"
#include "body/deviation.h"
#include "common/limits.h"
#include "neural/drive.h"

namespace multicpg::learning {

struct SteeringParams {
  double heading_gain = 0.1;  // swing cut per degree of heading error (10 deg: full cut)
  // The outer loop's time constant at 3 cm/s is 180 / (pi v lateral_gain) = 32 s, several times
  // the delay lines' 126 steps (4.7 s); 20 deg/m (95 s) let the robot drift 7-11 deg off its line
  // for several windows. The integral time lateral_gain / integral_gain = 1000 steps: 600 (0.1)
  // swung the heading +-10 deg over a few windows. Chosen by held windows after learning
  // (docs/learning.md, "Does the final controller hold?").
  double lateral_gain = 60.0;   // wanted heading change per metre off the course line, deg/m
  double integral_gain = 0.06;  // and per metre-step of accumulated offset, deg/(m step)
  double max_heading_offset_deg = 30.0;  // the wanted heading stays this close to the course
  // Robust mode judges a window as failed when the reflex had to cut more than this share of a
  // side's swing on average: the periods must do most of the compensating, or the robot crawls
  // (measured: R1+R3+L2 gaits held only at a mean cut of 0.85 walk 0.6 cm/s; docs/learning.md).
  double max_effort = 0.75;
};

// Documented ranges: gains up to 1000 (a full cut at a thousandth of a degree), a heading offset
// up to a right angle, an effort share of a side's swing.
inline constexpr Limits<double> kSteeringGainLimits{0.0, 1000.0};
inline constexpr Limits<double> kHeadingOffsetLimits{0.1, 90.0};
inline constexpr Limits<double> kMaxEffortLimits{0.01, 1.0};

// Throws OptionError (key "heading_gain", ...) for a value outside its limits.
void validate(const SteeringParams& params);

// The line to keep: a point on it and its heading, set when the reflex starts (where the robot
// was walking), and the integral of the offset from it.
struct SteeringState {
  body::Pose2 course;
  double offset_integral_m_steps = 0.0;
  double last_cut = 0.0;  // swing cut of the last step, 0..1, + = right side cut (turn right)
};

SteeringState start_steering(const body::Pose2& course);
// The direction windows measure the path angle against (body::measure_window): the course line's
// when a reflex keeps one, else none (the heading at each window's start).
std::optional<double> course_yaw_deg(const std::optional<SteeringState>& steering);

// One reflex step: reads the pose, returns the drive inputs with turn_left / turn_right set.
neural::DriveInputs steer(const SteeringParams& params, SteeringState& state,
                          const body::Pose2& now, neural::DriveInputs drive);

// The one steering hook, before a body's step: the reflex reads what the body senses (its yaw
// sensor, its position) and sets the controller's steering inputs. Every run that steers (the
// online loop, the walk after learning, the tunnel, Python's Simulation and replays) steers
// through it. Returns the step's |swing cut| (0..1).
double steer_body(const SteeringParams& params, SteeringState& state, body::Body& body);

}  // namespace multicpg::learning
