#include "common/checksum.h"

#include <cstdio>

namespace multicpg {
namespace {

// FNV-1a 64-bit offset basis and prime.
constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

}  // namespace

std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = kFnvOffset;
  for (char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= kFnvPrime;
  }
  return h;
}

std::string checksum_text(std::string_view text) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(text)));
  return std::string("fnv1a64:") + hex;
}

}  // namespace multicpg
