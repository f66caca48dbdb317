// A fake robot on pseudo-terminals (docs/hardware.md "Rehearse on the emulator"): it speaks the
// hardware file's protocol byte for byte (the AMOSII board's frames, or Dynamixel Protocol 2.0 and
// the yaw line), parses strictly, moves our MuJoCo robot one control step per command frame with
// the received targets, and answers with what that robot's sensors read, quantised as the
// hardware's would be. On request it injects faults: dropped or corrupted answer bytes, latency, a
// servo (or the board) that stops answering, a drifting or silent yaw sensor.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hw/hardware_file.h"
#include "hw/serial_port.h"
#include "sim/sim.h"

namespace multicpg::emulator {

// One injected fault, from command frame `step` on (KIND[=VALUE]@STEP).
struct Injection {
  enum class Kind {
    drop,        // each answer byte is lost with probability `value`
    corrupt,     // each answer gets one byte changed with probability `value`
    latency,     // each answer goes out `value` ms late
    silent,      // servo ID `value` stops answering (Dynamixel); the board (AMOSII)
    drift,       // the yaw reads `value` deg/s more as time goes on
    silent_yaw,  // the yaw sensor stops answering (a line), or reads 0 (a board input)
    hangup,      // the emulator closes its ports (the bus's first) and ends, as if killed
    hangup_yaw,  // the yaw line's port closes; the bus's stays until the host hangs up
  };
  Kind kind = Kind::drop;
  double value = 0.0;
  long step = 0;
};
// "drop=0.2@100", "silent=5@300", "silent-yaw@40", ... Throws BadInput naming the kinds, a value
// out of range or missing.
Injection parse_injection(std::string_view text, const hw::HardwareFile& file);
std::string to_string(const Injection& injection);

struct EmulatorSpec {
  std::vector<Injection> injections;
  std::uint64_t seed = 1;  // the draws of drop and corrupt
  // Each frame and answer also takes the time its bytes need on the wire at the file's baud.
  bool wire_time = false;
  std::filesystem::path log;  // JSON lines of what happened, with monotonic times; empty: none
};

// Digits after the point of the yaw line's numbers: 0.01 deg and 0.01 mm, an IMU's resolution.
inline constexpr int kYawLineDecimals = 2;

struct EmulatorSummary {
  long steps = 0;           // command frames, each one control step of the robot
  long answers = 0;         // answers sent
  long malformed = 0;       // host bytes or packets refused
  bool posture = false;     // the safe posture was commanded
  bool torque_off = false;  // every servo's torque was turned off
  bool hung_up = false;     // an injected hang-up closed a port: no run can follow
};

class Emulator {
 public:
  // Opens the pseudo-terminals (the bus's, and the yaw line's when the file has one) and starts
  // `model`'s robot in its start pose.
  Emulator(const sim::SimModel& model, const hw::HardwareFile& file, EmulatorSpec spec);
  Emulator(const Emulator&) = delete;
  Emulator& operator=(const Emulator&) = delete;
  ~Emulator();

  const std::string& bus_path() const { return bus_.path; }
  const std::string& yaw_path() const { return yaw_.path; }  // empty without a yaw line
  // Serves one run: until the host has opened and closed the bus port. Throws Interrupted on
  // SIGINT or SIGTERM, RuntimeFailure if the simulated robot becomes unstable.
  EmulatorSummary run();
  // Makes ready for the next run on the same ports: the robot back in its start pose, the
  // servos' RAM and the injections as at the start, the log appended to. False when a hang-up
  // closed the ports.
  bool next_run();

 private:
  class Impl;
  const sim::SimModel& model_;
  const hw::HardwareFile& file_;
  EmulatorSpec spec_;
  hw::Pty bus_;
  hw::Pty yaw_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace multicpg::emulator
