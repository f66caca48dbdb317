#include "body/body.h"

#include <limits>

namespace multicpg::body {

Pose2 Senses::pose() const {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  return {position ? position->x : kNone, position ? position->y : kNone, yaw_deg};
}

}  // namespace multicpg::body
