// The robot's side of the serial line against a scripted device on a pseudo-terminal: a malformed
// answer (cut short, a bad checksum, a servo that was not asked, an error it reports) is refused,
// counted by its kind and named (docs/hardware.md "Safety").
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <numbers>
#include <thread>

#include "hw/amosii.h"
#include "hw/bus.h"
#include "hw/dynamixel.h"
#include "hw/hardware_file.h"
#include "hw/serial_port.h"
#include "hw/yaw_line.h"
#include "robot/morphology.h"

namespace multicpg::hw {
namespace {

const std::filesystem::path kExamples =
    std::filesystem::path(MULTICPG_SOURCE_DIR) / "examples" / "hardware";
constexpr int kTimeoutMs = 300;

// Reads from `fd` until `done` says the request is whole (or a second passed).
Bytes read_request(int fd, const std::function<bool(const Bytes&)>& done) {
  Bytes in;
  const auto give_up = Clock::now() + std::chrono::seconds(1);
  while (!done(in) && Clock::now() < give_up) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    std::array<std::uint8_t, 512> b{};
    const ssize_t n = ::read(fd, b.data(), b.size());
    if (n > 0) in.insert(in.end(), b.begin(), b.begin() + n);
  }
  return in;
}

void send(int fd, const Bytes& bytes) {
  ASSERT_EQ(::write(fd, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
}

// What one step of a Dynamixel bus found.
struct Exchange {
  std::vector<StepError> errors;
  Feedback feedback;
  LinkErrors counts;
};
// What each servo sends for a SYNC READ: ID and the good answer -> the bytes sent.
using Answer = std::function<Bytes(std::uint8_t id, const Bytes& good)>;

Exchange run(const Answer& answer) {
  Exchange c;
  Pty pty = open_pty();
  HardwareFile file = load_hardware_file(kExamples / "dynamixel-hexapod.toml",
                                         robot::morphology(robot::RobotKind::hexapod));
  file.port = pty.path;
  file.timeout_ms = kTimeoutMs;
  std::unique_ptr<Bus> bus = open_bus(file);
  std::thread device([&] {
    const Bytes request = read_request(pty.master, [](const Bytes& in) {
      // Whole when the SYNC READ (the step's second packet) has come.
      std::size_t at = 0;
      for (int packets = 0; at < in.size();) {
        const dxl::ParseResult r = dxl::parse(std::span(in).subspan(at));
        if (r.status != dxl::ParseStatus::packet) return false;
        at += r.consumed;
        if (++packets == 2) return true;
      }
      return false;
    });
    Bytes answers;
    for (std::uint8_t id = 1; id <= 18; ++id) {
      const Bytes a = answer(id, dxl::status(id, 0, dxl::position_bytes(2048 + id)));
      answers.insert(answers.end(), a.begin(), a.end());
    }
    send(pty.master, answers);
  });
  JointCounts counts{std::vector<std::array<int, 3>>(6, {2048, 2048, 2048}), std::nullopt};
  bus->exchange(counts, c.feedback, c.errors);
  device.join();
  c.counts = bus->errors();
  close_pty(pty);
  return c;
}

Bytes as_is(std::uint8_t, const Bytes& good) {
  return good;
}

TEST(DynamixelLink, GoodAnswersGiveEveryJointsAngle) {
  const Exchange c = run(as_is);
  EXPECT_TRUE(c.errors.empty());
  EXPECT_EQ(c.counts.total(), 0);
  ASSERT_TRUE(c.feedback.angles[1][1]);  // R2.CTr, ID 5: count 2053, sign -1
  EXPECT_NEAR(*c.feedback.angles[1][1], -5 * 0.087890625 * std::numbers::pi / 180, 1e-12);
}

TEST(DynamixelLink, ABadCrcIsRefusedCountedAndNamed) {
  const Exchange c = run([](std::uint8_t id, const Bytes& good) {
    Bytes b = good;
    if (id == 5) b[9] ^= 0x40;
    return b;
  });
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].kind, LinkError::bad_checksum);
  EXPECT_EQ(c.errors[0].what, "bad CRC in an answer");
  EXPECT_EQ(c.counts.counts[static_cast<std::size_t>(LinkError::bad_checksum)], 1);
  EXPECT_FALSE(c.feedback.angles[1][1]);  // R2.CTr's reading is not taken
  EXPECT_TRUE(c.feedback.angles[1][0]);
}

TEST(DynamixelLink, AnAnswerFromAServoNotAskedIsRefused) {
  const Exchange c = run([](std::uint8_t id, const Bytes& good) {
    return id == 5 ? dxl::status(40, 0, dxl::position_bytes(1)) : good;
  });
  ASSERT_GE(c.errors.size(), 2u);
  EXPECT_EQ(c.errors[0].kind, LinkError::wrong_id);
  EXPECT_EQ(c.errors[0].what, "an answer from ID 40, which was not asked");
  EXPECT_EQ(c.errors[1].kind, LinkError::missing);
  EXPECT_EQ(c.errors[1].what, "no answer from R2.CTr (ID 5)");
  EXPECT_EQ(c.counts.counts[static_cast<std::size_t>(LinkError::wrong_id)], 1);
}

TEST(DynamixelLink, AnAnswerCutShortIsRefused) {
  const Exchange c = run([](std::uint8_t id, const Bytes& good) {
    return id == 18 ? Bytes(good.begin(), good.end() - 3) : good;
  });
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].kind, LinkError::short_answer);
  EXPECT_EQ(c.errors[0].what, "an answer cut short (12 bytes)");
  EXPECT_FALSE(c.feedback.angles[5][2]);
}

