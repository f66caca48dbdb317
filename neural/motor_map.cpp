#include "neural/motor_map.h"

#include <numbers>

#include "robot/joint_map.h"

namespace multicpg::neural {
namespace {

using robot::LegType;
using robot::RobotKind;

// docs/controller.md "Motor mapping and joint windows": ranges of the motor neurons (a, b) and
// command windows [lo, hi].
constexpr double kTcPreRange = 0.91;
constexpr LinearMap kCtrMap{-1.0, 0.96, 0.5985, 0.9975};   // 45..75 deg elevation
constexpr LinearMap kFtiMap{-1.0, 1.0, -1.0024, -0.8204};  // 130..120 deg flexion

struct Window {
  double lo, hi;
};

Window tc_window(RobotKind kind, LegType type) {
  if (kind == RobotKind::quadruped) {
    // AmosFour (docs/controller.md "Motor mapping and joint windows"): front pair -10..+40 deg,
    // hind pair -40..+10 deg.
    return type == LegType::hind ? Window{-0.572, 0.143} : Window{-0.167, 0.668};
  }
  switch (type) {
    case LegType::front:
      return {0.0, 0.715};  // 0..+50 deg
    case LegType::hind:
      return {-0.858, -0.143};  // -60..-10 deg
    case LegType::middle:
      break;
  }
  return {-0.501, 0.334};  // -30..+20 deg
}

}  // namespace

LegMotorMap leg_motor_map(RobotKind kind, LegType type, double lift_body_deg) {
  const Window w = tc_window(kind, type);
  const double lift = lift_body_deg * std::numbers::pi / 180.0;
  LinearMap ctr = kCtrMap;
  const double ctr_shift = robot::command_change(type, robot::Joint::CTr, -lift);
  ctr.to_lo += ctr_shift;
  ctr.to_hi += ctr_shift;
  LinearMap fti = kFtiMap;
  const double fti_shift = robot::command_change(type, robot::Joint::FTi, lift);
  fti.to_lo += fti_shift;
  fti.to_hi += fti_shift;
  return LegMotorMap{LinearMap{-kTcPreRange, kTcPreRange, w.lo, w.hi}, ctr, fti};
}

}  // namespace multicpg::neural
