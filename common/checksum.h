// A checksum of text, for files that must show when they were edited or damaged: FNV-1a 64-bit
// (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/). Not cryptographic: it detects
// accidents (truncation, a changed digit), not a forger.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace multicpg {

std::uint64_t fnv1a64(std::string_view text);

// "fnv1a64:" and the 16 lower-case hex digits of fnv1a64(text).
std::string checksum_text(std::string_view text);

}  // namespace multicpg
