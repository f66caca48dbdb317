// The search every learner shares (docs/learning.md "The search", paper Table 2): combinations of
// the working legs' periods from one period set, a threshold the trials' E must get under, and a
// cap on trials; why a search stopped. What is any one learner's own (the annealing's beta, a
// model's scales) is that learner's option (learning/learners.h), not part of these bounds.
#pragma once

#include <string_view>
#include <vector>

#include "common/enum_names.h"
#include "common/limits.h"

namespace multicpg::learning {

// One period per leg, in morphology order (R1..Rn, L1..Ln).
using Periods = std::vector<int>;

inline constexpr double kDefaultThresholdDeg = 8.0;  // E_req, paper §4
inline constexpr int kDefaultMaxTrials = 200;        // docs/learning.md "Stop and trial cap"
inline constexpr int kStartPeriod = 4;               // C0 = all 4 (tripod), Table 2

// Documented ranges: a threshold between a thousandth of a degree and a U-turn; a trial cap far
// past the paper's 200.
inline constexpr Limits<double> kThresholdLimits{0.001, 180.0};
inline constexpr Limits<int> kMaxTrialsLimits{1, 100'000};

struct SearchBounds {
  std::vector<int> period_set{4, 5, 6, 8, 9};   // Table 2 step (2)
  double threshold_deg = kDefaultThresholdDeg;  // stop when E < threshold
  int max_trials = kDefaultMaxTrials;           // reaching it ends the search, not held
  bool operator==(const SearchBounds&) const = default;
};

// Throws OptionError (key "threshold_deg", "max_trials", "period_set") for a value outside its
// limits, or a period set that is empty, repeats a value or holds a period that gives no gait.
void validate(const SearchBounds& bounds);

// Why a search stopped; episode_cap is a robust run's: every episode it may start
// (CompensationOptions::max_episodes) was used and its last windows still did not hold.
enum class StopReason { running, below_threshold, trial_cap, space_exhausted, episode_cap };
// Each reason's name in a learning record (learning/json.h).
inline constexpr auto kStopReasonNames =
    enum_names<StopReason>({{StopReason::running, "running"},
                            {StopReason::below_threshold, "below threshold"},
                            {StopReason::trial_cap, "trial cap"},
                            {StopReason::space_exhausted, "search space exhausted"},
                            {StopReason::episode_cap, "episode cap"}});
std::string_view to_string(StopReason reason);

}  // namespace multicpg::learning
