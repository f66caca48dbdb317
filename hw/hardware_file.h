// A hardware file (docs/hardware.md "The hardware file"): a TOML map of a real robot's servos and
// sensors onto the leg map the controller drives (legs R1..Ln, L1..Ln; joints TC, CTr, FTi, as in
// robot files): the serial port and protocol, each joint's servo ID, sign, zero and limits, the
// yaw source, and what a stop does. Checked whole before anything moves.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "robot/joint_map.h"
#include "robot/morphology.h"

namespace multicpg::hw {

enum class Protocol { amosii, dynamixel };
std::string_view to_string(Protocol protocol);
Protocol parse_protocol(std::string_view text);  // throws BadInput naming the choices
std::vector<std::string> protocol_names();       // every protocol's name, as files spell it

// What a stop (the end of a run, a fault, a signal) commands (docs/hardware.md "Safety").
enum class StopAction {
  posture,     // every joint to the safe posture, and held there
  torque_off,  // the safe posture, then every servo's torque off (Dynamixel)
};
std::string_view to_string(StopAction action);

enum class YawSource {
  board,  // an input of the AMOSII board (its sensor frame)
  line,   // a serial line of its own (hw/yaw_line.h)
};

// The servo counts a protocol can command: AMOSII board bytes 1..255, Dynamixel X 0..4095.
struct CountRange {
  int lo;
  int hi;
};
CountRange servo_range(Protocol protocol);
// Largest servo ID: the board's 32 ports, Dynamixel's 252.
int max_servo_id(Protocol protocol);

// One joint's servo: counts = zero + sign * angle / deg_per_count (angle in the paper's
// convention, degrees: TC + forward, CTr + elevation, FTi + extension), and the angles the joint
// may be sent to.
struct ServoJoint {
  int id = 0;
  double sign = 1.0;
  double zero = 0.0;           // counts at angle 0
  double deg_per_count = 1.0;  // the file's, or the joint's own
  robot::AngleRange limits{};  // rad

  // The counts for `angle_rad`, clamped to the limits first and rounded.
  int counts(double angle_rad) const;
  // The angle `counts` stand for (rad).
  double angle(int counts) const;
};

// An AMOSII foot contact sensor: a board input reading `off` in the air and `on` on the ground.
struct ContactInput {
  int port = 0;
  int off = 0;
  int on = 255;
  bool touching(int reading) const;  // past the middle of off..on
};

struct LegServos {
  std::string name;
  std::array<ServoJoint, robot::kJointsPerLeg> joints;  // TC, CTr, FTi
  std::optional<ContactInput> contact;                  // AMOSII board only
};

struct YawSpec {
  YawSource source = YawSource::line;
  // line: its own port
  std::string port;
  int baud = 115'200;
  int timeout_ms = 50;    // an unanswered poll
  bool position = false;  // answers POSE lines: the trunk's position is sensed
  // board: the input, its count at heading 0 and degrees per count; 0 and 255 (the rails: no
  // power, a broken wire) read as no reading
  int board_port = 0;
  double zero = 0.0;
  double deg_per_count = 1.0;
};

struct HardwareFile {
  std::filesystem::path path;
  std::string name;
  std::string checksum;  // of its text (common/checksum.h), recorded with every run
  Protocol protocol = Protocol::dynamixel;
  std::string port;
  int baud = 57'600;
  int timeout_ms = 20;          // an answer later than this is missing
  int max_errors = 3;           // control steps in a row with a bad or missing answer before a stop
  std::vector<LegServos> legs;  // in morphology order
  std::optional<ServoJoint> backbone;  // held at 0 (AMOSII's backbone joint)
  YawSpec yaw;
  StopAction stop = StopAction::posture;
  std::array<double, robot::kJointsPerLeg> safe_posture{};  // TC, CTr, FTi, rad, every leg
  // A rehearsal file's (multicpg emulate): the emulator serving its pseudo-terminals, so that a
  // port whose number the kernel gave another program after the emulator ended is not opened.
  std::optional<int> emulator_pid;

  // Whether the robot senses its trunk's position (a POSE yaw line).
  bool senses_position() const { return yaw.source == YawSource::line && yaw.position; }
  // "R1.CTr (ID 5)": a servo named for messages.
  std::string servo_name(int id) const;
};

// Most bytes a hardware file may have (a hexapod's is about 3 kB).
inline constexpr std::uintmax_t kMaxHardwareFileBytes = 1 << 20;
// Documented ranges.
inline constexpr int kMaxTimeoutMs = 10'000;
inline constexpr int kMaxErrorsLimit = 100;
// Largest process ID Linux hands out (PID_MAX_LIMIT on 64-bit machines, proc(5)).
inline constexpr long kMaxPid = 4'194'304;

// The hardware file at `path` for a robot with `morph`'s legs. Throws BadInput, one line
// "FILE: KEY: what is wrong", for a missing or unknown key, a value of the wrong type, a leg or
// joint not mapped, a duplicate servo ID or input, limits outside the servo's range, a safe posture
// outside a joint's limits, or a choice the protocol does not have.
HardwareFile load_hardware_file(const std::filesystem::path& path, const robot::Morphology& morph);

// The file's TOML with the bus and yaw ports replaced and the emulator serving them named (the
// emulator's rehearsal copy).
std::string with_ports(const std::filesystem::path& path, const std::string& port,
                       const std::string& yaw_port, int emulator_pid);

}  // namespace multicpg::hw
