#include "hw/bus.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <utility>

#include "common/errors.h"
#include "hw/amosii.h"
#include "hw/dynamixel.h"

namespace multicpg::hw {
namespace {

using std::chrono::milliseconds;

// The rails of a board input: a sensor without power, or a broken wire (no reading).
constexpr int kRailLow = 0;
constexpr int kRailHigh = 255;

std::string ms_text(int ms) {
  return std::to_string(ms) + " ms";
}

// Dynamixel servos (hw/dynamixel.h): a SYNC WRITE of goal positions and a SYNC READ of present
// positions per control step.
class DynamixelBus final : public Bus {
 public:
  explicit DynamixelBus(const HardwareFile& file)
      : file_(file), port_(file.port, file.baud, file.emulator_pid) {
    for (const LegServos& leg : file.legs) {
      for (const ServoJoint& j : leg.joints) ids_.push_back(static_cast<std::uint8_t>(j.id));
    }
    if (file.backbone) ids_.push_back(static_cast<std::uint8_t>(file.backbone->id));
  }

  void start_check(Feedback& feedback) override {
    for (std::uint8_t id : ids_) {
      if (!ask(dxl::ping(id), id)) {
        throw RuntimeFailure("start-up check: " + file_.servo_name(id) +
                             " does not answer a PING (" + last_ + ")");
      }
    }
    // Position mode can only be set with the torque off; the goal is set to where each servo is,
    // so turning the torque on moves nothing.
    const std::map<std::uint8_t, std::int32_t> present = present_positions();
    angles(present, feedback);
    for (std::uint8_t id : ids_) {
      const std::uint8_t off = 0;
      const std::uint8_t on = 1;
      const Bytes goal = dxl::position_bytes(present.at(id));
      if (!ask(dxl::write(id, dxl::kTorqueEnableAddress, std::span(&off, 1)), id) ||
          !ask(dxl::write(id, dxl::kOperatingModeAddress, std::span(&dxl::kPositionControlMode, 1)),
               id) ||
          !ask(dxl::write(id, dxl::kGoalPositionAddress, goal), id) ||
          !ask(dxl::write(id, dxl::kTorqueEnableAddress, std::span(&on, 1)), id)) {
        throw RuntimeFailure("start-up check: " + file_.servo_name(id) +
                             " did not take position mode and torque (" + last_ + ")");
      }
    }
  }

  void exchange(const JointCounts& counts, Feedback& feedback,
                std::vector<StepError>& errors) override {
    prepare(port_, file_.timeout_ms);
    port_.write(goal_packet(counts));
    port_.write(dxl::sync_read(dxl::kPresentPositionAddress, dxl::kPositionBytes, ids_));
    std::map<std::uint8_t, std::int32_t> present;
    for (const auto& [id, p] : read_statuses(ids_, errors)) {
      present[id] = dxl::position_value(std::span(p.params).subspan(1));
    }
    angles(present, feedback);
  }

  void stop(const JointCounts& posture, StopAction action) override {
    if (action == StopAction::torque_off) {
      const std::uint8_t off = 0;
      port_.write(dxl::write(dxl::kBroadcastId, dxl::kTorqueEnableAddress, std::span(&off, 1)));
    } else {
      port_.write(goal_packet(posture));
    }
  }

 private:
  void angles(const std::map<std::uint8_t, std::int32_t>& present, Feedback& feedback) const {
    feedback.angles.assign(file_.legs.size(), {});
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        const ServoJoint& servo = file_.legs[i].joints[j];
        const auto it = present.find(static_cast<std::uint8_t>(servo.id));
        if (it != present.end()) feedback.angles[i][j] = servo.angle(it->second);
      }
    }
  }

