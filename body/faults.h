// What can break on a walking robot, and when (paper §4; docs/faults.md). A fault strikes some legs
// (or one joint of each) or the yaw sensor at a controller step, and may be recovered later. The
// kind is a variant: a whole leg holding its disabled posture (the paper's malfunction), a
// locked, passive or weak joint, a shortened tibia, a slippery foot, a drifting or noisy yaw
// sensor. Plain types, no MuJoCo: the learner and its tests use them too; the physics of each
// kind is in sim/fault_effects.h.
//
// Adding a kind: an alternative of Malfunction with its traits (kName, kStrikes and, with a value,
// kValue and a member `value`) here, and its physics in sim/fault_effects.cpp. Parsing, JSON, the
// CLI, experiment files and Python go through the traits.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/limits.h"
#include "robot/morphology.h"

namespace multicpg::body {

// What a fault kind strikes.
enum class Strikes {
  legs,            // whole legs
  joints,          // one joint of each leg named
  legs_or_joints,  // whole legs, or one joint of each
  sensor,          // the yaw sensor (no leg)
};

// A fault kind's value, written KIND=VALUE: its name, unit and documented range.
struct ValueSpec {
  std::string_view name;
  std::string_view unit;
  Limits<double> limits;
  bool required;  // false: the kind may be written without a value
};

// The paper's malfunction: the leg's three joints hold the disabled posture (docs/controller.md
// "Disabled legs").
struct LegFault {
  static constexpr std::string_view kName = "leg";
  static constexpr Strikes kStrikes = Strikes::legs;
  bool operator==(const LegFault&) const = default;
};

// A servo that seized: the joint is stuck at the angle it had when it broke, or at the given
// angle (the paper's convention: + forward, elevation, extension).
struct LockedJoint {
  static constexpr std::string_view kName = "locked";
  static constexpr Strikes kStrikes = Strikes::joints;
  // Within the widest joint window (docs/robots.md "Joint limits": FTi -130..-20 deg, TC up to
  // +-70 deg); validate checks the joint's own limits.
  static constexpr ValueSpec kValue{"angle", "deg", {-180.0, 180.0}, false};
  std::optional<double> value;  // the lock angle, deg
  bool operator==(const LockedJoint&) const = default;
};

// A stripped gear or a motor without power: no motor torque, the joint swings freely (with its
// rotor inertia and friction).
struct PassiveJoint {
  static constexpr std::string_view kName = "passive";
  static constexpr Strikes kStrikes = Strikes::joints;
  bool operator==(const PassiveJoint&) const = default;
};

// A sagging battery or a worn motor: the torque limit times a factor. Down to 1 % (less is a
// passive joint).
struct WeakMotor {
  static constexpr std::string_view kName = "weak";
  static constexpr Strikes kStrikes = Strikes::legs_or_joints;
  static constexpr ValueSpec kValue{"factor", "", {0.01, 1.0}, true};
  double value = 1.0;  // the factor
  bool operator==(const WeakMotor&) const = default;
};

// A tibia broken shorter: its length times a fraction, the foot moved in with it. Down to a
// tenth (a stub still longer than the foot's radius).
struct ShortTibia {
  static constexpr std::string_view kName = "short";
  static constexpr Strikes kStrikes = Strikes::legs;
  static constexpr ValueSpec kValue{"fraction", "", {0.1, 1.0}, true};
  double value = 1.0;  // the fraction of the length left
  bool operator==(const ShortTibia&) const = default;
};

// A worn rubber foot: its friction times a factor.
struct SlipperyFoot {
  static constexpr std::string_view kName = "slip";
  static constexpr Strikes kStrikes = Strikes::legs;
  static constexpr ValueSpec kValue{"factor", "", {0.01, 1.0}, true};
  double value = 1.0;  // the factor
  bool operator==(const SlipperyFoot&) const = default;
};

// A drifting gyro: the yaw the learner and the steering reflex read grows at a rate from the
// fault on (the true yaw does not). Real MEMS gyros drift well under 1 deg/s; 10 is far beyond.
struct ImuDrift {
  static constexpr std::string_view kName = "drift";
  static constexpr Strikes kStrikes = Strikes::sensor;
  static constexpr ValueSpec kValue{"rate", "deg/s", {-10.0, 10.0}, true};
  double value = 0.0;  // deg/s
  bool operator==(const ImuDrift&) const = default;
};

// A noisy yaw sensor: Gaussian noise of a standard deviation on every reading, drawn from the
// run's seed (body::StartSpec::seed), one draw per controller step.
struct ImuNoise {
  static constexpr std::string_view kName = "noise";
  static constexpr Strikes kStrikes = Strikes::sensor;
  static constexpr ValueSpec kValue{"sigma", "deg", {0.0, 30.0}, true};
  double value = 0.0;  // standard deviation, deg
  bool operator==(const ImuNoise&) const = default;
};

using Malfunction = std::variant<LegFault, LockedJoint, PassiveJoint, WeakMotor, ShortTibia,
                                 SlipperyFoot, ImuDrift, ImuNoise>;

// Malfunctions fail or recover before controller step `step` of a run (docs/faults.md "When
// faults strike").
struct Fault {
  long step = 0;
  std::vector<std::size_t> legs;  // sorted leg indices; empty for a sensor fault
  bool recover = false;
  Malfunction kind = LegFault{};
  std::optional<robot::Joint> joint = std::nullopt;  // one joint of each leg; none = the whole leg
  bool operator==(const Fault&) const = default;
};
// Sorted by step; several events may share a step.
using FaultTimeline = std::vector<Fault>;

// The name of a kind ("leg", "locked", ...) and its traits.
std::string_view kind_name(const Malfunction& kind);
Strikes strikes(const Malfunction& kind);
// The kind's value, none when it has none or was not given (a lock at the angle it had).
std::optional<double> value_of(const Malfunction& kind);
// The kind named `name` with `value` (none: without one; `value_optional`: a required value may be
// left out, as a recovery does). Throws BadInput naming the kinds for an unknown name, a missing,
// superfluous or out-of-range value.
Malfunction make_kind(std::string_view name, std::optional<double> value,
                      bool value_optional = false);
// Every kind's name, "leg, locked, passive, ...".
std::string kind_names();

// Two faults strike the same thing when they are of the same kind on a shared leg and joint (a
// whole-leg weak motor overlaps each joint of that leg), or both on the sensor with one kind: one
// such fault at a time, and a recovery names the one it ends.
bool same_target(const Fault& a, const Fault& b);

}  // namespace multicpg::body
