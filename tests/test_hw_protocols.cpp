// The serial protocols and the hardware file without a port: known commands give known bytes, and
// bytes that are no frame are told apart (docs/hardware.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "common/errors.h"
#include "hw/amosii.h"
#include "hw/bus.h"
#include "hw/dynamixel.h"
#include "hw/hardware_file.h"
#include "hw/yaw_line.h"
#include "robot/joint_map.h"
#include "robot/morphology.h"
#include "tests/cli_runner.h"

namespace multicpg::hw {
namespace {

using testing::count_lines;
using testing::expect_bad_input;
using testing::make_temp_dir;

const std::filesystem::path kExamples = std::filesystem::path(MULTICPG_SOURCE_DIR) / "examples";
const std::filesystem::path kAmosii = kExamples / "hardware" / "amosii.toml";
const std::filesystem::path kDynamixel = kExamples / "hardware" / "dynamixel-hexapod.toml";

std::string fmt_hex(std::uint8_t value) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  return {kDigits[value >> 4], kDigits[value & 0xF]};
}

Bytes bytes(std::initializer_list<int> values) {
  Bytes out;
  for (int v : values) out.push_back(static_cast<std::uint8_t>(v));
  return out;
}

const robot::Morphology& hexapod() {
  return robot::morphology(robot::RobotKind::hexapod);
}

// --- Dynamixel Protocol 2.0: the e-Manual's example packets, byte for byte

TEST(Dynamixel, CrcIsTheProtocolsCrc16) {
  // CRC-16 with polynomial 0x8005, initial 0, not reflected: its check value over "123456789".
  const std::string text = "123456789";
  EXPECT_EQ(dxl::crc16(Bytes(text.begin(), text.end())), 0xFEE8);
}

TEST(Dynamixel, PingAndItsStatusAreTheManualsExample) {
  EXPECT_EQ(dxl::ping(1), bytes({0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x03, 0x00, 0x01, 0x19, 0x4E}));
  EXPECT_EQ(
      dxl::status(1, 0, bytes({0x06, 0x04, 0x26})),
      bytes({0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x07, 0x00, 0x55, 0x00, 0x06, 0x04, 0x26, 0x65, 0x5D}));
}

TEST(Dynamixel, WriteOfAGoalPositionIsTheManualsExample) {
  EXPECT_EQ(dxl::write(1, dxl::kGoalPositionAddress, dxl::position_bytes(512)),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x09, 0x00, 0x03, 0x74, 0x00, 0x00, 0x02, 0x00,
                   0x00, 0xCA, 0x89}));
  EXPECT_EQ(dxl::status(1, 0, {}),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x04, 0x00, 0x55, 0x00, 0xA1, 0x0C}));
}

TEST(Dynamixel, SyncReadOfPresentPositionsIsTheManualsExample) {
  const std::uint8_t ids[] = {1, 2};
  EXPECT_EQ(dxl::sync_read(dxl::kPresentPositionAddress, dxl::kPositionBytes, ids),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0xFE, 0x09, 0x00, 0x82, 0x84, 0x00, 0x04, 0x00, 0x01,
                   0x02, 0xCE, 0xFA}));
  EXPECT_EQ(dxl::status(1, 0, dxl::position_bytes(166)),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x08, 0x00, 0x55, 0x00, 0xA6, 0x00, 0x00, 0x00,
                   0x8C, 0xC0}));
  EXPECT_EQ(dxl::status(2, 0, dxl::position_bytes(2079)),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0x02, 0x08, 0x00, 0x55, 0x00, 0x1F, 0x08, 0x00, 0x00,
                   0xBA, 0xBE}));
}

TEST(Dynamixel, SyncWriteOfGoalPositionsIsTheManualsExample) {
  EXPECT_EQ(dxl::sync_write(dxl::kGoalPositionAddress, dxl::kPositionBytes,
                            {{1, dxl::position_bytes(150)}, {2, dxl::position_bytes(170)}}),
            bytes({0xFF, 0xFF, 0xFD, 0x00, 0xFE, 0x11, 0x00, 0x83, 0x74, 0x00, 0x04, 0x00,
                   0x01, 0x96, 0x00, 0x00, 0x00, 0x02, 0xAA, 0x00, 0x00, 0x00, 0x82, 0x87}));
}

