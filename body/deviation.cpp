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

}  // namespace multicpg::body
