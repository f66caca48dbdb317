// Flags shared by `learn` and `experiment`: the SA and trial settings of SPEC §6.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "learning/compensation.h"
#include "sim/stepper.h"

namespace multicpg::apps {

struct LearningFlags {
  std::string mode = "robust";
  std::string steering = "reflex";
  int hold_windows = learning::kDefaultHoldWindows;
  long monitor_windows = learning::kDefaultMonitorWindows;
  bool no_period_learning = false;
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

// Options for one run; throws BadInput (one line) for a bad value or leg set. `faults` is the
// whole timeline (apps/walk_flags.h parse_faults); it must fail some leg.
learning::CompensationOptions compensation_options(const LearningFlags& flags,
                                                   const robot::Morphology& morph,
                                                   const sim::FaultTimeline& faults);

}  // namespace multicpg::apps
