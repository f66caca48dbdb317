#include "body/deviation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"

namespace multicpg::body {

double WindowMeasure::worst_deg() const {
  return std::max(std::abs(yaw_deg), std::abs(path_deg));
}

WindowMeasure measure_window(const Pose2& start, const Pose2& end,
                             std::optional<double> course_yaw_deg) {
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
  WindowMeasure m;
  m.yaw_deg = wrap_degrees(end.yaw_deg - start.yaw_deg);
  const double heading = course_yaw_deg.value_or(start.yaw_deg) / kDegPerRad;
  const double dx = end.x - start.x;
  const double dy = end.y - start.y;
  m.forward_m = dx * std::cos(heading) + dy * std::sin(heading);
  m.lateral_m = -dx * std::sin(heading) + dy * std::cos(heading);
  if (!(m.forward_m >= kMinForwardForPathM)) {  // NaN too: no position sensed
    m.path_deg = m.lateral_m < 0.0 ? -90.0 : 90.0;
  } else {
    m.path_deg = std::atan2(m.lateral_m, m.forward_m) * kDegPerRad;
  }
  return m;
}

WalkMeasure measure_walk(const std::vector<Pose2>& boundaries, const Pose2& last) {
  WalkMeasure out;
  const WindowMeasure whole = measure_window(boundaries.front(), last);
  out.distance_m = std::hypot(whole.forward_m, whole.lateral_m);
  out.forward_m = whole.forward_m;
  out.lateral_m = whole.lateral_m;
  for (std::size_t k = 1; k < boundaries.size(); ++k) {
    out.window_deviations_deg.push_back(
        wrap_degrees(boundaries[k].yaw_deg - boundaries[k - 1].yaw_deg));
    out.windows.push_back(measure_window(boundaries[k - 1], boundaries[k]));
  }
  out.final_yaw_deg = last.yaw_deg;
  return out;
}

}  // namespace multicpg::body
