// The emulator (emulator.h): a fake robot serving the hardware file's protocol on pseudo-terminals.
#include "emulator/emulator.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <deque>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <utility>

#include "common/angles.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "hw/amosii.h"
#include "hw/bus.h"
#include "hw/dynamixel.h"
#include "hw/yaw_line.h"

namespace multicpg::emulator {
// The emulator speaks the hardware's protocols (hw/): their frames, files and ports.
using namespace hw;
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// How often the emulator looks for a signal while nobody speaks to it.
constexpr int kIdlePollMs = 100;
// PING answer: the model number of an XL430-W250 (e-Manual control table, address 0) and a
// firmware version.
constexpr std::uint16_t kModelNumber = 1060;
constexpr std::uint8_t kFirmware = 46;
// Status packet error numbers (e-Manual "Status Packet").
constexpr std::uint8_t kInstructionError = 0x02;
constexpr std::uint8_t kDataRangeError = 0x04;
constexpr std::uint8_t kDataLengthError = 0x05;
constexpr std::uint8_t kAccessError = 0x07;
// One start bit, eight data bits, one stop bit per byte on the wire.
constexpr double kBitsPerByte = 10.0;
// A board input with nothing on it reads its low rail.
constexpr std::uint8_t kRail = 0;
// Board inputs the heading spans: all but the two rails.
constexpr int kHeadingCounts = 254;

// A servo as the emulator keeps it: where it sits in the leg map, and its RAM.
struct Servo {
  int leg = -1;  // -1: the backbone
  int joint = 0;
  const ServoJoint* map = nullptr;
  std::optional<int> goal;  // counts; none until the host sets one
  bool torque = false;      // Dynamixel servos start with the torque off
  std::uint8_t mode = dxl::kPositionControlMode;
};

}  // namespace

