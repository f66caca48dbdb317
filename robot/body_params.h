// The physical parameters of a robot that differ between the paper's simulator and the real
// AMOSII (paper §5, §6; docs/robots.md Body parameters): how a disabled leg is held, how high the
// body is carried, masses, friction, slip, joint compliance and the servos' limits. The defaults
// are the paper's simulator (lpzrobots AMOSII, the "paper-sim" model, robot/body_models.h); every
// value has a range a real AMOSII could have, checked by validate(). docs/robots.md "Body
// parameters" says how each one maps onto MuJoCo.
#pragma once

#include <cstddef>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.h"
#include "robot/morphology.h"

namespace multicpg::robot {

// Constant motor commands a disabled leg's joints hold, m in [-1, 1] (+ = forward,
// elevation, extension). The default is the authors': TC 0, CTr 0.7, FTi -0.7 (paper §4
// "constant values"; docs/controller.md "Disabled legs").
struct LegPosture {
  double tc = 0.0;
  double ctr = 0.7;
  double fti = -0.7;

  bool operator==(const LegPosture&) const = default;
};
inline constexpr LegPosture kReferenceDisabledPosture{};

// One leg held in another posture than the others when disabled. An unset joint keeps the
// all-legs value (the authors' real-robot test (docs/robots.md Body parameters), changes only R3's
// FTi to -0.55).
struct LegPostureOverride {
  std::string leg;  // "R3"
  std::optional<double> tc;
  std::optional<double> ctr;
  std::optional<double> fti;