TEST(Dynamixel, ByteStuffingHidesTheHeaderAndParsingRemovesIt) {
  const Bytes data = bytes({0xFF, 0xFF, 0xFD, 0x01});
  const Bytes packet = dxl::write(7, 200, data);
  // instruction, address (2), data with one stuffed 0xFD, CRC: length 3 + 2 + 5 = 10
  EXPECT_EQ(packet[5], 10);
  const Bytes stuffed = bytes({0xC8, 0x00, 0xFF, 0xFF, 0xFD, 0xFD, 0x01});
  EXPECT_TRUE(std::search(packet.begin(), packet.end(), stuffed.begin(), stuffed.end()) !=
              packet.end());
  const dxl::ParseResult r = dxl::parse(packet);
  ASSERT_EQ(r.status, dxl::ParseStatus::packet);
  EXPECT_EQ(r.packet->params, bytes({0xC8, 0x00, 0xFF, 0xFF, 0xFD, 0x01}));
  EXPECT_EQ(dxl::unstuff(dxl::stuff(bytes({0xFF, 0xFF, 0xFD, 0xFD}))),
            bytes({0xFF, 0xFF, 0xFD, 0xFD}));
}

TEST(Dynamixel, ParsingTellsNoiseCutsAndBadCrcs) {
  Bytes stream = bytes({0x12, 0x34});
  const Bytes status = dxl::status(3, 0, dxl::position_bytes(2048));
  stream.insert(stream.end(), status.begin(), status.end());
  dxl::ParseResult r = dxl::parse(stream);
  EXPECT_EQ(r.status, dxl::ParseStatus::packet);
  EXPECT_EQ(r.skipped, 2u);
  EXPECT_EQ(r.consumed, stream.size());
  EXPECT_EQ(r.packet->id, 3);
  EXPECT_EQ(dxl::position_value(std::span(r.packet->params).subspan(1)), 2048);

  r = dxl::parse(std::span(status).first(status.size() - 1));
  EXPECT_EQ(r.status, dxl::ParseStatus::incomplete);
  EXPECT_EQ(r.consumed, 0u);

  Bytes bad = status;
  bad[9] ^= 0x01;
  r = dxl::parse(bad);
  EXPECT_EQ(r.status, dxl::ParseStatus::bad_crc);
  EXPECT_EQ(r.consumed, bad.size());

  Bytes short_length = status;
  short_length[5] = 2;  // less than instruction and CRC
  EXPECT_EQ(dxl::parse(short_length).status, dxl::ParseStatus::bad_length);
  EXPECT_EQ(dxl::error_text(0x80), "hardware alert");
  EXPECT_EQ(dxl::error_text(0x03), "CRC error");
}

// --- The AMOSII board as lpzrobots' AmosIISerialV2 speaks to it

TEST(Amosii, FramesHaveTheBoardsLayout) {
  amosii::Ports ports{};
  for (int i = 0; i < amosii::kPorts; ++i)
    ports[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i + 1);
  const Bytes motors = amosii::motor_frame(ports);
  ASSERT_EQ(motors.size(), 34u);
  EXPECT_EQ(motors.front(), 1);
  EXPECT_EQ(motors[22], 22);  // port 22 (R1's TC in the authors' wiring) is byte 22
  EXPECT_EQ(motors.back(), 0);
  EXPECT_EQ(amosii::sensor_request(), bytes({2, 0}));
  ports[5] = 0;
  EXPECT_THROW(amosii::motor_frame(ports), std::invalid_argument);
}

