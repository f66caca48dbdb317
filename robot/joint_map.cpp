#include "robot/joint_map.h"

#include <algorithm>
#include <numbers>

namespace multicpg::robot {
namespace {

constexpr double deg(double d) {
  return d * std::numbers::pi / 180.0;
}

// docs/robots.md "Joint angles": the servo maps m linearly onto its limits, so an angle is half the
// range times m plus the centre of the range.
constexpr double kTcOuterHalfRange = deg(70.0);   // front and hind legs
constexpr double kTcMiddleHalfRange = deg(60.0);  // middle legs
constexpr double kCtrHalfRange = deg(75.0);
constexpr double kFtiHalfRange = deg(55.0);  // (130 - 20) / 2
constexpr double kFtiCentre = deg(-75.0);    // flexion (130 + 20) / 2, extension positive

}  // namespace

AngleRange joint_limits(LegType type, Joint joint) {
  switch (joint) {
    case Joint::TC: {
      const double half = type == LegType::middle ? kTcMiddleHalfRange : kTcOuterHalfRange;
      return {-half, half};
    }
    case Joint::CTr:
      return {-kCtrHalfRange, kCtrHalfRange};
    case Joint::FTi:
      break;
  }
  return {kFtiCentre - kFtiHalfRange, kFtiCentre + kFtiHalfRange};
}

double joint_angle(LegType type, Joint joint, double command) {
  return joint_angle(joint_limits(type, joint), command);
}

double joint_angle(const AngleRange& r, double command) {
  const double m = std::clamp(command, -1.0, 1.0);
  return 0.5 * (r.lo + r.hi) + 0.5 * (r.hi - r.lo) * m;
}

double command_change(LegType type, Joint joint, double radians) {
  const AngleRange r = joint_limits(type, joint);
  return radians / (0.5 * (r.hi - r.lo));
}

}  // namespace multicpg::robot
