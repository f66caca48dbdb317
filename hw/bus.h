// The robot's side of a control step over a serial line: send the joints' counts, read back what
// the hardware reports, and name everything that went wrong (docs/hardware.md "Safety"). One
// implementation per protocol (the AMOSII board, Dynamixel servos) and the yaw line; the body
// (hw/hardware_body.h) decides when errors become a stop.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/enum_names.h"
#include "hw/hardware_file.h"
#include "hw/serial_port.h"
#include "hw/yaw_line.h"

namespace multicpg::hw {

// The counts of every mapped joint: per leg TC, CTr, FTi, then the backbone's (if mapped).
struct JointCounts {
  std::vector<std::array<int, robot::kJointsPerLeg>> legs;
  std::optional<int> backbone;
};

// The counts of the file's safe posture (the backbone at 0), what a stop commands.
JointCounts safe_posture_counts(const HardwareFile& file);

// What went wrong on a line, by kind; every error is counted once.
enum class LinkError {
  timeout,       // no answer at all by the deadline
  missing,       // one servo's answer missing while others came
  short_answer,  // an answer cut short
  bad_checksum,  // a CRC (Dynamixel), end byte (AMOSII) or checksum (yaw line) that does not match
  wrong_id,      // an answer from a servo that was not asked, or of the wrong kind
  servo_error,   // a servo's status packet reports an error
  malformed,     // bytes that are no packet of the protocol (noise, a bad length, an unknown line)
};
inline constexpr auto kLinkErrorNames =
    enum_names<LinkError>({{LinkError::timeout, "timeout"},
                           {LinkError::missing, "missing"},
                           {LinkError::short_answer, "short_answer"},
                           {LinkError::bad_checksum, "bad_checksum"},
                           {LinkError::wrong_id, "wrong_id"},
                           {LinkError::servo_error, "servo_error"},
                           {LinkError::malformed, "malformed"}});
inline constexpr std::size_t kLinkErrorKinds = kLinkErrorNames.values().size();
std::string_view to_string(LinkError error);

struct LinkErrors {
  std::array<long, kLinkErrorKinds> counts{};
  long total() const;
};

// One error of one step, named for the stop line ("bad CRC in the answer of R1.TC (ID 1)").
struct StepError {
  LinkError kind;
  std::string what;
  int servo = -1;  // the servo it concerns (missing), or -1
};

// What one step's answers reported (each joint and foot only where the hardware reports it).
struct Feedback {
  std::vector<std::array<std::optional<double>, robot::kJointsPerLeg>> angles;  // rad
  std::vector<std::optional<bool>> contacts;
  std::optional<double> yaw_deg;  // an AMOSII board's yaw input
};

class Bus {
 public:
  virtual ~Bus() = default;
  // Before the first motion: every servo (or the board) answers, and `feedback` gets what they
  // reported; the servos are made ready to move (Dynamixel: position mode, torque on, each held
  // where it is). Throws RuntimeFailure naming what did not answer.
  virtual void start_check(Feedback& feedback) = 0;
  // One control step: sends the counts, reads the answers into `feedback`, appends each error to
  // `errors` (and counts it). Throws RuntimeFailure when the port itself fails.
  virtual void exchange(const JointCounts& counts, Feedback& feedback,
                        std::vector<StepError>& errors) = 0;
  // Commands the stop: the counts of the safe posture, or every servo's torque off. Best effort
  // (one write, no answer awaited); throws RuntimeFailure when the port fails.
  virtual void stop(const JointCounts& posture, StopAction action) = 0;
  const LinkErrors& errors() const { return errors_; }

 protected:
  void add(std::vector<StepError>& errors, LinkError kind, std::string what, int servo = -1);
  // Before a request: after a failed answer, waits until the line is quiet (late bytes of that
  // answer must not pass for this one's), then drops what is waiting.
  void prepare(SerialPort& port, int timeout_ms);
  LinkErrors errors_;
  bool resync_ = false;  // the last answer failed
};

// The bus of `file`'s protocol on its port (opened now; RuntimeFailure if it cannot be).
std::unique_ptr<Bus> open_bus(const HardwareFile& file);

// The yaw line (hw/yaw_line.h): polls once per step.
class YawLine {
 public:
  // Opens the file's yaw port (RuntimeFailure if it cannot be).
  explicit YawLine(const HardwareFile& file);
  // Polls and reads one answer by the yaw timeout; on an error, appends it and returns nothing.
  std::optional<yaw_line::Reading> poll(std::vector<StepError>& errors);
  const LinkErrors& errors() const { return errors_; }

 private:
  const YawSpec& spec_;
  SerialPort port_;
  Bytes pending_;
  LinkErrors errors_;
  bool resync_ = false;  // the last answer failed
};

// How long a request waits for a quiet line after a failed answer, in timeouts: the late answer
// of one request, then the line quiet for one timeout.
inline constexpr int kResyncTimeouts = 4;

}  // namespace multicpg::hw
