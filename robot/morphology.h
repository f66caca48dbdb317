// Leg layout of the three robots (docs/controller.md "Legs, joints and the controller step"):
// names, sides and positions front to hind.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace multicpg::robot {

enum class RobotKind { hexapod, quadruped, octopod };
inline constexpr std::array<RobotKind, 3> kRobotKinds{RobotKind::hexapod, RobotKind::quadruped,
                                                      RobotKind::octopod};
// Position of `kind` in kRobotKinds, for tables of per-robot values.
constexpr std::size_t robot_index(RobotKind kind) {
  return static_cast<std::size_t>(kind);
}
enum class Side { right, left };
// Which AMOSII leg design a leg uses; decides its TC window and limit (docs/controller.md "Motor
// mapping and joint windows", docs/robots.md "Joint limits").
enum class LegType { front, middle, hind };
// Joints of a leg, in the order used everywhere (docs/controller.md "Legs, joints and the
// controller step").
enum class Joint { TC, CTr, FTi };
inline constexpr std::size_t kJointsPerLeg = 3;
inline constexpr std::array<Joint, kJointsPerLeg> kJoints{Joint::TC, Joint::CTr, Joint::FTi};

struct Leg {
  std::string name;  // R1..Rn, L1..Ln
  Side side;
  int position;  // 0 = front
  LegType type;
};

// What a robot's leg layout is. Legs are ordered R1..Rn then L1..Ln; legs[0] = R1 is the master.
struct Morphology {
  RobotKind kind;
  std::string name;
  int legs_per_side;
  std::vector<Leg> legs;

  std::size_t size() const { return legs.size(); }
};

const Morphology& morphology(RobotKind kind);

std::string_view to_string(RobotKind kind);
std::string_view to_string(Joint joint);

// Parsers for user input; each throws BadInput with one line naming what is wrong.
RobotKind parse_robot(std::string_view name);
Joint parse_joint(std::string_view name);  // "TC", "CTr" or "FTi"
std::size_t leg_index(const Morphology& morph, std::string_view name);

}  // namespace multicpg::robot
