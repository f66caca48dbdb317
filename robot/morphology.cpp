#include "robot/morphology.h"

#include <algorithm>

#include "common/errors.h"

namespace multicpg::robot {
namespace {

LegType leg_type(RobotKind kind, int position, int per_side) {
  // The quadruped AmosFour is AMOSII without its front legs (reference §6.2): its front pair
  // uses the middle-leg design and its hind pair the hind-leg design.
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

std::vector<std::size_t> parse_leg_list(const Morphology& morph, std::string_view list) {
  std::vector<std::size_t> out;
  std::size_t start = 0;
  while (start <= list.size() && !list.empty()) {
    std::size_t comma = list.find(',', start);
    if (comma == std::string_view::npos) comma = list.size();
    std::string_view item = list.substr(start, comma - start);
    if (item.empty()) throw BadInput("empty leg name in list '" + std::string(list) + "'");
    const std::size_t leg = leg_index(morph, item);
    if (std::find(out.begin(), out.end(), leg) != out.end()) {
      throw BadInput("leg " + std::string(item) + " is listed twice in '" + std::string(list) +
                     "'");
    }
    out.push_back(leg);
    start = comma + 1;
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string leg_list_name(const Morphology& morph, const std::vector<std::size_t>& legs) {
  std::string out;
  for (std::size_t i : legs) {
    if (!out.empty()) out += ',';
    out += morph.legs[i].name;
  }
  return out;
}

}  // namespace multicpg::robot