  bool operator==(const LegPostureOverride&) const = default;
};

// --- Defaults: the paper's simulator, lpzrobots AMOSII v2 (docs/robots.md) ---
// Trunk 3.0 kg; each leg 4 x 0.19205 kg (shoulder, coxa, femur, tibia) + 0.040432 kg (foot).
inline constexpr double kSimTrunkMass = 3.0;        // kg
inline constexpr double kSimSegmentMass = 0.19205;  // kg
inline constexpr double kSimFootMass = 0.040432;    // kg
inline constexpr int kHexapodLegs = 6;
inline constexpr double kSimLegsMass = kHexapodLegs * (4.0 * kSimSegmentMass + kSimFootMass);
inline constexpr double kSimTotalMass = kSimTrunkMass + kSimLegsMass;  // 7.8518 kg
// docs/robots.md "Contacts and materials": mu = roughness product 3.0 x 0.8 for every robot-ground
// pair.
inline constexpr double kSimFriction = 2.4;
// MuJoCo's own tangential creep at a foot of the default hexapod, m/s per N of tangential force
// on one contact, at impratio 1 (docs/robots.md "Body parameters": 0.00510 for pushes of 3-24 N,
// tests/test_body.cpp). The slip parameter is mapped onto MuJoCo as impratio = this / slip, so
// this value is today's contact, unchanged.
inline constexpr double kMujocoFootSlip = 0.0051;  // m/s per N
// docs/robots.md "Servos": coxaPower = 10 (1.962 / (0.035 2.2)) 0.035 3.0 and
// maxVel = 1.7 1.961 pi.
inline constexpr double kSimServoTorque = 10.0 * (1.962 / (0.035 * 2.2)) * 0.035 * 3.0;  // N m
inline constexpr double kSimServoSpeed = 1.7 * 1.961 * std::numbers::pi;                 // rad/s

// --- Ranges a real AMOSII could have (docs/robots.md "Body parameters") ---
// Total mass: the real robot's 5.758 kg (paper §5, docs/robots.md "Geometry and masses") without
// and with its batteries and sensors, up to past the simulator's 7.85 kg.
inline constexpr Limits<double> kTotalMassLimits{4.5, 9.0};
// Trunk: the real 2.2 kg to the simulator's 3.0 kg, with margin either side.
inline constexpr Limits<double> kTrunkMassLimits{1.5, 4.0};
// The six legs together: the real robot's 3.56 kg less 15 %. Lighter legs have feet so light
// that the sprung foot's 38 N preload drives it through its stop (measured: legs of 2.5 kg
// blow up in the first physics step, docs/robots.md "Body parameters").
inline constexpr double kMinLegsMass = 3.0;  // kg
// Coulomb friction: rubber on a smooth floor (~0.5) to lpzrobots' 2.4 and a little past.
inline constexpr Limits<double> kFrictionLimits{0.2, 3.0};
// Tangential slip, m/s per N: from 10x harder than MuJoCo's own to 5x lpzrobots' 0.01.
inline constexpr Limits<double> kSlipLimits{0.0005, 0.05};
// Series compliance of each joint's passive coupling, rad per N m (0 = rigid): up to 0.2,
// i.e. 10 deg of give under 1 N m.
inline constexpr Limits<double> kJointComplianceLimits{0.0, 0.2};
// Torsional friction (m, moment per N of normal force) of a rubber foot: up to the foot's radius.
inline constexpr Limits<double> kTorsionalFrictionLimits{0.0, 0.015};
// Rolling friction (m): up to a few mm of rubber deformation.
inline constexpr Limits<double> kRollingFrictionLimits{0.0, 0.005};
// Servo stall torque: hobby servos of the AMOSII's class give ~3 N m; the simulator's 26.75.
inline constexpr Limits<double> kServoTorqueLimits{2.0, 30.0};
// Servo no-load speed: 3 rad/s to past the simulator's 10.47 rad/s.
inline constexpr Limits<double> kServoSpeedLimits{3.0, 12.0};
// Body lift (docs/robots.md Body parameters; the authors' real robot: 5 deg) either way.
inline constexpr Limits<double> kLiftBodyLimits{-10.0, 15.0};
// Disabled-leg posture: any command a joint takes.
inline constexpr Limits<double> kPostureLimits{-1.0, 1.0};

struct BodyParams {
  // The posture a disabled leg holds (all legs), and legs that hold another.
  LegPosture disabled_posture = kReferenceDisabledPosture;
  std::vector<LegPostureOverride> leg_postures;
  // Degrees taken off the CTr window and added to the FTi window of every walking leg, so the
  // legs push the body up (docs/robots.md Body parameters; the authors' lift_body_up: 5).
  double lift_body = 0.0;
  // Hexapod masses (kg); the legs share total - trunk as the simulator does. Other robots keep
  // the trunk's density and the per-leg mass.
  double total_mass = kSimTotalMass;
  double trunk_mass = kSimTrunkMass;
  // Coulomb friction of the feet (and tibiae) and of the trunk against the ground.
  double foot_friction = kSimFriction;
  double trunk_friction = kSimFriction;
  // Force-dependent tangential slip of every contact, m/s per N (docs/robots.md "Slip").
  double slip = kMujocoFootSlip;
  // Compliance of the passive coupling between each servo and its segment, rad per N m.
  double joint_compliance = 0.0;
  // Torsional and rolling friction of the ground contacts (m); 0 = none.
  double torsional_friction = 0.0;
  double rolling_friction = 0.0;
  // Every leg servo's stall torque (N m) and no-load speed (rad/s).
  double servo_torque = kSimServoTorque;
  double servo_speed = kSimServoSpeed;

  bool operator==(const BodyParams&) const = default;
};

// One number of BodyParams named by its key ("slip", or a joint of the all-legs posture:
// "disabled_posture.ctr"), with its documented range: what a search over the body (the
// calibration, experiments/calibration.h) reads and writes.
struct BodyParams;
struct NumberParam {
  std::string_view key;
  Limits<double> limits;
  double (*get)(const BodyParams&);
  void (*set)(BodyParams&, double);
};
// Every number of BodyParams, in the struct's order (leg_postures, a list, is not one).
std::span<const NumberParam> number_params();
// Throws BadInput naming the known keys for an unknown one.
const NumberParam& number_param(std::string_view key);

// Throws OptionError ("total_mass", "leg_postures[0].fti", ...) for a value outside its range or
// a trunk that leaves the legs less than kMinLegsMass.
void validate(const BodyParams& params);

// The posture each leg of `morph` holds when disabled, in morphology order. Throws OptionError
// ("leg_postures[1].leg") for a leg the robot does not have or one named twice.
std::vector<LegPosture> disabled_postures(const BodyParams& params, const Morphology& morph);

}  // namespace multicpg::robot