TEST(DynamixelLink, AServosErrorAndAWrongLengthAreNamed) {
  const Exchange c = run([](std::uint8_t id, const Bytes& good) {
    if (id == 5) return dxl::status(5, 0x80, dxl::position_bytes(7));
    if (id == 6) return dxl::status(6, 0, Bytes{0x01, 0x02});
    return good;
  });
  ASSERT_EQ(c.errors.size(), 2u);
  EXPECT_EQ(c.errors[0].kind, LinkError::servo_error);
  EXPECT_EQ(c.errors[0].what, "R2.CTr (ID 5) reports hardware alert");
  EXPECT_EQ(c.errors[1].kind, LinkError::short_answer);
  EXPECT_EQ(c.errors[1].what, "R2.FTi (ID 6) answered 2 data bytes, not 4");
}

TEST(DynamixelLink, SilenceIsATimeout) {
  const Exchange c = run([](std::uint8_t, const Bytes&) { return Bytes{}; });
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0].kind, LinkError::timeout);
  EXPECT_EQ(c.errors[0].what, "no answer by the timeout (300 ms)");
}

// The AMOSII board answering one step's sensor request with `frame`.
std::vector<StepError> amosii_step(const Bytes& frame) {
  Pty pty = open_pty();
  HardwareFile file =
      load_hardware_file(kExamples / "amosii.toml", robot::morphology(robot::RobotKind::hexapod));
  file.port = pty.path;
  file.timeout_ms = kTimeoutMs;
  std::unique_ptr<Bus> bus = open_bus(file);
  std::thread board([&] {
    read_request(pty.master, [](const Bytes& in) {
      return in.size() == amosii::kMotorFrameBytes + amosii::kRequestBytes;
    });
    send(pty.master, frame);
  });
  std::vector<StepError> errors;
  Feedback feedback;
  JointCounts counts{std::vector<std::array<int, 3>>(6, {128, 128, 128}), 126};
  bus->exchange(counts, feedback, errors);
  board.join();
  close_pty(pty);
  return errors;
}

TEST(AmosiiLink, ShortFramesAndMissingEndBytesAreRefused) {
  amosii::Ports readings{};
  readings.fill(100);
  Bytes frame = amosii::sensor_frame(readings);
  EXPECT_TRUE(amosii_step(frame).empty());
  const std::vector<StepError> cut = amosii_step(Bytes(frame.begin(), frame.begin() + 20));
  ASSERT_EQ(cut.size(), 1u);
  EXPECT_EQ(cut[0].kind, LinkError::short_answer);
  EXPECT_EQ(cut[0].what, "a sensor frame of 20 of 33 bytes");
  frame.back() = 9;
  const std::vector<StepError> no_end = amosii_step(frame);
  ASSERT_EQ(no_end.size(), 1u);
  EXPECT_EQ(no_end[0].kind, LinkError::bad_checksum);
  EXPECT_EQ(no_end[0].what, "a sensor frame without its end byte");
}

// The yaw line answering one poll with `line`.
std::pair<std::optional<yaw_line::Reading>, std::vector<StepError>> yaw_poll(
    const std::string& line) {
  Pty pty = open_pty();
  HardwareFile file = load_hardware_file(kExamples / "dynamixel-hexapod.toml",
                                         robot::morphology(robot::RobotKind::hexapod));
  file.yaw.port = pty.path;
  file.yaw.timeout_ms = kTimeoutMs;
  YawLine yaw(file);
  std::thread sensor([&] {
    const Bytes poll = read_request(pty.master, [](const Bytes& in) { return !in.empty(); });
    EXPECT_EQ(poll, Bytes{yaw_line::kRequest});
    send(pty.master, Bytes(line.begin(), line.end()));
  });
  std::vector<StepError> errors;
  const std::optional<yaw_line::Reading> r = yaw.poll(errors);
  sensor.join();
  close_pty(pty);
  return {r, errors};
}

TEST(YawLineLink, OnlyWholeCheckedLinesAreReadings) {
  const auto good = yaw_poll(yaw_line::encode({-3.25, std::nullopt, std::nullopt}, 2));
  ASSERT_TRUE(good.first);
  EXPECT_DOUBLE_EQ(good.first->yaw_deg, -3.25);
  const auto bad = yaw_poll("YAW -3.25*00\r\n");
  EXPECT_FALSE(bad.first);
  ASSERT_EQ(bad.second.size(), 1u);
  EXPECT_EQ(bad.second[0].what, "yaw sensor: a line with a bad checksum");
  const auto cut = yaw_poll("YAW -3.2");
  ASSERT_EQ(cut.second.size(), 1u);
  EXPECT_EQ(cut.second[0].kind, LinkError::short_answer);
  const auto junk = yaw_poll("HELLO*00\r\n");
  ASSERT_EQ(junk.second.size(), 1u);
  EXPECT_EQ(junk.second[0].what, "yaw sensor: a line not in the yaw line's format");
}

}  // namespace
}  // namespace multicpg::hw