  Bytes goal_packet(const JointCounts& counts) const {
    std::vector<std::pair<std::uint8_t, Bytes>> data;
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        data.emplace_back(file_.legs[i].joints[j].id, dxl::position_bytes(counts.legs[i][j]));
      }
    }
    if (file_.backbone)
      data.emplace_back(file_.backbone->id, dxl::position_bytes(*counts.backbone));
    return dxl::sync_write(dxl::kGoalPositionAddress, dxl::kPositionBytes, data);
  }

  // Sends `packet` and awaits one status packet of `id` without error (start-up check).
  bool ask(const Bytes& packet, std::uint8_t id) {
    prepare(port_, file_.timeout_ms);
    port_.write(packet);
    std::vector<StepError> errors;
    const std::uint8_t ids[] = {id};
    const auto answers = read_statuses(ids, errors, /*data_bytes=*/-1);
    if (!errors.empty()) last_ = errors.front().what;
    return answers.count(id) == 1;
  }

  std::map<std::uint8_t, std::int32_t> present_positions() {
    std::vector<StepError> errors;
    prepare(port_, file_.timeout_ms);
    port_.write(dxl::sync_read(dxl::kPresentPositionAddress, dxl::kPositionBytes, ids_));
    const auto answers = read_statuses(ids_, errors);
    if (!errors.empty()) {
      throw RuntimeFailure("start-up check: reading the present positions: " + errors.front().what);
    }
    std::map<std::uint8_t, std::int32_t> out;
    for (const auto& [id, p] : answers) {
      out[id] = dxl::position_value(std::span(p.params).subspan(1));
    }
    return out;
  }

  // Reads one status packet from each of `ids` by the timeout. `data_bytes`: the data each must
  // carry after its error field (-1: any). Errors are counted and appended.
  std::map<std::uint8_t, dxl::Packet> read_statuses(std::span<const std::uint8_t> ids,
                                                    std::vector<StepError>& errors,
                                                    int data_bytes = dxl::kPositionBytes) {
    std::map<std::uint8_t, dxl::Packet> got;
    const auto deadline = Clock::now() + milliseconds(file_.timeout_ms);
    Bytes stream;
    std::vector<std::uint8_t> rejected;  // answered, but unusably
    bool heard = false;
    bool damaged = false;
    while (got.size() + rejected.size() < ids.size()) {
      if (port_.read_some(stream, deadline) == 0) break;
      heard = true;
      for (;;) {
        const dxl::ParseResult r = dxl::parse(stream);
        if (r.skipped > 0) {
          add(errors, LinkError::malformed,
              std::to_string(r.skipped) + " bytes that are no packet");
          damaged = true;
        }
        stream.erase(stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(r.consumed));
        if (r.status == dxl::ParseStatus::incomplete) break;
        damaged = damaged || r.status != dxl::ParseStatus::packet;
        if (r.status == dxl::ParseStatus::bad_crc) {
          add(errors, LinkError::bad_checksum, "bad CRC in an answer");
        } else if (r.status == dxl::ParseStatus::bad_length) {
          add(errors, LinkError::malformed, "a packet with an impossible length");
        } else {
          take(*r.packet, ids, data_bytes, got, rejected, errors);
        }
      }
    }
    if (got.size() + rejected.size() < ids.size()) {
      if (!heard) {
        add(errors, LinkError::timeout,
            "no answer by the timeout (" + ms_text(file_.timeout_ms) + ")");
      } else {
        if (!stream.empty()) {
          add(errors, LinkError::short_answer,
              "an answer cut short (" + std::to_string(stream.size()) + " bytes)");
        }
        if (!damaged && stream.empty()) {
          for (std::uint8_t id : ids) {
            if (got.count(id) == 0 &&
                std::find(rejected.begin(), rejected.end(), id) == rejected.end()) {
              add(errors, LinkError::missing, "no answer from " + file_.servo_name(id), id);
            }
          }
        }
      }
    }
    return got;
  }

  void take(const dxl::Packet& p, std::span<const std::uint8_t> ids, int data_bytes,
            std::map<std::uint8_t, dxl::Packet>& got, std::vector<std::uint8_t>& rejected,
            std::vector<StepError>& errors) {
    const bool asked = std::find(ids.begin(), ids.end(), p.id) != ids.end();
    if (p.instruction != dxl::Instruction::status || p.params.empty()) {
      add(errors, LinkError::wrong_id,
          "a packet that is no status packet (ID " + std::to_string(p.id) + ")");
    } else if (!asked || got.count(p.id) == 1) {
      add(errors, LinkError::wrong_id,
          "an answer from ID " + std::to_string(p.id) + ", which was not asked");
    } else if (p.params.front() != 0) {
      add(errors, LinkError::servo_error,
          file_.servo_name(p.id) + " reports " + dxl::error_text(p.params.front()));
      rejected.push_back(p.id);
    } else if (data_bytes >= 0 && p.params.size() != 1 + static_cast<std::size_t>(data_bytes)) {
      add(errors, LinkError::short_answer,
          file_.servo_name(p.id) + " answered " + std::to_string(p.params.size() - 1) +
              " data bytes, not " + std::to_string(data_bytes));
      rejected.push_back(p.id);
    } else {
      got.emplace(p.id, p);
    }
  }

  const HardwareFile& file_;
  SerialPort port_;
  std::vector<std::uint8_t> ids_;
  std::string last_;
};

