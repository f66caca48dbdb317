#include "robot/robot_file.h"

#include <fmt/format.h>

#include "robot/body.h"

namespace multicpg::robot {
namespace {

// fmt's shortest representation reads back to the same double, so a written window is the
// built-in one bit for bit.
std::string window_text(const AngleRange& w) {
  return fmt::format("[{}, {}]", w.lo, w.hi);
}

std::string joint_text(const JointMap& j) {
  return fmt::format("{{ joint = \"{}\", sign = {}, window = {} }}", j.name, j.sign,
                     window_text(j.window));
}

}  // namespace

RobotFile builtin_robot_file(RobotKind kind, const std::filesystem::path& model) {
  const RobotBody& body = robot_body(kind);
  RobotFile file;
  file.name = body.morphology.name;
  file.model = model;
  file.trunk = body.trunk[0].name;
  file.yaw = body.trunk[body.yaw_part].name;
  file.master = body.morphology.legs[0].name;
  for (const Leg& leg : body.morphology.legs) {
    LegMap map{leg.name, leg.side, leg.position, {}, leg.name + "_foot"};
    for (std::size_t j = 0; j < kJointsPerLeg; ++j) {
      const Joint joint = kJoints[j];
      map.joints[j] = {leg.name + "_" + std::string(to_string(joint)), 1.0,
                       joint_limits(leg.type, joint)};
    }
    file.legs.push_back(map);
  }
  if (body.trunk.size() > 1) {
    file.backbone = JointMap{"backbone", 1.0, {-body.backbone_limit, body.backbone_limit}};
  }
  file.layout = kind;
  return file;
}

std::string robot_file_toml(const RobotFile& file) {
  std::string t;
  t += "# A multicpg robot file (docs/robots.md \"Your robot: robot files\"). Windows in rad.\n";
  t += fmt::format("name = \"{}\"\n", file.name);
  t += fmt::format("model = \"{}\"\n", file.model.generic_string());
  t += fmt::format("trunk = \"{}\"\n", file.trunk);
  t += fmt::format("yaw = \"{}\"\n", file.yaw);
  t += fmt::format("master = \"{}\"\n", file.master);
  if (file.backbone) t += fmt::format("backbone = {}\n", joint_text(*file.backbone));
  for (const LegMap& leg : file.legs) {
    t += "\n[[legs]]\n";
    t += fmt::format("name = \"{}\"\n", leg.name);
    t += fmt::format("side = \"{}\"\n", to_string(leg.side));
    t += fmt::format("position = {}\n", leg.position);
    t += fmt::format("foot = \"{}\"\n", leg.foot);
    for (std::size_t j = 0; j < kJointsPerLeg; ++j) {
      t += fmt::format("{} = {}\n", to_string(kJoints[j]), joint_text(leg.joints[j]));
    }
  }
  return t;
}

}  // namespace multicpg::robot
