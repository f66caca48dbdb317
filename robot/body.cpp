#include "robot/body.h"

#include <numbers>

namespace multicpg::robot {
namespace {

constexpr double kPi = std::numbers::pi;

// --- Trunk (docs/robots.md "Trunk", lpzrobots AmosII v2 at scale 1) ---
constexpr double kTrunkLength = 0.43;         // hexapod, m
constexpr double kTrunkWidth = 0.07;          // m
constexpr double kTrunkHeight = 0.065;        // m
constexpr double kFrontLength = 0.12;         // front box, m
constexpr double kTrunkMass = kSimTrunkMass;  // both boxes, kg (density 3.0 / (0.43 0.07 0.065))
constexpr double kTrunkDensity = kTrunkMass / kTrunkLength;  // kg per m of trunk length
constexpr double kBackboneLimit = kPi / 4.0;                 // +-45 deg

// --- Leg roots (docs/robots.md "Leg roots") ---
constexpr double kFrontLegX = 0.175;       // m
constexpr double kLegDistFrontMid = 0.15;  // legdist2: front to middle, m
constexpr double kLegDistMidHind = 0.19;   // legdist1: middle to hind, m
constexpr double kRearOverhang = 0.05;     // trunk rear end behind the hind legs: 0.215 - 0.165
// Quadruped AmosFour (docs/robots.md "Trunk"): one 0.31 m box centred at the origin.
constexpr double kQuadFrontLegX = 0.09;
constexpr double kQuadHindLegX = -0.10;

// --- Masses (docs/robots.md "Mass budget") ---
// Total 5.758 / 2.2 x trunk mass = 7.8518 kg; the 4.8518 kg of legs are shared as
// shoulder = coxa = femur = tibia = 4.8518 / 24 x 19/20 and foot = 4.8518 / 6 / 20.
constexpr double kSegmentMass = kSimSegmentMass;  // kg
constexpr double kFootMass = kSimFootMass;        // kg

// --- Segments (docs/robots.md "Segments": lpzrobots Capsule(radius, cylinder length)) ---
constexpr Capsule kShoulder{0.0129, 0.045, kSegmentMass};
constexpr Capsule kCoxa{0.0172, 0.035, kSegmentMass};
constexpr Capsule kFemur{0.0129, 0.06, kSegmentMass};
constexpr Capsule kTibia{0.013, 0.087, kSegmentMass};
constexpr Capsule kFoot{0.015, 0.013, kFootMass};

// --- Servos (docs/robots.md "Servos") ---
constexpr double kMaxVelocity = kSimServoSpeed;    // 10.47 rad/s
constexpr double kServoGain = kMaxVelocity / 2.0;  // K = 5.2366 1/s (at the 0.1 s step)
// coxaPower = 10 (1.962 / (0.035 2.2)) 0.035 3.0 = 26.75 N m; backPower is 30/10 of it. The
// backbone is held at 0 and keeps its power whatever the leg servos are (BodyParams).
constexpr double kLegPower = kSimServoTorque;
constexpr double kBackPower = 3.0 * kLegPower;  // 80.26 N m
constexpr double kFtiDamp = 0.01;
// Gearbox rotor inertia reflected to the joint (lpzrobots' ODE motors are constraints and
// need none): a geared hobby servo (~200:1, rotor ~2.5e-7 kg m^2) reflects about 0.01 kg m^2.
// It also keeps the explicit velocity loop stable at the physics step: Kv h / I < 2 for the
// lightest joint (FTi, I = 0.011 kg m^2; docs/robots.md).
constexpr double kServoArmature = 0.01;  // kg m^2

// --- Foot (docs/robots.md "Foot spring") ---
// footPower = (350 0.08 / 2.2) 3.0 / 0.08 = 477.3 N/m, KD 0.05, stops 2 mm apart, preload 0.08 m.
constexpr FootSpring kFootSpring{(350.0 * 0.08 / 2.2) * kTrunkMass / 0.08, 0.05, 0.002, 0.08};
constexpr double kContactSensorRadius = 0.01515;  // docs/robots.md "Sensors, start, settling"
// Passive coupling of each joint (paper §5: "a passive coupling is installed at each joint"): a
// Kelvin-Voigt element whose damping is its stiffness times this relaxation time, a rubber-like
// loss (docs/robots.md "Body parameters": the walk hardly depends on it).
constexpr double kCouplingRelaxation = 0.005;  // s

// The velocity loop's gain is the servo's stall torque over its no-load speed (ServoSpec).
ServoSpec servo(double power, double damp, double max_velocity = kMaxVelocity) {
  return {.max_velocity = max_velocity,
          .gain = kServoGain,
          .power = power,
          .damp = damp,
          .armature = kServoArmature,
          .loop_gain = power / max_velocity};
}

RobotBody common_body(RobotKind kind) {
  RobotBody b;
  b.morphology = morphology(kind);
  b.trunk_width = kTrunkWidth;
  b.trunk_height = kTrunkHeight;
  b.backbone_x = 0.0;
  b.backbone_limit = kBackboneLimit;
  b.backbone_servo = servo(kBackPower, 0.0);
  b.leg_root_y = kTrunkWidth / 2.0;   // legs leave the trunk sides...
  b.leg_root_z = kTrunkHeight / 2.0;  // ...at the height of its top (shoulderHeight 6.5 cm)
  b.segments = {kShoulder, kCoxa, kFemur, kTibia, kFoot};
  b.tc_servo = servo(kLegPower, 0.0);
  b.ctr_servo = servo(kLegPower, 0.0);
  b.fti_servo = servo(kLegPower, kFtiDamp);
  b.foot = kFootSpring;
  b.contact_sensor_radius = kContactSensorRadius;
  b.foot_friction = kSimFriction;
  b.trunk_friction = kSimFriction;
  b.slip = kMujocoFootSlip;
  b.torsional_friction = 0.0;
  b.rolling_friction = 0.0;
  b.joint_compliance = 0.0;
  b.coupling_damping = 0.0;
  b.yaw_part = 0;
  return b;
}

// Hexapod and octopod: a front box on the backbone hinge and a centre box; the octopod inserts
// one more middle leg, legdist2 behind the first, and lengthens the centre box to match.
RobotBody amos_body(RobotKind kind) {
  RobotBody b = common_body(kind);
  const Morphology& morph = b.morphology;
  const int n = morph.legs_per_side;
  std::vector<double> leg_x;
  for (int pos = 0; pos < n - 1; ++pos) leg_x.push_back(kFrontLegX - pos * kLegDistFrontMid);
  leg_x.push_back(leg_x.back() - kLegDistMidHind);

  const double front_end = kTrunkLength / 2.0;
  const double joint_x = front_end - kFrontLength;
  const double rear_end = leg_x.back() - kRearOverhang;
  const double centre_length = joint_x - rear_end;
  b.trunk = {
      {"trunk", 0.5 * (joint_x + rear_end), centre_length, kTrunkDensity * centre_length},
      {"front_trunk", front_end - kFrontLength / 2.0, kFrontLength, kTrunkDensity * kFrontLength},
  };
  b.backbone_x = joint_x;
  b.yaw_part = 1;
  for (const Leg& leg : morph.legs) {
    const std::size_t part = leg.position == 0 ? 1 : 0;  // front legs hang on the front box
    b.mounts.push_back({part, leg_x[leg.position], leg.side == Side::left ? 1.0 : -1.0});
  }
  return b;
}

// AmosFour (docs/robots.md "Trunk"): the hexapod's centre box alone, no backbone, two leg pairs.
RobotBody quadruped_body() {
  RobotBody b = common_body(RobotKind::quadruped);
  const double length = kTrunkLength - kFrontLength;
  b.trunk = {{"trunk", 0.0, length, kTrunkDensity * length}};
  for (const Leg& leg : b.morphology.legs) {
    const double x = leg.position == 0 ? kQuadFrontLegX : kQuadHindLegX;
    b.mounts.push_back({0, x, leg.side == Side::left ? 1.0 : -1.0});
  }
  return b;
}

}  // namespace

const RobotBody& robot_body(RobotKind kind) {
  static const std::array<RobotBody, kRobotKinds.size()> bodies{
      amos_body(RobotKind::hexapod), quadruped_body(), amos_body(RobotKind::octopod)};
  return bodies[robot_index(kind)];
}

RobotBody robot_body(RobotKind kind, const BodyParams& params) {
  RobotBody b = robot_body(kind);
  // Ratios are exactly 1 at the defaults, so the paper-sim body is today's to the bit.
  const double trunk_scale = params.trunk_mass / kSimTrunkMass;
  for (TrunkBox& box : b.trunk) box.mass *= trunk_scale;
  const double leg_scale =
      (params.total_mass - params.trunk_mass) / (kSimTotalMass - kSimTrunkMass);
  for (Capsule* c : {&b.segments.shoulder, &b.segments.coxa, &b.segments.femur, &b.segments.tibia,
                     &b.segments.foot}) {
    c->mass *= leg_scale;
  }
  b.tc_servo = servo(params.servo_torque, 0.0, params.servo_speed);
  b.ctr_servo = servo(params.servo_torque, 0.0, params.servo_speed);
  b.fti_servo = servo(params.servo_torque, kFtiDamp, params.servo_speed);
  b.foot_friction = params.foot_friction;
  b.trunk_friction = params.trunk_friction;
  b.slip = params.slip;
  b.torsional_friction = params.torsional_friction;
  b.rolling_friction = params.rolling_friction;
  b.joint_compliance = params.joint_compliance;
  b.coupling_damping =
      params.joint_compliance > 0.0 ? kCouplingRelaxation / params.joint_compliance : 0.0;
  return b;
}

double total_mass(const RobotBody& body) {
  double mass = 0.0;
  for (const TrunkBox& box : body.trunk) mass += box.mass;
  const LegSegments& s = body.segments;
  const double leg = s.shoulder.mass + s.coxa.mass + s.femur.mass + s.tibia.mass + s.foot.mass;
  return mass + leg * static_cast<double>(body.mounts.size());
}

}  // namespace multicpg::robot
