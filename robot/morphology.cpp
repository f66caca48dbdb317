#include "robot/morphology.h"

#include <algorithm>
#include <optional>

#include "common/errors.h"
#include "common/user_text.h"

namespace multicpg::robot {
namespace {

LegType leg_type(RobotKind kind, int position, int per_side) {
  // The quadruped AmosFour is AMOSII without its front legs (docs/robots.md "Trunk"): its front
  // pair uses the middle-leg design and its hind pair the hind-leg design.
  if (kind == RobotKind::quadruped) return position == 0 ? LegType::middle : LegType::hind;
  if (position == 0) return LegType::front;
  return position == per_side - 1 ? LegType::hind : LegType::middle;
}

Morphology make(RobotKind kind, int per_side) {
  Morphology m{kind, std::string(to_string(kind)), per_side, {}};
  for (Side side : {Side::right, Side::left}) {
    for (int pos = 0; pos < per_side; ++pos) {
      std::string leg_name(1, side == Side::right ? 'R' : 'L');
      leg_name += std::to_string(pos + 1);
      m.legs.push_back(Leg{leg_name, side, pos, leg_type(kind, pos, per_side)});
    }
  }
  return m;
}

}  // namespace

const Morphology& morphology(RobotKind kind) {
  static const std::array<Morphology, kRobotKinds.size()> all{
      make(RobotKind::hexapod, 3), make(RobotKind::quadruped, 2), make(RobotKind::octopod, 4)};
  return all[robot_index(kind)];
}

std::string_view to_string(RobotKind kind) {
  return kRobotKindNames.name(kind);
}

std::string_view to_string(Joint joint) {
  return kJointNames.name(joint);
}

std::string_view to_string(Side side) {
  return kSideNames.name(side);
}

Joint parse_joint(std::string_view name) {
  if (const std::optional<Joint> joint = kJointNames.find(name)) return *joint;
  throw BadInput(unknown_name("joint", name, kJointNames.names()));
}

RobotKind parse_robot(std::string_view name) {
  if (const std::optional<RobotKind> kind = kRobotKindNames.find(name)) return *kind;
  throw BadInput(unknown_name("robot", name, kRobotKindNames.names()));
}

std::size_t leg_index(const Morphology& morph, std::string_view name) {
  for (std::size_t i = 0; i < morph.legs.size(); ++i) {
    if (morph.legs[i].name == name) return i;
  }
  std::string names;
  for (const Leg& leg : morph.legs) {
    if (!names.empty()) names += ' ';
    names += leg.name;
  }
  throw BadInput("the " + morph.name + " has no leg '" + std::string(name) + "' (legs: " + names +
                 ")");
}

}  // namespace multicpg::robot
