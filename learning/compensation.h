// Online malfunction compensation (paper §3-§4, docs/learning.md "Online compensation"): the robot
// walks on without resets, legs fail, a deviating 400-step window desynchronises the CPGs and
// starts the annealing of learning/annealing.h, each trial walking the candidate periods for one
// window.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "body/body.h"
#include "body/deviation.h"
#include "body/events.h"
#include "learning/annealing.h"
#include "learning/criterion.h"
#include "learning/learner.h"
#include "learning/learners.h"
#include "learning/steering.h"
#include "neural/controller.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// Which algorithm compensates.
enum class Mode {
  paper,   // paper §3 exactly: one window judges a trial, yaw only, learning ends there
  robust,  // yaw and path angle, several windows to accept, monitoring on, optional steering
};
enum class Steering { off, reflex };  // learning/steering.h
std::string_view to_string(Mode mode);
std::string_view to_string(Steering steering);
Mode parse_mode(std::string_view text);          // throws BadInput naming the choices
Steering parse_steering(std::string_view text);  // throws BadInput naming the choices

inline constexpr long kDefaultWindowSteps = 400;  // paper §3 step 2
// Windows walked after the failure without a deviation above the threshold before the run
// ends "no deviation": 5 windows = 2000 steps, 74 s at 27 Hz.
inline constexpr long kDefaultDetectionWindows = 5;
// Steps a leg's CPG needs from a reset to its locked orbit, slowest learnable period p = 9
// (measured with neural/: 211 steps; p = 5, 6, 8 need 46, 67, 87). p = 4 locks exactly only
// after about 740 steps, but its swing pattern is right from the first cycle except for a few
// isolated steps (18 of 540 after step 200), so it does not set the settle time.
inline constexpr long kSlowestLockSteps = 211;

// Steps walked unmeasured after a period change: the slowest CPG lock plus the longest delay
// line, whose contents still come from before the change (docs/controller.md "Delay lines").
// Hexapod 211 + 126 = 337, quadruped 211 + 108 = 319, octopod 211 + 144 = 355.
long default_settle_steps(const neural::ControllerModel& model);

// Steps after a reset of every CPG to `periods` until no window can see a transient: the
// slowest of these periods to lock exactly (neural::lock_steps; 737 for p = 4) plus the longest
// delay line, so the joints carry only locked signals. Hexapod with a leg at 4: 737 + 126 = 863.
long locked_settle_steps(const neural::ControllerModel& model, const Periods& periods);

// Robust mode: clean windows after the last fault or learning episode before the run ends.
inline constexpr long kDefaultMonitorWindows = 6;
// Robust mode: learning episodes at most in one run (each restarts learning after a deviation).
inline constexpr int kDefaultMaxEpisodes = 10;
// Controller steps a run may spend in trials (their settling and measured windows), over all its
// episodes, before it ends "budget reached" (docs/learning.md "Step budget"): 10^6 steps, 10.3 h
// of walking at 27 Hz. The paper's runs never reach it (at most 200 trials of 337 + 400 steps,
// 147,400 steps); a robust run of 10 episodes of 200 trials could (up to 4 million).
inline constexpr long kDefaultStepBudget = 1'000'000;