// The AMOSII board (hw/amosii.h): a motor frame and a sensor request per control step.
class AmosBus final : public Bus {
 public:
  explicit AmosBus(const HardwareFile& file)
      : file_(file), port_(file.port, file.baud, file.emulator_pid) {
    positions_.fill(amosii::kIdlePosition);
  }

  void start_check(Feedback& feedback) override {
    std::vector<StepError> errors;
    const std::optional<amosii::Ports> readings = sensors(errors);
    if (!readings) {
      throw RuntimeFailure("start-up check: the AMOSII board does not answer a sensor request (" +
                           errors.front().what + ")");
    }
    report(*readings, feedback);
  }

  void exchange(const JointCounts& counts, Feedback& feedback,
                std::vector<StepError>& errors) override {
    port_.write(motor_frame(counts));
    feedback.contacts.assign(file_.legs.size(), std::nullopt);
    if (const std::optional<amosii::Ports> readings = sensors(errors)) report(*readings, feedback);
  }

  void stop(const JointCounts& posture, StopAction /*action*/) override {
    port_.write(motor_frame(posture));  // the file refuses torque_off for the board
  }

 private:
  void report(const amosii::Ports& readings, Feedback& feedback) const {
    feedback.contacts.assign(file_.legs.size(), std::nullopt);
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      if (const std::optional<ContactInput>& c = file_.legs[i].contact) {
        feedback.contacts[i] = c->touching(readings[static_cast<std::size_t>(c->port - 1)]);
      }
    }
    if (file_.yaw.source == YawSource::board) {
      const int reading = readings[static_cast<std::size_t>(file_.yaw.board_port - 1)];
      if (reading != kRailLow && reading != kRailHigh) {
        feedback.yaw_deg = (reading - file_.yaw.zero) * file_.yaw.deg_per_count;
      }
    }
  }

  Bytes motor_frame(const JointCounts& counts) {
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        positions_[static_cast<std::size_t>(file_.legs[i].joints[j].id - 1)] =
            static_cast<std::uint8_t>(counts.legs[i][j]);
      }
    }
    if (file_.backbone) {
      positions_[static_cast<std::size_t>(file_.backbone->id - 1)] =
          static_cast<std::uint8_t>(*counts.backbone);
    }
    return amosii::motor_frame(positions_);
  }

  std::optional<amosii::Ports> sensors(std::vector<StepError>& errors) {
    prepare(port_, file_.timeout_ms);
    port_.write(amosii::sensor_request());
    const auto deadline = Clock::now() + milliseconds(file_.timeout_ms);
    Bytes frame;
    while (frame.size() < amosii::kSensorFrameBytes) {
      if (port_.read_some(frame, deadline) == 0) break;
    }
    if (frame.empty()) {
      add(errors, LinkError::timeout,
          "the board did not answer by the timeout (" + ms_text(file_.timeout_ms) + ")");
      return std::nullopt;
    }
    const amosii::SensorFrame f = amosii::parse_sensor_frame(frame);
    if (f.status == amosii::SensorStatus::short_frame) {
      add(errors, LinkError::short_answer,
          "a sensor frame of " + std::to_string(frame.size()) + " of " +
              std::to_string(amosii::kSensorFrameBytes) + " bytes");
    } else if (f.status == amosii::SensorStatus::no_end_byte) {
      add(errors, LinkError::bad_checksum, "a sensor frame without its end byte");
    } else if (frame.size() > amosii::kSensorFrameBytes) {
      add(errors, LinkError::malformed,
          std::to_string(frame.size() - amosii::kSensorFrameBytes) + " bytes after a sensor frame");
    } else {
      return f.readings;
    }
    return std::nullopt;
  }

  const HardwareFile& file_;
  SerialPort port_;
  amosii::Ports positions_{};
};

}  // namespace

