// Flags shared by `learn` and `experiment`: the SA and trial settings of SPEC §6.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>

#include "learning/compensation.h"

namespace multicpg::apps {

struct LearningFlags {
  double beta = learning::kDefaultBeta;
  double threshold = learning::kDefaultThresholdDeg;
  long window = learning::kDefaultWindowSteps;
  std::optional<long> settle;
  int max_trials = learning::kDefaultMaxTrials;
  std::uint64_t seed = 1;
};

// Adds --beta --threshold --window --settle --max-trials --seed (without --beta when
// `with_beta` is false: the beta study sets it per run).
void add_learning_flags(CLI::App& cmd, LearningFlags& flags, bool with_beta = true);

// Options for one run; throws BadInput (one line) for a bad value or leg set.
learning::CompensationOptions compensation_options(const LearningFlags& flags,
                                                   const robot::Morphology& morph,
                                                   std::vector<std::size_t> disabled,
                                                   long fail_step);

}  // namespace multicpg::apps
