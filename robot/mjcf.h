// MJCF text of a robot on flat ground (docs/robots.md), made from its RobotBody. The file is plain
// MuJoCo 2.2 MJCF: it loads in MuJoCo's own tools (mujoco-testxml, mujoco-simulate).
//
// Names, so that tools can find a leg's parts: bodies and geoms "trunk", "front_trunk",
// "<leg>_coxa", "<leg>_femur", "<leg>_tibia", "<leg>_foot" (geoms also "<leg>_shoulder");
// joints "root", "backbone", "<leg>_TC", "<leg>_CTr", "<leg>_FTi", "<leg>_foot_spring" (and with
// compliant joints "<leg>_TC_coupling", ... after each servo joint, coupling_joint());
// torque actuators "<joint>" (the servo law is sim/servo.h); sites and touch sensors
// "<leg>_foot"; orientation sensor "yaw" on the front trunk; keyframe "start".
#pragma once

#include <array>
#include <string>
#include <vector>

#include "robot/body.h"
#include "robot/robot_file.h"
#include "robot/terrain.h"

namespace multicpg::robot {

// The world around the robot. The corridor of paper §5 (Table 1) is two walls parallel to x,
// from x = 0 (the robot starts at its entrance) to x = tunnel_length, tunnel_width apart.
struct Scene {
  bool tunnel = false;
  double tunnel_length = 3.0;  // m
  double tunnel_width = 1.2;   // m
  Terrain terrain;             // the ground (robot/terrain.h); the walls stand on it

  bool operator==(const Scene&) const = default;
};

// A file the MJCF refers to, beside it (rough ground's heightfield): its name and bytes.
struct ModelFile {
  std::string name;
  std::string bytes;
};

// The files make_mjcf's document refers to for `scene` (none for most).
std::vector<ModelFile> scene_files(const Scene& scene);

// TC, CTr, FTi angles of one leg (rad, joint_map.h convention).
using LegAngles = std::array<double, kJointsPerLeg>;

struct MjcfOptions {
  double physics_dt = 0.005;  // s, MuJoCo timestep
  Scene scene;
  std::vector<LegAngles> start_pose;  // one per leg: the "start" keyframe's joint angles
};

// The passive coupling joint behind a servo joint ("R1_TC" -> "R1_TC_coupling"), present when the
// body's joint_compliance is above 0. The segment's angle is the servo's plus the coupling's.
std::string coupling_joint(const std::string& servo_joint);

// Height of the trunk origin that puts the lowest foot of `pose` on the ground (m). The TC axis
// is vertical and the coxa horizontal, so only CTr and FTi decide how far a foot reaches down.
double stand_height(const RobotBody& body, const std::vector<LegAngles>& pose);

// The MJCF document. The "start" keyframe stands the robot at the origin facing +x in
// options.start_pose, feet on the ground.
std::string make_mjcf(const RobotBody& body, const MjcfOptions& options);

// `v` as MuJoCo reads it back from make_mjcf's document (which writes 12 significant digits).
double mjcf_value(double v);

// The ground a robot file's world adds (robot_file_mjcf).
inline constexpr const char* kRobotFileGround = "multicpg_ground";

// A robot file's world (docs/robots.md "Your robot: robot files"): a document that includes the
// file's MJCF as `model_file`, adds a motor on each of its servo_joints (the servo law's, for the
// joints the model leaves without an actuator), the ground of scene.terrain (a plane if the model
// has none and the terrain is flat, steps on it, a tilted plane, a heightfield) and, with
// scene.tunnel, the tunnel's walls as make_mjcf has them for `body` (the compiled walls differ
// only in their material's name; collisions must then be "all", set on the compiled model).
std::string robot_file_mjcf(const RobotBody& body, const Scene& scene, const RobotFile& file,
                            const std::string& model_file);

}  // namespace multicpg::robot