JointCounts safe_posture_counts(const HardwareFile& file) {
  JointCounts c;
  for (const LegServos& leg : file.legs) {
    std::array<int, robot::kJointsPerLeg> counts{};
    for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
      counts[j] = leg.joints[j].counts(file.safe_posture[j]);
    }
    c.legs.push_back(counts);
  }
  if (file.backbone) c.backbone = file.backbone->counts(0.0);
  return c;
}

std::string_view to_string(LinkError error) {
  return kLinkErrorNames.name(error);
}

long LinkErrors::total() const {
  long sum = 0;
  for (long c : counts) sum += c;
  return sum;
}

void Bus::add(std::vector<StepError>& errors, LinkError kind, std::string what, int servo) {
  ++errors_.counts[static_cast<std::size_t>(kind)];
  errors.push_back({kind, std::move(what), servo});
  resync_ = true;
}

void Bus::prepare(SerialPort& port, int timeout_ms) {
  if (std::exchange(resync_, false)) {
    port.wait_quiet(milliseconds(timeout_ms),
                    Clock::now() + kResyncTimeouts * milliseconds(timeout_ms));
  }
  port.drop_input();
}

std::unique_ptr<Bus> open_bus(const HardwareFile& file) {
  if (file.protocol == Protocol::amosii) return std::make_unique<AmosBus>(file);
  return std::make_unique<DynamixelBus>(file);
}

YawLine::YawLine(const HardwareFile& file)
    : spec_(file.yaw), port_(file.yaw.port, file.yaw.baud, file.emulator_pid) {}

std::optional<yaw_line::Reading> YawLine::poll(std::vector<StepError>& errors) {
  const auto fail = [&](LinkError kind, std::string what) {
    ++errors_.counts[static_cast<std::size_t>(kind)];
    errors.push_back({kind, "yaw sensor: " + std::move(what), -1});
    resync_ = true;
    return std::nullopt;
  };
  if (std::exchange(resync_, false)) {
    port_.wait_quiet(milliseconds(spec_.timeout_ms),
                     Clock::now() + kResyncTimeouts * milliseconds(spec_.timeout_ms));
  }
  port_.drop_input();  // only the answer to this poll counts
  pending_.clear();
  const std::uint8_t request = yaw_line::kRequest;
  port_.write(std::span(&request, 1));
  const auto deadline = Clock::now() + milliseconds(spec_.timeout_ms);
  for (;;) {
    const yaw_line::Split s = yaw_line::next_line(pending_);
    if (s.complete) {
      if (s.too_long) return fail(LinkError::malformed, "a line longer than 80 bytes");
      const yaw_line::Line line = yaw_line::parse_line(s.text);
      if (line.status == yaw_line::LineStatus::bad_checksum) {
        return fail(LinkError::bad_checksum, "a line with a bad checksum");
      }
      if (line.status == yaw_line::LineStatus::malformed) {
        return fail(LinkError::malformed, "a line not in the yaw line's format");
      }
      if (spec_.position && !line.reading.x_m) {
        return fail(LinkError::malformed, "a YAW line where POSE lines were expected");
      }
      return line.reading;
    }
    if (port_.read_some(pending_, deadline) == 0) {
      if (pending_.empty()) {
        return fail(LinkError::timeout,
                    "no answer by the timeout (" + ms_text(spec_.timeout_ms) + ")");
      }
      return fail(LinkError::short_answer, "an answer cut short");
    }
  }
}

}  // namespace multicpg::hw
