// The orientation sensor on a serial line of its own (docs/hardware.md "The yaw line"): our
// format, for an IMU behind a microcontroller that answers polls. The host sends the request
// byte 'Y'; the sensor answers one ASCII line
//   YAW <deg>*<cs>\r\n            or   POSE <x m> <y m> <yaw deg>*<cs>\r\n
// where <cs> is two hex digits, the XOR of every byte before '*' (as NMEA 0183 sentences check
// theirs). POSE lines come from a sensor that also knows the trunk's position (motion capture),
// which robust learning needs. Pure functions, testable without a port.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace multicpg::hw::yaw_line {

inline constexpr std::uint8_t kRequest = 'Y';
// Longest line accepted, end of line included: "POSE" and three numbers of up to 20 characters.
inline constexpr std::size_t kMaxLineBytes = 80;

struct Reading {
  double yaw_deg = 0.0;
  std::optional<double> x_m;  // both or neither (a POSE line)
  std::optional<double> y_m;
  bool operator==(const Reading&) const = default;
};

// The line for `reading` with `decimals` digits after the point, "\r\n" included.
std::string encode(const Reading& reading, int decimals);

// The XOR of `text`'s bytes.
std::uint8_t checksum(std::string_view text);

enum class LineStatus {
  reading,       // a well-formed line
  bad_checksum,  // well-formed, but its checksum does not match
  malformed,     // no '*', an unknown word, a number missing, not finite or with trailing text
};
struct Line {
  LineStatus status = LineStatus::malformed;
  Reading reading;
};
// One line without its end of line.
Line parse_line(std::string_view line);

// The first line of a byte stream: its text (without "\r\n") once a '\n' has come, and the bytes
// it took. A line longer than kMaxLineBytes is returned cut at that length, marked too_long.
struct Split {
  bool complete = false;
  bool too_long = false;
  std::size_t consumed = 0;
  std::string text;
};
Split next_line(std::span<const std::uint8_t> stream);

}  // namespace multicpg::hw::yaw_line
