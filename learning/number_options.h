// The learning options set by a number, declared once: each one's name (the CLI's --FLAG, and
// Python's keyword with '_' for '-'), its key in a run's record and an experiment file's
// [learning] (learning/json.h, whose type macros name the same members; tests/test_compensation.cpp
// checks that they do), its limits and its help text. The CLI's flags (apps/learning_options.cpp)
// and Python's keywords (python/run_args.cpp) are made from this table.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "common/limits.h"
#include "learning/compensation.h"

namespace multicpg::learning {

// One option whose value is a T, held in CompensationOptions as a Stored (a std::optional<T>:
// no value is the default the run works out).
template <class T, class Stored = T>
struct NumberOption {
  using Value = T;
  std::string_view flag;  // "hold-windows": --hold-windows, Python's hold_windows
  std::string_view key;   // its key in a record: "hold_windows", "annealing.threshold_deg"
  std::string_view help;  // what --help says of it
  bool robust_only;       // robust mode's alone: paper mode refuses it
  Limits<T> limits;
  Stored& (*field)(CompensationOptions&);
};

using LearningNumber = std::variant<NumberOption<int>, NumberOption<long>, NumberOption<double>,
                                    NumberOption<long, std::optional<long>>>;

// In the order --help lists them.
inline const std::array<LearningNumber, 8> kLearningNumbers{
    NumberOption<int>{
        "hold-windows", "hold_windows", "robust mode: consecutive windows a combination must hold",
        true, kHoldWindowsLimits, [](CompensationOptions& o) -> int& { return o.hold_windows; }},
    NumberOption<long>{
        "monitor-windows", "monitor_windows",
        "robust mode: clean windows after the last fault or episode before the run ends", true,
        kMonitorWindowsLimits, [](CompensationOptions& o) -> long& { return o.monitor_windows; }},
    NumberOption<double>{"threshold", "annealing.threshold_deg",
                         "deviation (deg) below which learning stops", false, kThresholdLimits,
                         [](CompensationOptions& o) -> double& { return o.search.threshold_deg; }},
    NumberOption<long>{"window", "window_steps", "steps per measured window", false,
                       kWindowStepsLimits,
                       [](CompensationOptions& o) -> long& { return o.window_steps; }},
    NumberOption<long, std::optional<long>>{
        "settle", "settle_steps",
        "unmeasured steps after each period change (default: slowest CPG lock + longest delay, "
        "337 for the hexapod; robust mode: 863)",
        false, kSettleStepsLimits,
        [](CompensationOptions& o) -> std::optional<long>& { return o.settle_steps; }},
    NumberOption<int>{"max-trials", "annealing.max_trials",
                      "trials an episode may take before it ends 'not converged'", false,
                      kMaxTrialsLimits,
                      [](CompensationOptions& o) -> int& { return o.search.max_trials; }},
    NumberOption<int>{"max-episodes", "max_episodes",
                      "robust mode: episodes (detection, then learning) before the run ends "
                      "'episode cap reached'",
                      true, kMaxEpisodesLimits,
                      [](CompensationOptions& o) -> int& { return o.max_episodes; }},
    NumberOption<long>{"step-budget", "step_budget",
                       "controller steps the run may spend in trials, over all its episodes, "
                       "before it ends 'budget reached' (docs/learning.md \"Step budget\")",
                       false, kStepBudgetLimits,
                       [](CompensationOptions& o) -> long& { return o.step_budget; }},
};

// The Python keyword of an option: its flag with '_' for '-'.
inline std::string keyword(std::string_view flag) {
  std::string out(flag);
  for (char& c : out) {
    if (c == '-') c = '_';
  }
  return out;
}

}  // namespace multicpg::learning