// Documented ranges. A window or settle of up to 10^5 steps (an hour at 27 Hz);
// counts of windows and episodes far past the defaults above.
inline constexpr Limits<long> kWindowStepsLimits{1, 100'000};
inline constexpr Limits<long> kSettleStepsLimits{0, 100'000};
inline constexpr Limits<long> kDetectionWindowsLimits{1, 1000};
inline constexpr Limits<int> kHoldWindowsLimits{1, 100};
inline constexpr Limits<long> kMonitorWindowsLimits{1, 1000};
inline constexpr Limits<int> kMaxEpisodesLimits{1, 1000};
inline constexpr Limits<long> kStepBudgetLimits{1, body::kMaxSteps};

// How a compensation run learns. What fails and when is the run's, not the learner's: the
// body's fault schedule (body::FaultSchedule) says what came.
struct CompensationOptions {
  Mode mode = Mode::robust;
  // The search's bounds for every learner (period set, threshold, trial cap). A run records them
  // with the annealing's beta as "annealing" (learning/json.h), as runs were recorded when the
  // annealing was the only learner.
  SearchBounds search;
  // Which learner searches, with its options (learning/learners.h): the paper's annealing, its
  // beta its option "beta".
  LearnerChoice learner;
  long window_steps = kDefaultWindowSteps;
  // Unmeasured steps after every period change (paper: and before the first detection window).
  // Empty = paper: default_settle_steps(model); robust: locked_settle_steps(model, periods).
  std::optional<long> settle_steps;
  long detection_windows = kDefaultDetectionWindows;  // paper mode (see above)
  int hold_windows = kDefaultHoldWindows;             // robust mode
  long monitor_windows = kDefaultMonitorWindows;      // robust mode
  int max_episodes = kDefaultMaxEpisodes;             // robust mode
  long step_budget = kDefaultStepBudget;              // both modes (see above)
  bool learn_periods = true;                          // robust mode; false = steering alone
  // Whether each episode's learner is told which legs failed (paper §3: a lost leg's period is
  // never picked); false = told nothing, it searches every leg's period (docs/learning.md
  // "What a learner is told").
  bool tell_fault = true;
  Steering steering = Steering::reflex;  // robust mode
  SteeringParams steering_params;
  std::uint64_t seed = 0;
};

// The settle a run of `options` starts with (LearningResult::settle_steps): the given one, else
// paper mode's default_settle_steps, robust mode's locked_settle_steps for all periods at 4.
long start_settle_steps(const CompensationOptions& options, const neural::ControllerModel& model);

// What a run of `options` makes a trial's E of (learning/criterion.h): paper mode's |yaw change|,
// robust mode's worst of |yaw change| and |path angle|, and with the reflex its effort.
Criterion criterion(const CompensationOptions& options);

// A robust-mode window's E, what it compares with the threshold (docs/learning.md "Deviation"):
// the worse of |yaw change| and |path angle|, and with the reflex its effort scaled so that
// max_effort reads as the threshold.
double robust_deviation(const CompensationOptions& options, const body::WindowMeasure& window);

// Throws OptionError (key "annealing.beta", "window_steps", "learner.name", ...; one line) for a
// value outside its limits or an unknown learner or learner option. Paper mode ignores the
// robust-mode options (hold, monitor and max episodes, learn_periods, steering).
void validate(const CompensationOptions& options);

// Throws OptionError (key "mode") for a fault timeline these options cannot learn with: paper
// mode takes one fault and no recovery (paper §3).
void validate_faults(const CompensationOptions& options, const body::FaultTimeline& faults);

// One learning episode: from a detecting window to the end of its annealing.
struct Episode {
  long detection_step = 0;     // steps after the start when the deviation was seen
  double detection_deg = 0.0;  // E of the detecting window (C0's E_ref)
  int trials = 0;
  bool held = false;  // its last combination held under the threshold
  std::optional<StopReason> reason;
  bool interrupted = false;  // a fault or recovery came while it learned
  Periods periods;           // the accepted combination when it ended
  double final_deviation_deg = 0.0;
};

// How a run ended: converged (a combination held under the threshold), not converged (the trial
// cap, the search space or the episodes ran out), no deviation (no window ever exceeded the
// threshold, so learning never started) or budget reached (its trials used up the step budget;
// the robot walks on with the learner's answer so far).
enum class Outcome { converged, not_converged, no_deviation, budget_reached };
// "converged", "not converged", "no deviation", "budget reached"
std::string_view to_string(Outcome outcome);
Outcome parse_outcome(std::string_view text);         // throws BadInput naming the choices
StopReason parse_stop_reason(std::string_view text);  // to_string(StopReason)'s names

// What a learner learned from besides its trials (docs/learning.md "A learner's data"): the file
// of its landscape dataset and how that was walked ("periods alone", "the steering reflex").
struct LearnedFrom {
  std::string dataset;
  std::string walked;
  bool operator==(const LearnedFrom&) const = default;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LearnedFrom, dataset, walked)

struct LearningResult {
  Outcome outcome = Outcome::not_converged;
  bool converged() const { return outcome == Outcome::converged; }
  std::optional<StopReason> reason;  // why annealing stopped; empty when it never started
  int trials = 0;
  double initial_deviation_deg = 0.0;  // E of C0: the detecting window (or the last window)
  // Paper mode: E of the accepted combination when the run ended. Robust mode: the largest E of
  // the windows walked after the last fault or episode (docs/learning.md "What learn prints").
  double final_deviation_deg = 0.0;
  Periods periods;  // the accepted combination, left on the controller
  std::vector<TrialRecord> trace;
  long steps_walked = 0;
  std::optional<long> detection_step;  // steps after the start when the deviation was seen
  long settle_steps = 0;               // as used (robust: after a change to all-4 periods)
  Mode mode = Mode::robust;
  std::vector<Episode> episodes;  // robust mode: one per detection (paper: at most one)
  // Robust mode: each window walked after the last episode or fault, as measured.
  std::vector<body::WindowMeasure> final_windows;
  // Mean |swing cut| of the steering reflex over the last window (0 = no steering used).
  double steering_effort = 0.0;
  // The reflex as the run left it (robust mode with Steering::reflex), to walk on with.
  std::optional<SteeringState> steering;
  // A model-based learner's map after the last trial (its last episode's): the kBestForecasts
  // combinations its model gives the best chance to hold, best first; not recorded in JSON.
  std::vector<Forecast> forecasts;
  std::optional<LearnedFrom> learned_from;  // empty: the learner learned from its trials alone
};

// Runs the whole online loop on `body`, which should be walking forward with every client
// synchronised (as make_controller_state leaves it), at its step 0 (else std::invalid_argument:
// a caller's mistake), its faults to come as its schedule says. Throws OptionError for options or
// a timeline validate() or validate_faults() refuse. Paper mode is
// paper §3 exactly (docs/learning.md "The search"); robust mode:
// - a window is judged on both its yaw change and its path angle (body::measure_window);
// - a combination is accepted only when it holds for hold_windows consecutive windows (a trial
//   stops at its first window over the threshold, whose deviation is the trial's E);
// - after an episode the robot keeps walking and monitoring, and a window over the threshold
//   starts a new episode; the run ends after monitor_windows clean windows past the last fault;
// - a recovery that leaves no fault in force sets every period back to the master's and
//   resynchronises the clients (paper §2.3), then settles;
// - with Steering::reflex, learning/steering.h holds the course set where the run started.
// The learner learns from `data` (learning::learner_data of options.learner, resolved once
// before the run; empty for a learner that learns from its trials alone).
LearningResult compensate(body::Body& body, const CompensationOptions& options,
                          const LearnerData& data);

// The observer's events of a learning run (body/events.h), as compensate emits them and as a
// recorded result is replayed (its detections, decided trials and episode ends).
body::Event detection_event(int episode, double deviation_deg, const Periods& periods);
body::Event trial_end_event(int episode, const TrialRecord& trial);
body::Event episode_end_event(int episode, const Episode& ended);

// JSON with converged, status, reason, trials, initial/final_deviation_deg, periods
// (leg name -> period), disabled (names), steps_walked, detection_step (null if none),
// settle_steps and trace (trial, periods, deviation_deg, accepted, acceptance_probability,
// legs_changed, redraws, tabu_redraw).
nlohmann::json to_json(const LearningResult& result, const robot::Morphology& morph,
                       const std::vector<std::size_t>& disabled);

// The result to_json wrote (without the steering state, which it does not record). Throws
// BadInput naming the field when `j` is not such a record for `morph`.
LearningResult result_from_json(const nlohmann::json& j, const robot::Morphology& morph);

}  // namespace multicpg::learning
