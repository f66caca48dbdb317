// Portable random draws: the same numbers on every machine and standard library (std's
// distributions are not specified bit for bit), so a seed gives the same run everywhere.
#pragma once

#include <cstdint>
#include <random>
#include <stdexcept>

namespace multicpg {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a well-mixed 64-bit value for each input,
// for seeds derived from other seeds and keys.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// SplitMix64 as a stream: the next 64-bit draw from `state`, which it advances.
constexpr std::uint64_t splitmix64_next(std::uint64_t& state) {
  const std::uint64_t out = splitmix64(state);
  state += 0x9e3779b97f4a7c15ULL;
  return out;
}

// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw: every value exact.
constexpr double unit_from_bits(std::uint64_t bits) {
  constexpr int kDropBits = 64 - 53;
  return static_cast<double>(bits >> kDropBits) * 0x1.0p-53;
}

// Uniform integer in [0, n), n >= 1: rejection on the raw 64-bit output (no modulo bias).
inline std::uint64_t draw_below(std::mt19937_64& rng, std::uint64_t n) {
  if (n == 0) throw std::logic_error("draw_below(0)");
  // Outputs below 2^64 mod n are rejected, so the rest splits into n classes of equal size.
  const std::uint64_t reject_below = (0 - n) % n;
  for (;;) {
    const std::uint64_t x = rng();
    if (x >= reject_below) return x % n;
  }
}

// Uniform double in [0, 1) from one output of `rng`.
inline double draw_unit(std::mt19937_64& rng) {
  return unit_from_bits(rng());
}

}  // namespace multicpg