TEST(Amosii, SensorFramesAreCheckedByTheirEndByte) {
  amosii::Ports readings{};
  readings[12] = 200;  // input 13: R1's foot
  Bytes frame = amosii::sensor_frame(readings);
  ASSERT_EQ(frame.size(), 33u);
  const amosii::SensorFrame ok = amosii::parse_sensor_frame(frame);
  EXPECT_EQ(ok.status, amosii::SensorStatus::ok);
  EXPECT_EQ(ok.readings[12], 200);
  EXPECT_EQ(amosii::parse_sensor_frame(std::span(frame).first(20)).status,
            amosii::SensorStatus::short_frame);
  frame.back() = 7;
  EXPECT_EQ(amosii::parse_sensor_frame(frame).status, amosii::SensorStatus::no_end_byte);
}

TEST(Amosii, TheBoardReadsCommandsStrictly) {
  amosii::Ports ports;
  ports.fill(128);
  Bytes stream = amosii::motor_frame(ports);
  const Bytes request = amosii::sensor_request();
  stream.insert(stream.end(), request.begin(), request.end());
  amosii::Command c = amosii::parse_command(stream);
  EXPECT_EQ(c.status, amosii::CommandStatus::motors);
  EXPECT_EQ(c.consumed, 34u);
  c = amosii::parse_command(std::span(stream).subspan(34));
  EXPECT_EQ(c.status, amosii::CommandStatus::request);
  EXPECT_EQ(amosii::parse_command(std::span(stream).first(20)).status,
            amosii::CommandStatus::incomplete);
  // A frame cut short by an end byte, and an unknown command byte: refused up to the end byte.
  const Bytes cut = bytes({1, 5, 6, 0, 2, 0});
  c = amosii::parse_command(cut);
  EXPECT_EQ(c.status, amosii::CommandStatus::malformed);
  EXPECT_EQ(c.consumed, 4u);
  c = amosii::parse_command(bytes({9, 9, 0}));
  EXPECT_EQ(c.status, amosii::CommandStatus::malformed);
  EXPECT_EQ(c.consumed, 3u);
}

// The example file sends, for the controller's commands -1 and +1, the bytes the authors' code
// sends to the same servo (lpzrobots, amosIIserialv2.cpp setMotors: servoPosMin, servoPosMax).
TEST(Amosii, TheExampleFileSendsTheAuthorsBytes) {
  struct Expected {
    std::size_t leg;
    robot::Joint joint;
    int port, at_minus_one, at_plus_one;
  };
  using robot::Joint;
  const Expected authors[] = {
      {0, Joint::TC, 22, 243, 6},   {1, Joint::TC, 26, 243, 6},   {2, Joint::TC, 12, 243, 6},
      {3, Joint::TC, 21, 9, 243},   {4, Joint::TC, 29, 9, 243},   {5, Joint::TC, 11, 9, 243},
      {0, Joint::CTr, 23, 6, 250},  {1, Joint::CTr, 30, 250, 6},  {2, Joint::CTr, 13, 250, 6},
      {3, Joint::CTr, 19, 250, 6},  {4, Joint::CTr, 28, 6, 250},  {5, Joint::CTr, 9, 6, 250},
      {0, Joint::FTi, 24, 180, 10}, {1, Joint::FTi, 25, 61, 241}, {2, Joint::FTi, 14, 60, 243},
      {3, Joint::FTi, 20, 75, 245}, {4, Joint::FTi, 27, 186, 7},  {5, Joint::FTi, 10, 189, 6}};
  const HardwareFile file = load_hardware_file(kAmosii, hexapod());
  for (const Expected& e : authors) {
    const ServoJoint& servo = file.legs[e.leg].joints[static_cast<std::size_t>(e.joint)];
    const robot::LegType type = hexapod().legs[e.leg].type;
    EXPECT_EQ(servo.id, e.port);
    EXPECT_EQ(servo.counts(robot::joint_angle(type, e.joint, -1.0)), e.at_minus_one)
        << file.legs[e.leg].name << "." << robot::to_string(e.joint);
    EXPECT_EQ(servo.counts(robot::joint_angle(type, e.joint, 1.0)), e.at_plus_one)
        << file.legs[e.leg].name << "." << robot::to_string(e.joint);
  }
  ASSERT_TRUE(file.backbone);
  EXPECT_EQ(file.backbone->counts(0.0), 126);  // the middle of the authors' 250..1
}

