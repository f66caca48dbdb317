// The AMOSII board's serial protocol as the paper's authors' public code speaks it
// (docs/hardware.md "The AMOSII board"; lpzrobots, real_robots/robots/amosii/amosIIserialv2.cpp,
// class AmosIISerialV2): 57,600 baud 8N1, one byte per board port, 0 as the frame's end byte, no
// checksum. Pure functions: frames in, bytes out and back, testable without a port.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "hw/bytes.h"

namespace multicpg::hw::amosii {

inline constexpr int kBaud = 57'600;
// The board has 32 ports (1..32): servo outputs in a motor frame, analogue inputs in a sensor
// frame, one byte each.
inline constexpr int kPorts = 32;
using Ports = std::array<std::uint8_t, kPorts>;  // [0] = port 1

inline constexpr std::uint8_t kSetMotors = 1;   // command byte of a motor frame
inline constexpr std::uint8_t kGetSensors = 2;  // command byte of a sensor request
inline constexpr std::uint8_t kEnd = 0;         // every frame's last byte
// Motor frame: command, the 32 ports' positions, end. Sensor request: command, end. Sensor frame
// (the board's answer): the 32 ports' readings, end.
inline constexpr std::size_t kMotorFrameBytes = 1 + kPorts + 1;
inline constexpr std::size_t kRequestBytes = 2;
inline constexpr std::size_t kSensorFrameBytes = kPorts + 1;
// A servo position is a byte other than the end byte; the authors' code starts every port at 128
// and sends that to ports without a servo.
inline constexpr std::uint8_t kMinPosition = 1;
inline constexpr std::uint8_t kMaxPosition = 255;
inline constexpr std::uint8_t kIdlePosition = 128;

// A motor frame of `positions`; throws std::invalid_argument for a position of 0 (the end byte).
Bytes motor_frame(const Ports& positions);
Bytes sensor_request();
// The board's answer (the emulator's): `readings`, then the end byte.
Bytes sensor_frame(const Ports& readings);

// The board's answer read back: its readings when the frame is whole and ends in the end byte.
enum class SensorStatus { ok, short_frame, no_end_byte };
struct SensorFrame {
  SensorStatus status = SensorStatus::short_frame;
  Ports readings{};
};
SensorFrame parse_sensor_frame(std::span<const std::uint8_t> bytes);

// The host's frames as the board (the emulator) reads them from its stream.
enum class CommandStatus {
  motors,      // a whole motor frame
  request,     // a sensor request
  incomplete,  // more bytes are needed
  malformed,   // an unknown command byte, or a frame not closed by the end byte
};
struct Command {
  CommandStatus status = CommandStatus::incomplete;
  std::size_t consumed = 0;  // bytes of the stream taken (for malformed: up to the next end byte)
  Ports positions{};         // motors
};
Command parse_command(std::span<const std::uint8_t> stream);

}  // namespace multicpg::hw::amosii
