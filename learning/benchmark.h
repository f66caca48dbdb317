// Learners scored against the truth (docs/learning.md "Learner benchmark"): a learner learns on
// a scenario's landscape (learning/landscapes.h) instead of a walking robot. A trial is a lookup:
// each window it walks is one of the combination's measured windows, drawn by the run's seed
// (trial noise is the landscape's own) or taken in the order they were walked (what the
// deterministic simulation measures, docs/learning.md "Live physics"); whether its final
// combination holds is read from every window the landscape measured.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "learning/landscapes.h"
#include "learning/learners.h"

namespace multicpg::learning {

// Which of a combination's measured windows a trial walks. drawn: a permutation drawn anew for
// each measurement, so a combination near the threshold may pass one trial and fail the next, as
// a real robot's noisy trials would. walked: the landscape's windows in the order it walked them,
// the same at every visit, which is what the simulation measures: a live trial after a settle
// walks the landscape's windows to about 1e-12 deg, whatever the robot did before
// (docs/learning.md "Live physics").
enum class WindowOrder { drawn, walked };
std::string_view to_string(WindowOrder order);
WindowOrder parse_window_order(std::string_view text);  // throws BadInput naming the choices

// How a trial is measured, as the online loop does (learning/compensation.h) with the steering
// reflex off: the paper's one window of |yaw change|, or robust mode's worst error of up to
// hold_windows windows, stopping at the first over the threshold.
struct TrialProtocol {
  bool yaw_only = false;                   // paper mode
  int hold_windows = kDefaultHoldWindows;  // robust mode
  WindowOrder window_order = WindowOrder::drawn;
  // Episodes a run may have. 1: the first alone, a stop on a combination that does not hold in
  // truth ends the run (a false stop). More: robust mode's monitoring, as a live run has it: the
  // combination walks on through the landscape's later windows, and the first of them over the
  // threshold starts another episode from it, its learner told what the earlier ones walked
  // (LearnerSetup::earlier) and seeded as a live run's next episode (walked order only).
  int episodes = 1;
};

// What judges a replayed trial: the paper's |yaw change| of one window, or the dataset's
// criterion over the protocol's hold_windows.
Criterion replay_criterion(const LandscapeDataset& dataset, const TrialProtocol& protocol);

// Throws BadInput for episodes a replay cannot walk: fewer than one, or more than one where no
// later window follows a trial in order (paper mode, drawn windows).
void check_episodes(const TrialProtocol& protocol);

// What a replayed learner is told about the fault (docs/learning.md "What a learner is told"):
// the scenario's failed legs, as every run tells them, or nothing.
enum class Told { failed_legs, nothing };

// One learning run replayed on one scenario.
struct ReplayRun {
  bool deviated = false;  // the start (all 4) deviated in the window it walked, so learning ran
  int trials = 0;         // over every episode
  int episodes = 0;       // learning episodes walked (0: no deviation)
  StopReason reason = StopReason::running;
  Periods answer;                 // the combination the learner ended with
  bool answer_holds = false;      // in truth: every window of the landscape under the threshold
  double answer_worst_deg = 0.0;  // its worst window in the landscape
  // The trial, counted over every episode, at which the learner stopped, held, on a combination
  // that holds in truth.
  std::optional<int> held_at;
  // The run ended on a stop, held, on a combination that does not hold in truth (with more
  // episodes allowed: its last episode's).
  bool false_stop = false;
  // The first trial whose combination holds in truth, whether or not the learner saw it.
  std::optional<int> first_holding_tried;
  std::vector<TrialRecord> trace;
};

// Replays `choice` on `scenario` of `dataset` with run seed `seed`: the start's E is one window
// of the all-4 combination (drawn, or its first with WindowOrder::walked); if it is under the
// threshold the run ends there (no deviation). The learner's seed and every window draw derive from
// `seed`; the window drawn for a combination at its k-th measurement depends only on (seed,
// combination, k), so every learner sees the same noise for the same combination (common random
// numbers). The learner learns from `data` (learner_data of `choice`) with `scenario` withheld:
// it never sees the scenario it replays. `search` bounds the search (period set and threshold must
// be the dataset's). Throws BadInput when the choice or the bounds do not fit the dataset.
// `learner_seed`, when given, seeds the learner instead (as `learn --seed` seeds a live run's
// first episode, and + k its episode k + 1), so a walked replay can retrace a live run trial by
// trial. `told`: what the learner is told of the fault; told nothing it still never sees the
// scenario it replays.
ReplayRun replay_run(const LandscapeDataset& dataset, const ScenarioLandscape& scenario,
                     const LearnerChoice& choice, const LearnerData& data,
                     const SearchBounds& search, const TrialProtocol& protocol, std::uint64_t seed,
                     std::optional<std::uint64_t> learner_seed = std::nullopt,
                     Told told = Told::failed_legs);

// The two exact baselines of a scenario: random search without replacement needs (N+1)/(K+1)
// trials on average to draw the first of K holding combinations among N (the start excluded);
// the oracle needs one. Empty when none holds.
std::optional<double> random_expected_trials(const ScenarioLandscape& scenario);

}  // namespace multicpg::learning
