// A robot file (docs/robots.md "Your robot: robot files"): a TOML leg map that names a MuJoCo
// model (MJCF) and, in it, the trunk, the yaw sensor's body or site, and each leg's joints (TC,
// CTr, FTi: sign and angle window) and foot. The controller of paper §2 drives it as it drives
// the built-in robot with the same leg layout (robot/morphology.h).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "robot/joint_map.h"
#include "robot/morphology.h"

namespace multicpg::robot {

// One servo joint of the model: its name, the sign that turns its angle into the paper's
// convention (joint_map.h: TC + forward, CTr + elevation, FTi + extension) and the window a
// motor command m in [-1, 1] spans (rad, joint_map.h joint_limits for the built-in robots).
struct JointMap {
  std::string name;
  double sign = 1.0;  // +1 or -1
  AngleRange window{};
};

struct LegMap {
  std::string name;  // R1..Rn, L1..Ln (paper §4.1)
  Side side;
  int position;                                // 0 = front
  std::array<JointMap, kJointsPerLeg> joints;  // TC, CTr, FTi
  std::string foot;  // the geom that touches the ground, or the body whose first geom it is
};

// What a robot file says, checked against its model (sim/robot_file.h load_robot_file).
struct RobotFile {
  std::filesystem::path path;  // the TOML, as given
  std::string name;
  std::filesystem::path model;  // the MJCF or URDF, resolved against the TOML's folder
  // Its MJCF, read once (a URDF as MuJoCo's loader reads it, with a free joint on the trunk).
  std::string model_xml;
  std::string trunk;         // the body with the free joint
  std::string yaw;           // the body or site whose framequat sensor gives the yaw
  std::string master;        // the leg whose CPG the others follow (paper §2.3)
  std::vector<LegMap> legs;  // in morphology order (R1..Rn, L1..Ln)
  std::optional<JointMap> backbone;
  // The joints of the map that the model leaves without an actuator: each gets a motor driven by
  // the servo law (found by load_robot_file).
  std::vector<std::string> servo_joints;
  // The model has no ground plane (a URDF never has): a flat one is added (friction 1).
  bool add_ground = false;
  // The built-in robot with the same leg layout: its controller tables, servos and fault
  // geometry serve this robot.
  RobotKind layout;
};

// The leg map of a built-in robot (robot/mjcf.h names) whose MJCF is `model` (no text read).
RobotFile builtin_robot_file(RobotKind kind, const std::filesystem::path& model);

// The TOML of `file`, its model named relative to the TOML's folder; load_robot_file reads it
// back to the same description (every number written to round-trip exactly).
std::string robot_file_toml(const RobotFile& file);

std::string_view to_string(Side side);  // "right", "left"

}  // namespace multicpg::robot
