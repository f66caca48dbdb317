#include "robot/mjcf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "robot/joint_map.h"

namespace multicpg::robot {
namespace {

// --- World and contact (docs/robots.md "Contacts and materials") ---
// Semi-implicit Euler, MuJoCo's default (docs/robots.md "Integrator and time steps"): converged at
// the default physics step (docs/robots.md); contacts keep MuJoCo's default softness and friction
// impedance.
constexpr const char* kIntegrator = "Euler";
// Elliptic friction cones: with mu = 2.4 the pyramidal approximation does not hold the feet (the
// hexapod does not advance; docs/robots.md).
constexpr const char* kCone = "elliptic";
// Torsional and rolling friction when the body has none: MuJoCo's defaults, inert at condim 3.
constexpr double kTorsionalFriction = 0.005;
constexpr double kRollingFriction = 0.0001;
// Contact dimensions: tangential friction; with torsional; with torsional and rolling.
constexpr int kCondimSliding = 3;
constexpr int kCondimTorsional = 4;
constexpr int kCondimRolling = 6;
// Contacts (docs/robots.md "Contacts and materials"). The ground touches only the trunk
// boxes and the lower legs (tibia and foot): explicit contact pairs, which skip MuJoCo's broad
// phase. In 102 walks (every robot, every period, up to three disabled legs) only feet and trunk
// boxes touched it. The walls of the tunnel may meet any part, so they collide dynamically: the
// world class (walls) with the robot class, the robot's parts not with each other (their TC windows
// keep neighbouring legs apart). The ground is in neither class.
constexpr const char* kFlatCollision = "predefined";  // the pairs alone
constexpr const char* kTunnelCollision = "all";       // the pairs and the dynamic wall contacts
constexpr int kWorldClass = 1;
constexpr int kRobotClass = 2;
constexpr const char* kGroundLegParts[] = {"_tibia", "_foot"};
// Sparse constraint Jacobians: each row touches one leg's chain and the trunk, a third of the 31
// (hexapod) degrees of freedom; MuJoCo's "auto" picks dense below 60. Same solution, ~15 % less
// work per step (docs/robots.md "Cost of the physics").
constexpr const char* kJacobian = "sparse";
// Start clearance between the lowest foot and the ground, so the robot settles onto its feet.
constexpr double kStartClearance = 0.001;  // m
// Corridor walls (paper §5): tall and thick enough to stop the trunk and legs.
constexpr double kWallHeight = 0.3;      // m
constexpr double kWallThickness = 0.02;  // m
constexpr const char* kWallRgba = ".6 .55 .5 .5";
// Rough ground's heightfield file (beside the MJCF; MuJoCo's binary heightfield format) and the
// slab under its surface, deep enough that no foot reaches through.
constexpr const char* kHeightfieldFile = "terrain.hfield";
constexpr double kHeightfieldBase = 0.05;  // m

struct Vec3 {
  double x, y, z;
};

// Distance from the FTi joint to the centre of the foot capsule at its outer stop: the tibia
// cylinder, both tibia caps and the spring travel, less the foot radius (lpzrobots AmosII).
double foot_centre_distance(const RobotBody& body) {
  const LegSegments& s = body.segments;
  return s.tibia.length + 2.0 * s.tibia.radius + body.foot.travel - s.foot.radius;
}

class Writer {
 public:
  void line(int depth, const std::string& text) {
    out_ << std::string(2 * static_cast<std::size_t>(depth), ' ') << text << "\n";
  }

  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

std::string vec(const Vec3& v) {
  return num(v.x) + " " + num(v.y) + " " + num(v.z);
}

std::string capsule(const std::string& name, const Vec3& from, const Vec3& to, const Capsule& c) {
  return "<geom name=\"" + name + "\" type=\"capsule\" fromto=\"" + vec(from) + " " + vec(to) +
         "\" size=\"" + num(c.radius) + "\" mass=\"" + num(c.mass) + "\"/>";
}

std::string hinge(const std::string& name, const Vec3& axis, const AngleRange& range,
                  const ServoSpec& servo) {
  return "<joint name=\"" + name + "\" type=\"hinge\" axis=\"" + vec(axis) + "\" range=\"" +
         num(range.lo) + " " + num(range.hi) + "\" armature=\"" + num(servo.armature) + "\"/>";
}

// The passive coupling behind a servo (RobotBody::joint_compliance): a spring hinge on the servo's
// axis, so the segment turns by the servo's angle plus the coupling's give.
std::string coupling(const RobotBody& body, const std::string& servo_joint, const Vec3& axis) {
  return "<joint name=\"" + coupling_joint(servo_joint) + "\" type=\"hinge\" axis=\"" + vec(axis) +
         "\" limited=\"false\" stiffness=\"" + num(1.0 / body.joint_compliance) + "\" damping=\"" +
         num(body.coupling_damping) + "\"/>";
}

// The joints of the MJCF in document order, for the keyframe.
struct Emitted {
  std::vector<double> qpos;
  std::vector<std::pair<std::string, const ServoSpec*>> servos;  // actuated joints
  std::vector<std::string> feet;
};

// One leg, from its shoulder (a geom of the trunk body) to its foot. `origin_x` is where the
// frame of the trunk part it hangs on sits in the trunk frame.
void write_leg(Writer& w, int depth, const RobotBody& body, std::size_t index, double origin_x,
               const LegAngles& start, Emitted& emitted) {
  const Leg& leg = body.morphology.legs[index];
  const LegMount& mount = body.mounts[index];
  const LegSegments& seg = body.segments;
  const double s = mount.side;  // the leg points along s * y
  const std::string& n = leg.name;
  const Vec3 root{mount.x - origin_x, s * body.leg_root_y, body.leg_root_z};
  const Vec3 tc{root.x, root.y + s * seg.shoulder.length, root.z};

  // Axes chosen so positive angles are forward (TC), elevation (CTr), extension (FTi) on both
  // sides (joint_map.h): for a right leg (s = -1) forward is +z rotation, up is -x rotation.
  const Vec3 tc_axis{0.0, 0.0, -s};
  const Vec3 lift_axis{s, 0.0, 0.0};

  const bool compliant = body.joint_compliance > 0.0;
  // A servo joint, and its coupling when the joints are compliant.
  const auto servo_joint = [&](int d, Joint joint, const Vec3& axis, const ServoSpec& spec) {
    const std::string name = n + "_" + std::string(to_string(joint));
    w.line(d, hinge(name, axis, joint_limits(leg.type, joint), spec));
    if (compliant) w.line(d, coupling(body, name, axis));
  };

  w.line(depth, capsule(n + "_shoulder", root, tc, seg.shoulder));
  w.line(depth, "<body name=\"" + n + "_coxa\" pos=\"" + vec(tc) + "\">");
  servo_joint(depth + 1, Joint::TC, tc_axis, body.tc_servo);
  w.line(depth + 1, capsule(n + "_coxa", {0, 0, 0}, {0, s * seg.coxa.length, 0}, seg.coxa));
  w.line(depth + 1, "<body name=\"" + n + "_femur\" pos=\"0 " + num(s * seg.coxa.length) + " 0\">");
  servo_joint(depth + 2, Joint::CTr, lift_axis, body.ctr_servo);
  w.line(depth + 2, capsule(n + "_femur", {0, 0, 0}, {0, s * seg.femur.length, 0}, seg.femur));
  w.line(depth + 2,
         "<body name=\"" + n + "_tibia\" pos=\"0 " + num(s * seg.femur.length) + " 0\">");
  servo_joint(depth + 3, Joint::FTi, lift_axis, body.fti_servo);
  w.line(depth + 3, capsule(n + "_tibia", {0, 0, 0}, {0, s * seg.tibia.length, 0}, seg.tibia));

  // Foot: slides inward along the tibia (positive = compressed), pushed out against its stop
  // by a spring preloaded by preload_length (docs/robots.md "Foot spring").
  const double half = seg.foot.length / 2.0;
  w.line(depth + 3,
         "<body name=\"" + n + "_foot\" pos=\"0 " + num(s * foot_centre_distance(body)) + " 0\">");
  w.line(depth + 4, "<joint name=\"" + n + "_foot_spring\" type=\"slide\" axis=\"0 " + num(-s) +
                        " 0\" range=\"0 " + num(body.foot.travel) + "\" stiffness=\"" +
                        num(body.foot.stiffness) + "\" springref=\"" +
                        num(-body.foot.preload_length) + "\" damping=\"" + num(body.foot.damping) +
                        "\"/>");
  w.line(depth + 4, capsule(n + "_foot", {0, -s * half, 0}, {0, s * half, 0}, seg.foot));
  // Contact sensor sphere around the foot's outer cap (docs/robots.md "Sensors, start, settling").
  w.line(depth + 4, "<site name=\"" + n + "_foot\" type=\"sphere\" pos=\"0 " + num(s * half) +
                        " 0\" size=\"" + num(body.contact_sensor_radius) + "\"/>");
  w.line(depth + 3, "</body>");
  w.line(depth + 2, "</body>");
  w.line(depth + 1, "</body>");
  w.line(depth, "</body>");

  for (std::size_t j = 0; j < kJointsPerLeg; ++j) {
    emitted.qpos.push_back(start[j]);
    if (compliant) emitted.qpos.push_back(0.0);  // the coupling at rest
  }
  emitted.qpos.push_back(0.0);  // the foot spring
  emitted.servos.emplace_back(n + "_TC", &body.tc_servo);
  emitted.servos.emplace_back(n + "_CTr", &body.ctr_servo);
  emitted.servos.emplace_back(n + "_FTi", &body.fti_servo);
  emitted.feet.push_back(n + "_foot");
}

void write_legs_of(Writer& w, int depth, const RobotBody& body, std::size_t part,
                   const MjcfOptions& options, Emitted& emitted) {
  const double origin_x = part == 0 ? 0.0 : body.backbone_x;
  for (std::size_t i = 0; i < body.mounts.size(); ++i) {
    if (body.mounts[i].trunk_part == part) {
      write_leg(w, depth, body, i, origin_x, options.start_pose.at(i), emitted);
    }
  }
}

// The body's torsional and rolling friction, or MuJoCo's defaults when it has none (inert at
// condim 3).
double torsional(const RobotBody& body) {
  return body.torsional_friction > 0.0 ? body.torsional_friction : kTorsionalFriction;
}
double rolling(const RobotBody& body) {
  return body.rolling_friction > 0.0 ? body.rolling_friction : kRollingFriction;
}

// "mu torsional rolling" of a geom.
std::string geom_friction(const RobotBody& body, double mu) {
  return num(mu) + " " + num(torsional(body)) + " " + num(rolling(body));
}

std::string trunk_box(const RobotBody& body, const TrunkBox& box, double origin_x) {
  // The trunk's own friction against the walls, where it differs from the legs' (the default).
  const std::string friction =
      body.trunk_friction == body.foot_friction
          ? ""
          : " friction=\"" + geom_friction(body, body.trunk_friction) + "\"";
  return "<geom name=\"" + box.name + "\" type=\"box\" pos=\"" + num(box.x_centre - origin_x) +
         " 0 0\" size=\"" + num(box.length / 2) + " " + num(body.trunk_width / 2) + " " +
         num(body.trunk_height / 2) + "\" mass=\"" + num(box.mass) + "\"" + friction + "/>";
}

// Contact dimensions of the ground pairs: torsional and rolling friction act only when set.
int condim(const RobotBody& body) {
  if (body.rolling_friction > 0.0) return kCondimRolling;
  if (body.torsional_friction > 0.0) return kCondimTorsional;
  return kCondimSliding;
}

// MuJoCo's tangential creep on a contact is proportional to 1 / impratio (docs/robots.md "Body
// parameters"); at impratio 1 a foot creeps kMujocoFootSlip m/s per N.
double impratio(const RobotBody& body) {
  return kMujocoFootSlip / body.slip;
}

Vec3 rotated(const std::array<double, 4>& q, const Vec3& v) {
  const std::array<double, 3> r = robot::rotate(q, {v.x, v.y, v.z});
  return {r[0], r[1], r[2]};
}

std::string quat(const std::array<double, 4>& q) {
  return num(q[0]) + " " + num(q[1]) + " " + num(q[2]) + " " + num(q[3]);
}

// The walls stand on the ground: on a slope, tilted with it. `contact` gives their contact class.
void write_walls(Writer& w, const Scene& scene, const std::string& contact,
                 const std::string& material) {
  const double half_len = scene.tunnel_length / 2.0;
  const bool tilted = scene.terrain.kind == TerrainKind::slope;
  const std::array<double, 4> q = ground_rotation(scene.terrain);
  for (double side : {1.0, -1.0}) {
    const Vec3 along{half_len, side * (scene.tunnel_width + kWallThickness) / 2.0,
                     kWallHeight / 2.0};
    const Vec3 pos = tilted ? rotated(q, along) : along;
    w.line(2, "<geom name=\"" + std::string(side > 0 ? "wall_left" : "wall_right") + "\" " +
                  contact + " type=\"box\" pos=\"" + vec(pos) + "\"" +
                  (tilted ? " quat=\"" + quat(q) + "\"" : std::string()) + " size=\"" +
                  num(half_len) + " " + num(kWallThickness / 2.0) + " " + num(kWallHeight / 2.0) +
                  "\" material=\"" + material + "\"/>");
  }
}

// The ground: the plane (tilted on a slope), rough ground's heightfield, or the plane with steps
// on it. Every robot part that may touch the ground is paired with "ground" (make_mjcf); steps
// and walls meet the robot dynamically.
void write_ground(Writer& w, const Terrain& t) {
  switch (t.kind) {
    case TerrainKind::flat:
    case TerrainKind::steps:
      w.line(2,
             "<geom name=\"ground\" type=\"plane\" size=\"0 0 1\" contype=\"0\" "
             "conaffinity=\"0\" material=\"grid\"/>");
      break;
    case TerrainKind::slope:
      w.line(2, "<geom name=\"ground\" type=\"plane\" size=\"0 0 1\" quat=\"" +
                    quat(ground_rotation(t)) +
                    "\" contype=\"0\" conaffinity=\"0\" material=\"grid\"/>");
      break;
    case TerrainKind::rough:
      w.line(2,
             "<geom name=\"ground\" type=\"hfield\" hfield=\"terrain\" contype=\"0\" "
             "conaffinity=\"0\" material=\"grid\"/>");
      break;
  }
  if (t.kind != TerrainKind::steps) return;
  // Ahead of and behind the start: up for depth_m, down for depth_m, ..., to the terrain's edge.
  int n = 0;
  for (double side : {1.0, -1.0}) {
    for (double x = kStepsStart; x + t.depth_m <= kTerrainSide / 2.0; x += 2.0 * t.depth_m) {
      const Vec3 pos{side * (x + t.depth_m / 2.0), 0.0, t.height_m / 2.0};
      w.line(2, "<geom name=\"step_" + std::to_string(n++) +
                    "\" class=\"world\" type=\"box\" pos=\"" + vec(pos) + "\" size=\"" +
                    num(t.depth_m / 2.0) + " " + num(kTerrainSide / 2.0) + " " +
                    num(t.height_m / 2.0) + "\" material=\"grid\"/>");
    }
  }
}

}  // namespace

std::vector<ModelFile> scene_files(const Scene& scene) {
  if (scene.terrain.kind != TerrainKind::rough) return {};
  // MuJoCo's binary heightfield: int32 rows, int32 columns, then float32 samples, row-major.
  const std::vector<float> samples = rough_samples(scene.terrain);
  const std::int32_t n = rough_samples_per_side();
  std::string bytes(2 * sizeof(std::int32_t) + samples.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), &n, sizeof n);
  std::memcpy(bytes.data() + sizeof n, &n, sizeof n);
  std::memcpy(bytes.data() + 2 * sizeof n, samples.data(), samples.size() * sizeof(float));
  return {{kHeightfieldFile, std::move(bytes)}};
}

std::string coupling_joint(const std::string& servo_joint) {
  return servo_joint + "_coupling";
}

double stand_height(const RobotBody& body, const std::vector<LegAngles>& pose) {
  const LegSegments& s = body.segments;
  const double tibia_reach = foot_centre_distance(body) + s.foot.length / 2.0;
  double deepest = 0.0;
  for (const LegAngles& a : pose) {
    const double ctr = a[1];
    const double fti = a[2];
    // Depth of the foot's outer cap below the CTr joint, plus its radius.
    const double depth =
        -(s.femur.length * std::sin(ctr) + tibia_reach * std::sin(ctr + fti)) + s.foot.radius;
    deepest = std::max(deepest, depth);
  }
  return deepest - body.leg_root_z + kStartClearance;
}

std::string make_mjcf(const RobotBody& body, const MjcfOptions& options) {
  const Morphology& morph = body.morphology;
  Writer w;
  Emitted emitted;
  w.line(0, "<mujoco model=\"multicpg-" + morph.name + "\">");
  w.line(1, "<!-- Generated by multicpg from robot/body.cpp (docs/robots.md). -->");
  w.line(1, "<compiler angle=\"radian\"/>");
  const double ratio = impratio(body);
  const Terrain& terrain = options.scene.terrain;
  const bool dynamic = options.scene.tunnel || terrain.kind == TerrainKind::steps;
  w.line(1, "<option timestep=\"" + num(options.physics_dt) + "\" integrator=\"" + kIntegrator +
                "\" cone=\"" + kCone + "\" jacobian=\"" + kJacobian + "\" collision=\"" +
                (dynamic ? kTunnelCollision : kFlatCollision) + "\"" +
                (ratio == 1.0 ? "" : " impratio=\"" + num(ratio) + "\"") + "/>");
  w.line(1, "<asset>");
  w.line(2,
         "<texture name=\"grid\" type=\"2d\" builtin=\"checker\" rgb1=\".35 .4 .45\" "
         "rgb2=\".25 .3 .35\" width=\"256\" height=\"256\"/>");
  w.line(2, "<material name=\"grid\" texture=\"grid\" texrepeat=\"10 10\"/>");
  w.line(2, "<material name=\"wall\" rgba=\"" + std::string(kWallRgba) + "\"/>");
  if (terrain.kind == TerrainKind::rough) {
    w.line(2, "<hfield name=\"terrain\" file=\"" + std::string(kHeightfieldFile) + "\" size=\"" +
                  num(kTerrainSide / 2.0) + " " + num(kTerrainSide / 2.0) + " " +
                  num(terrain.height_m) + " " + num(kHeightfieldBase) + "\"/>");
  }
  w.line(1, "</asset>");
  w.line(1, "<default>");
  w.line(2, "<geom contype=\"" + std::to_string(kRobotClass) + "\" conaffinity=\"" +
                std::to_string(kWorldClass) + "\" friction=\"" +
                geom_friction(body, body.foot_friction) + "\"/>");
  w.line(2, "<joint limited=\"true\"/>");
  w.line(2, "<default class=\"world\">");
  w.line(3, "<geom contype=\"" + std::to_string(kWorldClass) + "\" conaffinity=\"" +
                std::to_string(kRobotClass) + "\"/>");
  w.line(2, "</default>");
  w.line(1, "</default>");

  w.line(1, "<worldbody>");
  w.line(2, "<light name=\"sun\" pos=\"0 0 3\" dir=\"0 0 -1\" directional=\"true\"/>");
  write_ground(w, terrain);
  if (options.scene.tunnel) write_walls(w, options.scene, "class=\"world\"", "wall");

  // The robot stands on the ground: above rough ground's highest bump; on a slope, tilted with
  // it about the start.
  double z0 = stand_height(body, options.start_pose);
  if (terrain.kind == TerrainKind::rough) z0 += terrain.height_m;
  emitted.qpos = {0.0, 0.0, z0, 1.0, 0.0, 0.0, 0.0};
  if (terrain.kind == TerrainKind::slope) {
    const std::array<double, 4> q = ground_rotation(terrain);
    const Vec3 p = rotated(q, {0.0, 0.0, z0});
    emitted.qpos = {p.x, p.y, p.z, q[0], q[1], q[2], q[3]};
  }
  w.line(2, "<body name=\"" + body.trunk[0].name + "\" pos=\"0 0 " + num(z0) + "\">");
  w.line(3, "<freejoint name=\"root\"/>");
  w.line(3, trunk_box(body, body.trunk[0], 0.0));
  write_legs_of(w, 3, body, 0, options, emitted);
  if (body.trunk.size() > 1) {
    const TrunkBox& front = body.trunk[1];
    w.line(3, "<body name=\"" + front.name + "\" pos=\"" + num(body.backbone_x) + " 0 0\">");
    // Backbone: pitch hinge held at 0 by its servo (docs/robots.md "Trunk").
    w.line(4, hinge("backbone", {0, 1, 0}, {-body.backbone_limit, body.backbone_limit},
                    body.backbone_servo));
    emitted.qpos.push_back(0.0);
    emitted.servos.emplace_back("backbone", &body.backbone_servo);
    w.line(4, trunk_box(body, front, body.backbone_x));
    write_legs_of(w, 4, body, 1, options, emitted);
    w.line(3, "</body>");
  }
  w.line(2, "</body>");
  w.line(1, "</worldbody>");

  w.line(1, "<contact>");
  const int dims = condim(body);
  const auto pair = [&](const std::string& geom, double mu) {
    const std::string friction = num(mu) + " " + num(mu) + " " + num(torsional(body)) + " " +
                                 num(rolling(body)) + " " + num(rolling(body));
    w.line(2, "<pair geom1=\"ground\" geom2=\"" + geom + "\"" +
                  (dims == kCondimSliding ? "" : " condim=\"" + std::to_string(dims) + "\"") +
                  " friction=\"" + friction + "\"/>");
  };
  for (const TrunkBox& box : body.trunk) pair(box.name, body.trunk_friction);
  for (const Leg& leg : morph.legs) {
    for (const char* part : kGroundLegParts) pair(leg.name + part, body.foot_friction);
  }
  w.line(1, "</contact>");

  // One torque actuator per servo; sim/servo.h computes its torque every physics step, never
  // more than the servo's power.
  w.line(1, "<actuator>");
  for (const auto& [joint, servo] : emitted.servos) {
    w.line(2, "<motor name=\"" + joint + "\" joint=\"" + joint +
                  "\" ctrllimited=\"true\" ctrlrange=\"" + num(-servo->power) + " " +
                  num(servo->power) + "\"/>");
  }
  w.line(1, "</actuator>");

  w.line(1, "<sensor>");
  for (const std::string& foot : emitted.feet) {
    w.line(2, "<touch name=\"" + foot + "\" site=\"" + foot + "\"/>");
  }
  w.line(2, "<framequat name=\"yaw\" objtype=\"xbody\" objname=\"" +
                body.trunk[body.yaw_part].name + "\"/>");
  w.line(1, "</sensor>");

  std::string qpos;
  for (double q : emitted.qpos) {
    if (!qpos.empty()) qpos += ' ';
    qpos += num(q);
  }
  w.line(1, "<keyframe>");
  w.line(2, "<key name=\"start\" qpos=\"" + qpos + "\"/>");
  w.line(1, "</keyframe>");
  w.line(0, "</mujoco>");
  return w.str();
}

double mjcf_value(double v) {
  return std::stod(num(v));
}

std::string robot_file_mjcf(const RobotBody& body, const Scene& scene, const RobotFile& file,
                            const std::string& model_file) {
  Writer w;
  w.line(0, "<mujoco model=\"multicpg-robot-file\">");
  w.line(1, "<include file=\"" + model_file + "\"/>");
  // The ground (robot/terrain.h): a flat model keeps its own plane (or gets one), steps stand on
  // it; a slope and rough ground replace it (make_sim_model turns the model's own off).
  const Terrain& t = scene.terrain;
  const std::string side = num(kTerrainSide / 2.0);
  if (t.kind == TerrainKind::rough) {
    w.line(1, "<asset>");
    w.line(2, "<hfield name=\"multicpg_terrain\" file=\"" + std::string(kHeightfieldFile) +
                  "\" size=\"" + side + " " + side + " " + num(t.height_m) + " " +
                  num(kHeightfieldBase) + "\"/>");
    w.line(1, "</asset>");
  }
  w.line(1, "<worldbody>");
  if (t.kind == TerrainKind::rough) {
    w.line(2, "<geom name=\"" + std::string(kRobotFileGround) +
                  "\" type=\"hfield\" hfield=\"multicpg_terrain\"/>");
  } else if (t.kind == TerrainKind::slope || file.add_ground) {
    w.line(2, "<geom name=\"" + std::string(kRobotFileGround) + "\" type=\"plane\" size=\"" + side +
                  " " + side + " 0.1\"" +
                  (t.kind == TerrainKind::slope ? " quat=\"" + quat(ground_rotation(t)) + "\""
                                                : std::string()) +
                  "/>");
  }
  if (t.kind == TerrainKind::steps) {
    int n = 0;
    for (double dir : {1.0, -1.0}) {
      for (double x = kStepsStart; x + t.depth_m <= kTerrainSide / 2.0; x += 2.0 * t.depth_m) {
        const Vec3 pos{dir * (x + t.depth_m / 2.0), 0.0, t.height_m / 2.0};
        w.line(2, "<geom name=\"multicpg_step_" + std::to_string(n++) + "\" type=\"box\" pos=\"" +
                      vec(pos) + "\" size=\"" + num(t.depth_m / 2.0) + " " + side + " " +
                      num(t.height_m / 2.0) + "\"/>");
      }
    }
  }
  w.line(1, "</worldbody>");
  if (!file.servo_joints.empty()) {
    w.line(1, "<actuator>");
    for (const std::string& joint : file.servo_joints) {
      w.line(2, "<motor name=\"multicpg_" + joint + "\" joint=\"" + joint + "\"/>");
    }
    w.line(1, "</actuator>");
  }
  if (scene.tunnel) {
    w.line(1, "<asset>");
    w.line(2, "<material name=\"multicpg_wall\" rgba=\"" + std::string(kWallRgba) + "\"/>");
    w.line(1, "</asset>");
    w.line(1, "<worldbody>");
    // What make_mjcf's "world" class and default give its walls.
    write_walls(w, scene,
                "contype=\"" + std::to_string(kWorldClass) + "\" conaffinity=\"" +
                    std::to_string(kRobotClass) + "\" friction=\"" +
                    geom_friction(body, body.foot_friction) + "\"",
                "multicpg_wall");
    w.line(1, "</worldbody>");
  }
  w.line(0, "</mujoco>");
  return w.str();
}

}  // namespace multicpg::robot
