#include "hw/yaw_line.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace multicpg::hw::yaw_line {
namespace {

constexpr std::size_t kChecksumDigits = 2;

std::optional<double> number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::vector<std::string_view> words(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    if (end == i) return {};  // two spaces in a row: not our format
    out.push_back(text.substr(i, end - i));
    i = end + 1;
    if (end < text.size() && i == text.size()) return {};  // a trailing space
  }
  return out;
}

}  // namespace

std::uint8_t checksum(std::string_view text) {
  std::uint8_t x = 0;
  for (char c : text) x ^= static_cast<std::uint8_t>(c);
  return x;
}

std::string encode(const Reading& reading, int decimals) {
  const std::string body = reading.x_m
                               ? fmt::format("POSE {:.{}f} {:.{}f} {:.{}f}", *reading.x_m, decimals,
                                             *reading.y_m, decimals, reading.yaw_deg, decimals)
                               : fmt::format("YAW {:.{}f}", reading.yaw_deg, decimals);
  return fmt::format("{}*{:02X}\r\n", body, checksum(body));
}

Line parse_line(std::string_view line) {
  Line out;
  const std::size_t star = line.find('*');
  if (star == std::string_view::npos || line.size() != star + 1 + kChecksumDigits) return out;
  unsigned sum = 0;
  const std::string_view digits = line.substr(star + 1);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), sum, 16);
  if (error != std::errc() || end != digits.data() + digits.size()) return out;
  const std::string_view body = line.substr(0, star);
  const std::vector<std::string_view> w = words(body);
  if (w.size() == 2 && w[0] == "YAW") {
    const std::optional<double> yaw = number(w[1]);
    if (!yaw) return out;
    out.reading.yaw_deg = *yaw;
  } else if (w.size() == 4 && w[0] == "POSE") {
    const std::optional<double> x = number(w[1]);
    const std::optional<double> y = number(w[2]);
    const std::optional<double> yaw = number(w[3]);
    if (!x || !y || !yaw) return out;
    out.reading = {*yaw, x, y};
  } else {
    return out;
  }
  out.status = checksum(body) == sum ? LineStatus::reading : LineStatus::bad_checksum;
  return out;
}

Split next_line(std::span<const std::uint8_t> stream) {
  Split s;
  const auto nl = std::find(stream.begin(), stream.end(), static_cast<std::uint8_t>('\n'));
  const auto length = static_cast<std::size_t>(nl - stream.begin());
  if (length >= kMaxLineBytes) {
    s.complete = s.too_long = true;
    s.consumed = kMaxLineBytes;
    s.text.assign(stream.begin(), stream.begin() + kMaxLineBytes);
    return s;
  }
  if (nl == stream.end()) return s;
  s.complete = true;
  s.consumed = length + 1;
  s.text.assign(stream.begin(), nl);
  if (!s.text.empty() && s.text.back() == '\r') s.text.pop_back();
  return s;
}

}  // namespace multicpg::hw::yaw_line
