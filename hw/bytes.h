// Bytes on a serial line, as the protocols of this folder encode and decode them.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace multicpg::hw {

using Bytes = std::vector<std::uint8_t>;

// "FF FF FD 00": upper-case hex pairs, for messages and golden tests.
std::string hex(std::span<const std::uint8_t> bytes);

}  // namespace multicpg::hw
