// What one measuring window says about the robot's course (docs/learning.md "Deviation"): the yaw
// change of the paper's criterion, and the path angle of its Table 1 (the trunk's displacement
// against the course: the heading at the window's start, or the line a steering reflex keeps),
// which sees a sideways crab that the yaw change cannot.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

namespace multicpg::body {

// Trunk pose at one instant: position in the ground plane (m) and yaw (deg, + = left). A body
// that senses no position (a real robot with an orientation sensor only, docs/hardware.md) reports
// x and y as NaN, never a made-up position.
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw_deg = 0.0;
  bool has_position() const { return std::isfinite(x) && std::isfinite(y); }
};

struct WindowMeasure {
  double yaw_deg = 0.0;    // wrap(yaw(end) - yaw(start)), + = left turn (paper §4.1)
  double path_deg = 0.0;   // atan2(lateral, forward) of the displacement, + = left (Table 1)
  double forward_m = 0.0;  // displacement along the course (see measure_window)
  double lateral_m = 0.0;  // and to its left
  // Mean swing cut of a steering reflex over the window, 0..1 (0 when none steers;
  // learning/steering.h).
  double steering_effort = 0.0;
  // The larger of |yaw_deg| and |path_deg|: what the robust criterion compares with the
  // threshold (a window holds when both are under it).
  double worst_deg() const;
};

// The one test of "held" for trials, windows and landscapes: a deviation strictly under the
// threshold (paper §3: learning stops when E < E_req).
inline bool holds(double deviation_deg, double threshold_deg) {
  return deviation_deg < threshold_deg;
}

// Below this forward displacement (m) the path angle is not defined (the robot stands or walks
// backwards): it is reported as +-90 deg, so a robot that does not advance never "holds". So is
// the path angle of a body that senses no position (Pose2::has_position; forward and lateral
// are then NaN).
inline constexpr double kMinForwardForPathM = 1e-3;

// `course_yaw_deg`: the direction of the course the robot keeps (a steering reflex's line,
// learning/steering.h), against which forward, lateral and the path angle are measured, as Table 1
// measures them against the tunnel's axis; without one, the heading at the window's start. A
// robot that holds its line with its body turned (a compensated crab) walks straight on the
// course, which the heading at the window's start would report as a constant path angle.
WindowMeasure measure_window(const Pose2& start, const Pose2& end,
                             std::optional<double> course_yaw_deg = std::nullopt);

// A walk measured from its poses at the window boundaries (the first where measuring began, then
// one per complete window) and its last pose: the whole displacement against the first heading,
// and each complete window's yaw change and path angle. Where no position is sensed the
// displacement and the path angles are NaN and +-90 deg (measure_window).
struct WalkMeasure {
  double distance_m = 0.0;
  double forward_m = 0.0;
  double lateral_m = 0.0;
  // wrap(yaw(end) - yaw(start)) of each complete window; + = left turn.
  std::vector<double> window_deviations_deg;
  std::vector<WindowMeasure> windows;
  double final_yaw_deg = 0.0;
};
WalkMeasure measure_walk(const std::vector<Pose2>& boundaries, const Pose2& last);

}  // namespace multicpg::body