// --- The yaw line

TEST(YawLine, LinesCarryAnXorChecksum) {
  const yaw_line::Reading yaw{-12.345, std::nullopt, std::nullopt};
  const std::string line = yaw_line::encode(yaw, 2);
  EXPECT_EQ(line, "YAW -12.35*" + std::string(fmt_hex(yaw_line::checksum("YAW -12.35"))) + "\r\n");
  const yaw_line::Line back = yaw_line::parse_line(line.substr(0, line.size() - 2));
  EXPECT_EQ(back.status, yaw_line::LineStatus::reading);
  EXPECT_DOUBLE_EQ(back.reading.yaw_deg, -12.35);
  EXPECT_FALSE(back.reading.x_m);

  const yaw_line::Line pose =
      yaw_line::parse_line("POSE 1.5 -0.25 30*" + fmt_hex(yaw_line::checksum("POSE 1.5 -0.25 30")));
  EXPECT_EQ(pose.status, yaw_line::LineStatus::reading);
  EXPECT_DOUBLE_EQ(*pose.reading.x_m, 1.5);
  EXPECT_DOUBLE_EQ(*pose.reading.y_m, -0.25);

  EXPECT_EQ(yaw_line::parse_line("YAW 1.00*00").status, yaw_line::LineStatus::bad_checksum);
  for (const char* bad :
       {"YAW 1.00", "YAW x*00", "YAW  1*00", "ROLL 1*00", "YAW nan*00", "YAW 1*0", "POSE 1 2*00"}) {
    EXPECT_EQ(yaw_line::parse_line(bad).status, yaw_line::LineStatus::malformed) << bad;
  }
  const std::string two = "YAW 1*7A\r\nYAW 2";
  const yaw_line::Split s = yaw_line::next_line(Bytes(two.begin(), two.end()));
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(s.text, "YAW 1*7A");
  EXPECT_EQ(s.consumed, 10u);
}

// --- The hardware file

TEST(HardwareFile, TheExamplesLoad) {
  const HardwareFile d = load_hardware_file(kDynamixel, hexapod());
  EXPECT_EQ(d.protocol, Protocol::dynamixel);
  EXPECT_EQ(d.legs.size(), 6u);
  EXPECT_EQ(d.legs[1].joints[1].id, 5);
  EXPECT_EQ(d.servo_name(5), "R2.CTr (ID 5)");
  EXPECT_EQ(d.legs[0].joints[0].counts(0.0), 2048);
  EXPECT_FALSE(d.senses_position());
  const HardwareFile a = load_hardware_file(kAmosii, hexapod());
  EXPECT_EQ(a.protocol, Protocol::amosii);
  EXPECT_EQ(a.yaw.source, YawSource::board);
  EXPECT_EQ(a.legs[0].contact->port, 13);
  // Targets are clamped to the limits before they become counts.
  EXPECT_EQ(d.legs[0].joints[0].counts(2.0),
            d.legs[0].joints[0].counts(70.0 * std::numbers::pi / 180));
}

// Writes the Dynamixel example with `from` replaced by `to` (once) into a scratch folder.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = testing::read_file(kDynamixel.string());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string path = make_temp_dir("multicpg-hw-") + "/robot.toml";
  std::ofstream(path) << text;
  return path;
}