class Emulator::Impl {
 public:
  Impl(const sim::SimModel& model, const HardwareFile& file, EmulatorSpec spec, Pty& bus, Pty& yaw,
       bool append_log)
      : model_(model),
        file_(file),
        spec_(std::move(spec)),
        bus_(bus),
        yaw_(yaw),
        state_(sim::make_sim_state(model)),
        random_(spec_.seed),
        active_(spec_.injections.size(), false) {
    for (std::size_t i = 0; i < file.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        Servo& s = servos_[file.legs[i].joints[j].id];
        s.leg = static_cast<int>(i);
        s.joint = static_cast<int>(j);
        s.map = &file.legs[i].joints[j];
      }
    }
    if (file.backbone) servos_[file.backbone->id].map = &*file.backbone;
    if (file.protocol == Protocol::amosii) {
      for (auto& [id, s] : servos_) s.torque = true;  // the board's servos always hold
    }
    board_.fill(amosii::kIdlePosition);
    posture_ = safe_posture_counts(file);
    if (!spec_.log.empty()) {
      log_.open(spec_.log, append_log ? std::ios::app : std::ios::trunc);
      if (!log_) {
        throw BadInput("cannot write the log '" + spec_.log.string() +
                       "': " + std::strerror(errno));
      }
    }
    log({{"event", "start"},
         {"bus", bus_.path},
         {"yaw", yaw_.path},
         {"protocol", to_string(file.protocol)}});
  }

  EmulatorSummary run() {
    bool bus_open = true;
    bool yaw_open = !yaw_.path.empty();
    while (bus_open) {
      check_interrupted();
      std::vector<pollfd> fds{{bus_.master, POLLIN, 0}};
      if (yaw_open) fds.push_back({yaw_.master, POLLIN, 0});
      int wait_ms = kIdlePollMs;
      if (const std::optional<Clock::duration> next = send_due()) {
        wait_ms = std::min<int>(
            wait_ms, static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(*next).count()));
      }
      const int ready = ::poll(fds.data(), fds.size(), wait_ms);
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) throw RuntimeFailure("emulator: poll failed");
      if (fds[0].revents != 0) bus_open = take(bus_, bus_in_, [this] { serve_bus(); });
      if (yaw_open && fds.size() > 1 && fds[1].revents != 0) {
        yaw_open = take(yaw_, yaw_in_, [this] { serve_yaw(); });
      }
      send_due();
      if (hangup_yaw_ && yaw_open) {
        log({{"event", "hangup"}, {"port", yaw_.path}, {"step", summary_.steps}});
        close_pty(yaw_);
        yaw_open = false;
        summary_.hung_up = true;
      }
      if (hangup_) {
        log({{"event", "hangup"}, {"port", bus_.path}, {"step", summary_.steps}});
        close_pty(bus_);
        close_pty(yaw_);
        summary_.hung_up = true;
        bus_open = false;
      }
    }
    log({{"event", "end"},
         {"steps", summary_.steps},
         {"answers", summary_.answers},
         {"malformed", summary_.malformed}});
    return summary_;
  }

 private:
  // Reads what the host sent on `pty` and serves it; false once the host has hung up.
  template <class Serve>
  bool take(Pty& pty, Bytes& in, Serve serve) {
    std::array<std::uint8_t, 512> buffer{};
    const ssize_t n = ::read(pty.master, buffer.data(), buffer.size());
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return true;
    if (n <= 0) return false;  // EIO: every slave descriptor is closed
    if (pty.slave >= 0) {
      // The host has the port open now: let its closing end the run.
      ::close(pty.slave);
      pty.slave = -1;
    }
    in.insert(in.end(), buffer.begin(), buffer.begin() + n);
    (&pty == &bus_ ? bus_inbound_ : yaw_inbound_) += static_cast<std::size_t>(n);
    serve();
    return true;
  }

  void log(nlohmann::json event) {
    if (!log_.is_open()) return;
    event["t"] = monotonic_s();
    log_ << event.dump() << "\n" << std::flush;
  }

  void refuse(const std::string& what) {
    ++summary_.malformed;
    log({{"event", "malformed"}, {"what", what}, {"step", summary_.steps}});
  }

  bool injected(Injection::Kind kind, double* value = nullptr) const {
    for (std::size_t i = 0; i < spec_.injections.size(); ++i) {
      if (active_[i] && spec_.injections[i].kind == kind) {
        if (value != nullptr) *value = spec_.injections[i].value;
        return true;
      }
    }
    return false;
  }

  bool servo_silent(int id) const {
    for (std::size_t i = 0; i < spec_.injections.size(); ++i) {
      const Injection& in = spec_.injections[i];
      if (active_[i] && in.kind == Injection::Kind::silent &&
          (file_.protocol == Protocol::amosii || static_cast<int>(in.value) == id)) {
        return true;
      }
    }
    return false;
  }

  // The time `bytes` take on the wire at `baud` (none unless asked for).
  Clock::duration wire_time(std::size_t bytes, int baud) const {
    if (!spec_.wire_time) return Clock::duration::zero();
    return std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(kBitsPerByte * static_cast<double>(bytes) / baud));
  }

  // Queues one answer for `pty`, through the injected faults: bytes lost or changed now, the
  // answer out after the latency and its bytes' wire time (commands are read meanwhile, as a bus
  // adapter's latency leaves a servo's own work alone).
  void answer(Pty& pty, Bytes bytes, int baud) {
    double value = 0.0;
    if (injected(Injection::Kind::corrupt, &value) && !bytes.empty() &&
        std::bernoulli_distribution(value)(random_)) {
      const std::size_t at =
          std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random_);
      bytes[at] ^= static_cast<std::uint8_t>(std::uniform_int_distribution<int>(1, 255)(random_));
    }
    if (injected(Injection::Kind::drop, &value)) {
      std::bernoulli_distribution lost(value);
      std::erase_if(bytes, [&](std::uint8_t) { return lost(random_); });
    }
    // The request's bytes and the answer's on the wire.
    std::size_t& inbound = &pty == &bus_ ? bus_inbound_ : yaw_inbound_;
    Clock::duration delay = wire_time(std::exchange(inbound, 0) + bytes.size(), baud);
    if (injected(Injection::Kind::latency, &value)) {
      delay += std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double, std::milli>(value));
    }
    Clock::time_point due = Clock::now() + delay;
    if (!out_.empty()) due = std::max(due, out_.back().due);  // in the order they were asked
    out_.push_back({pty.master, std::move(bytes), due});
    ++summary_.answers;
  }

  // Writes the answers that are due; the time until the next one (or none).
  std::optional<Clock::duration> send_due() {
    while (!out_.empty() && out_.front().due <= Clock::now()) {
      const Outgoing& o = out_.front();
      std::size_t done = 0;
      while (done < o.bytes.size()) {
        const ssize_t n = ::write(o.fd, o.bytes.data() + done, o.bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // the host is gone; its hang-up ends the run
        done += static_cast<std::size_t>(n);
      }
      out_.pop_front();
    }
    if (out_.empty()) return std::nullopt;
    return out_.front().due - Clock::now();
  }

  // One control step of the robot toward the servos' goals.
  void step_robot() {
    ++summary_.steps;
    for (std::size_t i = 0; i < spec_.injections.size(); ++i) {
      if (!active_[i] && spec_.injections[i].step < summary_.steps) {
        active_[i] = true;
        if (spec_.injections[i].kind == Injection::Kind::drift) drift_from_ = state_.data->time;
        hangup_ = hangup_ || spec_.injections[i].kind == Injection::Kind::hangup;
        hangup_yaw_ = hangup_yaw_ || spec_.injections[i].kind == Injection::Kind::hangup_yaw;
        log({{"event", "inject"},
             {"injection", to_string(spec_.injections[i])},
             {"step", summary_.steps}});
      }
    }
    for (const auto& [id, s] : servos_) {
      if (s.leg < 0) continue;
      const auto leg = static_cast<std::size_t>(s.leg);
      const auto joint = static_cast<std::size_t>(s.joint);
      if (s.goal) state_.targets[leg][joint] = s.map->angle(*s.goal);
      state_.faults.joints[leg][joint].servo =
          s.torque ? sim::JointCondition::Servo::driven : sim::JointCondition::Servo::passive;
    }
    sim::physics_step(model_, state_);
  }

  // The posture's counts on every mapped servo: the host commands its stop.
  void check_posture() {
    if (summary_.posture) return;
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      for (std::size_t j = 0; j < robot::kJointsPerLeg; ++j) {
        const std::optional<int>& goal = servos_.at(file_.legs[i].joints[j].id).goal;
        if (goal != posture_.legs[i][j]) return;
      }
    }
    summary_.posture = true;
    log({{"event", "posture"}, {"step", summary_.steps}});
  }

  // A joint's angle as its servo reports it: counts, within the servo's range.
  int present(const Servo& s) const {
    const double a = s.leg < 0
                         ? 0.0
                         : sim::joint_angle(model_, state_, static_cast<std::size_t>(s.leg),
                                            robot::kJoints[static_cast<std::size_t>(s.joint)]);
    const CountRange range = servo_range(file_.protocol);
    const long c = std::lround(s.map->zero + s.map->sign * a * kDegPerRad / s.map->deg_per_count);
    return static_cast<int>(std::clamp<long>(c, range.lo, range.hi));
  }

  double yaw_deg() const {
    double drift = 0.0;
    double rate = 0.0;
    if (injected(Injection::Kind::drift, &rate)) drift = rate * (state_.data->time - drift_from_);
    return wrap_degrees(sim::trunk_yaw_deg(model_, state_) + drift);
  }

  // --- the AMOSII board
  void serve_amosii() {
    for (;;) {
      const amosii::Command c = amosii::parse_command(bus_in_);
      if (c.status == amosii::CommandStatus::incomplete) return;
      bus_in_.erase(bus_in_.begin(), bus_in_.begin() + static_cast<std::ptrdiff_t>(c.consumed));
      if (c.status == amosii::CommandStatus::malformed) {
        refuse(std::to_string(c.consumed) + " bytes that are no frame of the board");
      } else if (c.status == amosii::CommandStatus::motors) {
        board_ = c.positions;
        for (auto& [id, s] : servos_) s.goal = board_[static_cast<std::size_t>(id - 1)];
        step_robot();
        check_posture();
      } else {
        if (!servo_silent(0)) answer(bus_, amosii::sensor_frame(sensors()), file_.baud);
      }
    }
  }

  amosii::Ports sensors() const {
    amosii::Ports p{};
    for (std::size_t i = 0; i < file_.legs.size(); ++i) {
      if (const std::optional<ContactInput>& c = file_.legs[i].contact) {
        p[static_cast<std::size_t>(c->port - 1)] =
            static_cast<std::uint8_t>(sim::foot_contact(model_, state_, i) ? c->on : c->off);
      }
    }
    if (file_.yaw.source == YawSource::board) {
      std::uint8_t reading = kRail;
      if (!injected(Injection::Kind::silent_yaw)) {
        const long c = std::lround(file_.yaw.zero + yaw_deg() / file_.yaw.deg_per_count);
        // A heading past the last input count wraps round to the first, as headings do.
        reading = static_cast<std::uint8_t>(
            ((c - 1) % kHeadingCounts + kHeadingCounts) % kHeadingCounts + 1);
      }
      p[static_cast<std::size_t>(file_.yaw.board_port - 1)] = reading;
    }
    return p;
  }

  // --- Dynamixel servos
  void serve_dynamixel() {
    for (;;) {
      const dxl::ParseResult r = dxl::parse(bus_in_);
      if (r.skipped > 0) refuse(std::to_string(r.skipped) + " bytes before a header");
      bus_in_.erase(bus_in_.begin(), bus_in_.begin() + static_cast<std::ptrdiff_t>(r.consumed));
      if (r.status == dxl::ParseStatus::incomplete) return;
      if (r.status == dxl::ParseStatus::bad_crc) {
        refuse("a packet with a bad CRC");
      } else if (r.status == dxl::ParseStatus::bad_length) {
        refuse("a packet with an impossible length");
      } else {
        packet(*r.packet);
      }
    }
  }

  void status(std::uint8_t id, std::uint8_t error, const Bytes& data = {}) {
    if (servo_silent(id)) return;
    answer(bus_, dxl::status(id, error, data), file_.baud);
  }

  void packet(const dxl::Packet& p) {
    const bool broadcast = p.id == dxl::kBroadcastId;
    const bool known = servos_.count(p.id) == 1;
    if (!broadcast && !known) return;  // no servo with this ID on the bus: nobody answers
    switch (p.instruction) {
      case dxl::Instruction::ping:
        for (const auto& [id, s] : servos_) {
          if (broadcast || id == p.id) {
            status(static_cast<std::uint8_t>(id), 0,
                   {static_cast<std::uint8_t>(kModelNumber & 0xFF),
                    static_cast<std::uint8_t>(kModelNumber >> 8), kFirmware});
          }
        }
        return;
      case dxl::Instruction::write:
        write(p);
        return;
      case dxl::Instruction::sync_write:
        sync_write(p);
        return;
      case dxl::Instruction::sync_read:
        sync_read(p);
        return;
      default:
        refuse("instruction " + std::to_string(static_cast<int>(p.instruction)));
        if (!broadcast) status(p.id, kInstructionError);
    }
  }

  // Writes `data` at `address` of servo `s`: the status packet's error (0: done).
  std::uint8_t poke(Servo& s, std::uint16_t address, std::span<const std::uint8_t> data) {
    if (address == dxl::kTorqueEnableAddress) {
      if (data.size() != 1) return kDataLengthError;
      if (data[0] > 1) return kDataRangeError;
      s.torque = data[0] == 1;
      return 0;
    }
    if (address == dxl::kOperatingModeAddress) {
      if (data.size() != 1) return kDataLengthError;
      if (s.torque) return kAccessError;  // EEPROM items are locked while the torque is on
      if (data[0] != dxl::kPositionControlMode) return kDataRangeError;  // only position mode
      s.mode = data[0];
      return 0;
    }
    if (address == dxl::kGoalPositionAddress) {
      if (data.size() != dxl::kPositionBytes) return kDataLengthError;
      const std::int32_t goal = dxl::position_value(data);
      if (goal < 0 || goal > dxl::kMaxPosition) return kDataRangeError;
      s.goal = goal;
      return 0;
    }
    return kAccessError;  // not an item the emulator keeps
  }

  void write(const dxl::Packet& p) {
    if (p.params.size() < 2) {
      refuse("a WRITE without an address");
      return;
    }
    const auto address = static_cast<std::uint16_t>(p.params[0] | (p.params[1] << 8));
    const std::span<const std::uint8_t> data(p.params.begin() + 2, p.params.end());
    for (auto& [id, s] : servos_) {
      if (p.id != dxl::kBroadcastId && id != p.id) continue;
      const std::uint8_t error = poke(s, address, data);
      if (error != 0)
        refuse("WRITE at " + std::to_string(address) + " of ID " + std::to_string(id));
      if (p.id != dxl::kBroadcastId) status(static_cast<std::uint8_t>(id), error);
    }
    torque_check(address);
  }

  // After a write of the torque during the run: whether every servo's torque is off now.
  void torque_check(std::uint16_t address) {
    if (address != dxl::kTorqueEnableAddress || summary_.steps == 0) return;
    if (std::none_of(servos_.begin(), servos_.end(),
                     [](const auto& s) { return s.second.torque; })) {
      if (!summary_.torque_off) log({{"event", "torque_off"}, {"step", summary_.steps}});
      summary_.torque_off = true;
    }
  }

  void sync_write(const dxl::Packet& p) {
    const std::span<const std::uint8_t> params(p.params);
    if (p.id != dxl::kBroadcastId || params.size() < 4) {
      refuse("a SYNC WRITE without address and size");
      return;
    }
    const auto address = static_cast<std::uint16_t>(params[0] | (params[1] << 8));
    const std::size_t size = params[2] | (params[3] << 8);
    if (size == 0 || (params.size() - 4) % (size + 1) != 0) {
      refuse("a SYNC WRITE whose data do not fit its size");
      return;
    }
    for (std::size_t at = 4; at < params.size(); at += size + 1) {
      const auto it = servos_.find(params[at]);
      if (it == servos_.end()) continue;
      if (poke(it->second, address, params.subspan(at + 1, size)) != 0) {
        refuse("SYNC WRITE at " + std::to_string(address) + " of ID " + std::to_string(params[at]));
      }
    }
    if (address == dxl::kGoalPositionAddress) {
      step_robot();
      check_posture();
    }
    torque_check(address);
  }

  void sync_read(const dxl::Packet& p) {
    const std::span<const std::uint8_t> params(p.params);
    if (params.size() < 4) {
      refuse("a SYNC READ without address and size");
      return;
    }
    const auto address = static_cast<std::uint16_t>(params[0] | (params[1] << 8));
    const std::size_t size = params[2] | (params[3] << 8);
    if (address != dxl::kPresentPositionAddress || size != dxl::kPositionBytes) {
      refuse("a SYNC READ of something other than the present positions");
      return;
    }
    for (std::size_t at = 4; at < params.size(); ++at) {
      const auto it = servos_.find(params[at]);
      if (it == servos_.end()) continue;
      status(params[at], 0, dxl::position_bytes(present(it->second)));
    }
  }

  void serve_bus() {
    if (file_.protocol == Protocol::amosii) {
      serve_amosii();
    } else {
      serve_dynamixel();
    }
  }

  // --- the yaw line
  void serve_yaw() {
    for (std::uint8_t b : yaw_in_) {
      if (b != yaw_line::kRequest) {
        refuse("a byte on the yaw line that is no request");
        continue;
      }
      if (injected(Injection::Kind::silent_yaw)) continue;
      yaw_line::Reading r{yaw_deg(), std::nullopt, std::nullopt};
      if (file_.yaw.position) {
        const sim::Position p = sim::trunk_position(model_, state_);
        r.x_m = p.x;
        r.y_m = p.y;
      }
      const std::string line = yaw_line::encode(r, kYawLineDecimals);
      answer(yaw_, Bytes(line.begin(), line.end()), file_.yaw.baud);
    }
    yaw_in_.clear();
  }

  const sim::SimModel& model_;
  const HardwareFile& file_;
  EmulatorSpec spec_;
  Pty& bus_;
  Pty& yaw_;
  sim::SimState state_;
  std::mt19937_64 random_;
  std::vector<bool> active_;
  double drift_from_ = 0.0;
  bool hangup_ = false;  // injected hang-ups, due now
  bool hangup_yaw_ = false;
  std::map<int, Servo> servos_;
  amosii::Ports board_{};
  JointCounts posture_;
  Bytes bus_in_;
  Bytes yaw_in_;
  struct Outgoing {
    int fd;
    Bytes bytes;
    Clock::time_point due;
  };
  std::deque<Outgoing> out_;     // answers waiting for their time
  std::size_t bus_inbound_ = 0;  // bytes the host sent since the last answer
  std::size_t yaw_inbound_ = 0;
  std::ofstream log_;
  EmulatorSummary summary_;
};

