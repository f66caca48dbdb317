#include "hw/amosii.h"

#include <algorithm>
#include <stdexcept>

namespace multicpg::hw::amosii {
namespace {

// A malformed frame is dropped up to and including the next end byte, where the next frame
// begins (or the whole stream when none has come).
std::size_t past_next_end(std::span<const std::uint8_t> stream, std::size_t from) {
  const auto end =
      std::find(stream.begin() + static_cast<std::ptrdiff_t>(from), stream.end(), kEnd);
  return end == stream.end() ? stream.size() : static_cast<std::size_t>(end - stream.begin()) + 1;
}

}  // namespace

Bytes motor_frame(const Ports& positions) {
  Bytes out{kSetMotors};
  for (std::uint8_t p : positions) {
    if (p == kEnd) throw std::invalid_argument("an AMOSII servo position cannot be 0");
    out.push_back(p);
  }
  out.push_back(kEnd);
  return out;
}

Bytes sensor_request() {
  return {kGetSensors, kEnd};
}

Bytes sensor_frame(const Ports& readings) {
  Bytes out(readings.begin(), readings.end());
  out.push_back(kEnd);
  return out;
}

SensorFrame parse_sensor_frame(std::span<const std::uint8_t> bytes) {
  SensorFrame f;
  if (bytes.size() < kSensorFrameBytes) return f;
  if (bytes[kPorts] != kEnd) {
    f.status = SensorStatus::no_end_byte;
    return f;
  }
  std::copy_n(bytes.begin(), kPorts, f.readings.begin());
  f.status = SensorStatus::ok;
  return f;
}

Command parse_command(std::span<const std::uint8_t> stream) {
  Command c;
  if (stream.empty()) return c;
  if (stream[0] == kGetSensors) {
    if (stream.size() < kRequestBytes) return c;
    c.status = stream[1] == kEnd ? CommandStatus::request : CommandStatus::malformed;
    c.consumed = stream[1] == kEnd ? kRequestBytes : past_next_end(stream, 1);
    return c;
  }
  if (stream[0] == kSetMotors) {
    // A position is never the end byte, so an early end byte is a frame cut short, and a frame
    // without one where it belongs is no frame.
    const auto end = std::find(stream.begin() + 1, stream.end(), kEnd);
    if (end == stream.end()) {
      if (stream.size() < kMotorFrameBytes) return c;  // still arriving
      c.status = CommandStatus::malformed;
      c.consumed = kMotorFrameBytes;
      return c;
    }
    const auto at = static_cast<std::size_t>(end - stream.begin());
    if (at != kMotorFrameBytes - 1) {
      c.status = CommandStatus::malformed;
      c.consumed = at + 1;
      return c;
    }
    std::copy_n(stream.begin() + 1, kPorts, c.positions.begin());
    c.status = CommandStatus::motors;
    c.consumed = kMotorFrameBytes;
    return c;
  }
  c.status = CommandStatus::malformed;
  c.consumed = past_next_end(stream, 0);
  return c;
}

}  // namespace multicpg::hw::amosii
