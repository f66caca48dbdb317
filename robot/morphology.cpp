#include "robot/morphology.h"

#include <algorithm>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

LegType leg_type(RobotKind kind, int position, int per_side) {
  // The quadruped AmosFour is AMOSII without its front legs (docs/robots.md "Trunk"): its front
  // pair uses the middle-leg design and its hind pair the hind-leg design.
  if (kind == RobotKind::quadruped) return position == 0 ? LegType::middle : LegType::hind;
  if (position == 0) return LegType::front;
  return position == per_side - 1 ? LegType::hind : LegType::middle;
}

Morphology make(RobotKind kind, std::string name, int per_side) {
  Morphology m{kind, std::move(name), per_side, {}};
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
      make(RobotKind::hexapod, "hexapod", 3), make(RobotKind::quadruped, "quadruped", 2),
      make(RobotKind::octopod, "octopod", 4)};
  return all[robot_index(kind)];
}

std::string_view to_string(RobotKind kind) {
  return morphology(kind).name;
}

std::string_view to_string(Joint joint) {
  switch (joint) {
    case Joint::CTr:
      return "CTr";
    case Joint::FTi:
      return "FTi";
    case Joint::TC:
      break;
  }
  return "TC";
}

Joint parse_joint(std::string_view name) {
  for (Joint j : kJoints) {
    if (name == to_string(j)) return j;
  }
  throw BadInput("unknown joint '" + std::string(name) + "' (TC, CTr or FTi)");
}

RobotKind parse_robot(std::string_view name) {
  for (RobotKind k : kRobotKinds) {
    if (name == morphology(k).name) return k;
  }
  throw BadInput("unknown robot '" + std::string(name) +
                 "' (expected hexapod, quadruped or octopod)");
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