TEST(HardwareFile, EveryMistakeIsOneLineNamingFileAndKey) {
  struct Case {
    std::string from, to, mentions;
  };
  const Case cases[] = {
      {"FTi = { id = 3, sign = -1, zero = 2048, limits_deg = [-130, -20] }", "",
       "legs[0].FTi: missing"},
      {"{ id = 5,", "{ id = 4,", "legs[1].CTr.id: ID 4 is also legs[1].TC's"},
      {"limits_deg = [-75, 75] }", "limits_deg = [-75, 190] }",
       "outside the servo's range 0..4095"},
      {"{ id = 1,", "{ id = \"one\",", "legs[0].TC.id: must be an integer"},
      {"sign = 1, zero = 2048, limits_deg = [-70, 70]",
       "sign = 2, zero = 2048, limits_deg = [-70, 70]", "must be 1 or -1"},
      {"protocol = \"dynamixel\"", "protocol = \"can\"", "protocol: 'can' (amosii or dynamixel)"},
      {"baud = 1000000", "baud = 1000001", "baud: baud 1000001 is not a termios rate"},
      {"source = \"line\"", "source = \"board\"", "yaw.source: 'board': only an AMOSII board"},
      {"TC = 0, CTr = -60", "TC = 80, CTr = -60",
       "stop.posture_deg.TC: 80 deg is outside R1.TC's limits"},
      {"name = \"R2\"", "name = \"L2\"", "legs[1].name: 'L2', expected 'R2'"},
      {"max_errors = 3", "max_errors = 3\nmax_error = 4", "max_error: unknown key on line"},
      // As a mistyped flag: the line, and the key meant.
      {"max_errors = 3", "max_errors = 3\ntimout_ms = 4",
       "timout_ms: unknown key on line 13 (did you mean timeout_ms?)"},
      {"timeout_ms = 20\nmax", "timeout_ms = 0\nmax", "timeout_ms: must be in 1..10000, got 0"},
  };
  for (const Case& c : cases) {
    const std::string path = edited(c.from, c.to);
    try {
      load_hardware_file(path, hexapod());
      ADD_FAILURE() << "accepted: " << c.to;
    } catch (const BadInput& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(c.mentions), std::string::npos) << what;
      EXPECT_EQ(count_lines(what), 1) << what;
    }
    std::filesystem::remove_all(std::filesystem::path(path).parent_path());
  }
  try {
    load_hardware_file(kAmosii, robot::morphology(robot::RobotKind::quadruped));
    ADD_FAILURE() << "a hexapod's file for the quadruped";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("legs: 6 legs; the quadruped has 4"), std::string::npos);
  }
}

TEST(HardwareFile, CommandsRefuseABadFileBeforeAnythingMoves) {
  const std::string unmapped =
      edited("FTi = { id = 3, sign = -1, zero = 2048, limits_deg = [-130, -20] }", "");
  expect_bad_input("walk --hardware " + unmapped, "legs[0].FTi: missing");
  expect_bad_input("learn --mode paper --disable R1 --hardware " + unmapped,
                   "legs[0].FTi: missing");
  expect_bad_input("tunnel --learn --mode paper --disable R1 --hardware " + unmapped,
                   "legs[0].FTi: missing");
  expect_bad_input("emulate --hardware " + unmapped, "legs[0].FTi: missing");
  // As every missing input file reads (common/input_file.h).
  expect_bad_input("walk --hardware /nonexistent/robot.toml",
                   "/nonexistent/robot.toml: cannot read (No such file or directory)");
  expect_bad_input("walk --lock-step", "--lock-step needs --hardware");
  // What the hardware cannot do: a fault of a real robot's physics, robust mode without position.
  expect_bad_input("walk --fault R2.CTr:locked@0 --hardware " + kDynamixel.string(),
                   "on hardware only the paper's leg fault");
  expect_bad_input("learn --disable R1 --hardware " + kDynamixel.string(),
                   "--mode: robust mode judges the trunk's path");
  expect_bad_input("emulate --protocol amosii --hardware " + kDynamixel.string(),
                   "speaks dynamixel");
  expect_bad_input("emulate --inject silent=40@3 --hardware " + kDynamixel.string(),
                   "no servo of the hardware file has ID 40");
  expect_bad_input("emulate --inject wobble@3 --hardware " + kDynamixel.string(),
                   "KIND[=VALUE]@STEP");
  std::filesystem::remove_all(std::filesystem::path(unmapped).parent_path());
}

}  // namespace
}  // namespace multicpg::hw
