#include "hw/bytes.h"

#include <fmt/format.h>

namespace multicpg::hw {

std::string hex(std::span<const std::uint8_t> bytes) {
  std::string out;
  for (std::uint8_t b : bytes) out += fmt::format("{}{:02X}", out.empty() ? "" : " ", b);
  return out;
}

}  // namespace multicpg::hw