Emulator::Emulator(const sim::SimModel& model, const HardwareFile& file, EmulatorSpec spec)
    : model_(model),
      file_(file),
      spec_(std::move(spec)),
      bus_(open_pty()),
      yaw_(file.yaw.source == YawSource::line ? open_pty() : Pty{}) {
  impl_ = std::make_unique<Impl>(model_, file_, spec_, bus_, yaw_, false);
}

namespace {

// Holds the port open again (as open_pty did) so that the next host's bytes wait for it and its
// hang-up ends its run, and drops what the last host left unread.
void reopen(Pty& pty) {
  if (pty.slave < 0) {
    pty.slave = ::open(pty.path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (pty.slave < 0) throw RuntimeFailure("emulator: cannot open " + pty.path + " again");
    ::ioctl(pty.slave, TIOCNXCL);  // a host killed while it held the port exclusively
  }
  std::array<std::uint8_t, 512> buffer{};
  pollfd p{pty.master, POLLIN, 0};
  while (::poll(&p, 1, 0) > 0 && (p.revents & POLLIN) != 0 &&
         ::read(pty.master, buffer.data(), buffer.size()) > 0) {
  }
}

}  // namespace

bool Emulator::next_run() {
  if (bus_.master < 0) return false;
  impl_.reset();
  reopen(bus_);
  if (!yaw_.path.empty()) {
    if (yaw_.master < 0) return false;
    reopen(yaw_);
  }
  impl_ = std::make_unique<Impl>(model_, file_, spec_, bus_, yaw_, true);
  return true;
}

Emulator::~Emulator() {
  close_pty(bus_);
  close_pty(yaw_);
}

EmulatorSummary Emulator::run() {
  return impl_->run();
}

}  // namespace multicpg::emulator
