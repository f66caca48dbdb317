// The documented range of a numeric option, checked in one place: validate()
// functions of option structs check through require_in, the CLI shows the same range in --help
// and checks it at parse time, experiment files report it with file, line and key.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

#include "common/errors.h"

namespace multicpg {

// A closed interval [lo, hi].
template <class T>
struct Limits {
  T lo;
  T hi;
  bool contains(T value) const {
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value)) return false;
    }
    return value >= lo && value <= hi;
  }
  // "0..100", as --help and error messages show it.
  std::string text() const { return fmt::format("{}..{}", lo, hi); }
};

// Seeds a user gives (--seed, an experiment's `seed`): the 32-bit range NumPy's seeds have, written
// out the same in --help, errors and docs/cli.md. The seed each run of an experiment derives from
// it and its name (experiments/runner.h) uses all 64 bits.
inline constexpr Limits<std::uint64_t> kSeedLimits{0, 4'294'967'295};

// Throws OptionError(key, "must be in lo..hi, got value") unless `limits` contains `value`
// (NaN and infinities never are).
template <class T>
void require_in(const std::string& key, T value, const Limits<T>& limits) {
  if (!limits.contains(value)) {
    throw OptionError(key, fmt::format("must be in {}, got {}", limits.text(), value));
  }
}

}  // namespace multicpg

namespace multicpg {

// Runs `check` (a validate() of a nested option struct) and prefixes the key of any OptionError
// it throws with `prefix` ("annealing" + "beta" -> "annealing.beta").
template <class Check>
void within(const std::string& prefix, Check&& check) {
  try {
    check();
  } catch (const OptionError& e) {
    throw OptionError(prefix + "." + e.key(), e.what());
  }
}

}  // namespace multicpg
