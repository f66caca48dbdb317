// The bounds of an experiment (docs/experiments.md "Experiment files"), in one place: an experiment
// file or an in-memory document (Python) is measured against them before it is parsed further or
// any run is allocated, so no file, however large, deep or wide, can crash the process or exhaust
// its memory. Each is refused with one line naming what exceeds which limit (exit 2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/limits.h"

namespace multicpg::experiments {

// Bytes of an experiment file. The paper's experiments take under 2 kB; 1 MiB leaves room for
// any hand-written sweep and bounds the time and memory of parsing (under 0.1 s, a few MB).
inline constexpr std::size_t kMaxExperimentFileBytes = std::size_t{1} << 20;
inline constexpr std::string_view kMaxExperimentFileText = "1 MiB";

// Levels of nesting: each table, dotted-key part, list and inline table one level. The deepest
// option is 6 levels (scenarios[i].faults[j].legs[k]); toml++ bounds lists and inline tables
// (at 256) but follows tables and dotted keys without a bound, recursing as deep when it frees
// them, which a deep enough file turns into a stack overflow.
inline constexpr int kMaxExperimentDepth = 64;

// Values in one list (a grid axis, a list option, the scenarios): ten thousand is far more than
// any sweep needs and keeps a list from costing more than milliseconds to check.
inline constexpr std::size_t kMaxListValues = 10'000;

// Runs of one experiment: grid points x scenarios x runs, or a landscape's combinations. Every
// run holds about 9 kB of options from the moment the experiment is resolved (docs/
// benchmarks.md), so 10^5 runs take about 1 GB and 25 s to check; that is 400 times the paper's
// largest experiment (240 runs) and weeks of computing. --max-runs raises it, up to 10^6.
inline constexpr std::int64_t kDefaultMaxRuns = 100'000;
inline constexpr Limits<std::int64_t> kMaxRunsLimits{1, 1'000'000};

// Runs per scenario or beta (documented range).
inline constexpr Limits<int> kRunsLimits{1, 100'000};

// The run limit of one experiment and what the user calls it ("--max-runs" on the command line),
// for the message that refuses more (resolve_sweep, sweep.h).
struct SweepLimits {
  std::int64_t max_runs = kDefaultMaxRuns;
  std::string max_runs_name = "max_runs";
};

}  // namespace multicpg::experiments
