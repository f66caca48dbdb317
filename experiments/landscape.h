// The landscape of one leg-failure scenario: every combination of working-leg periods,
// each walked and measured the same way, so the learners can be scored against the truth. Two
// ways of walking (docs/learning.md "The landscape dataset"):
// - periods alone (steering off): from a robot already walking (warmed-up, locked controller with
//   the legs failed), set to the combination, settled, then measured over W windows of 400 steps;
// - as the default robust run walks (steering reflex): the robot walks with every leg at 4 and
//   the reflex on until robust mode would start learning (learning::watch_until_deviation); from
//   that one state each combination is set, settled and judged as robust mode judges a trial
//   (learning::robust_trial), window by window until the first over the threshold or W held: the
//   first trial of a live run, exactly.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "body/deviation.h"
#include "common/limits.h"
#include "experiments/run_robot.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "learning/course_walk.h"
#include "learning/landscapes.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::experiments {

// Windows measured per combination: 6 x 400 steps = 89 s at 27 Hz, long enough that a slow
// drift shows in some window.
inline constexpr int kDefaultLandscapeWindows = 6;
inline constexpr Limits<int> kLandscapeWindowsLimits{1, 1000};
// Combinations listed in summary.json's "top".
inline constexpr std::size_t kLandscapeTop = 10;

// Everything that decides a landscape's results.
struct LandscapeSpec {
  RobotSpec robot;                    // run_robot.h
  std::vector<std::size_t> disabled;  // sorted, unique, not every leg
  std::vector<int> period_set = learning::AnnealingParams{}.period_set;
  int windows = kDefaultLandscapeWindows;
  long window_steps = learning::kDefaultWindowSteps;
  double threshold_deg = learning::kDefaultThresholdDeg;
  // off: periods alone, every window walked; reflex: as robust mode's first trial (above).
  learning::Steering steering = learning::Steering::off;
};

// Throws BadInput (one line) for an unknown or repeated leg, every leg disabled, an empty period
// set, a repeated period or one outside 1-9, windows < 1, window steps < 1, threshold <= 0.
void validate(const LandscapeSpec& spec);

// What one combination does (the ground truth of docs/learning.md's landscape).
struct CombinationMeasure {
  learning::Periods periods;  // every leg; disabled legs keep 4
  long settle_steps = 0;      // walked unmeasured after the periods were set
  // Every window walked; with the reflex, up to the first over the threshold.
  std::vector<body::WindowMeasure> windows;
  // Largest window error: worst_deg() of the windows, with the reflex robust mode's E
  // (learning::robust_deviation: its effort too).
  double worst_deg = 0.0;
  bool holds = false;  // every one of the spec's windows walked and under the threshold
  bool first_window_passes = false;  // the paper's criterion on the first window: |yaw| < threshold
};

// Measures one combination: a sim::Stepper started with every leg at 4 and `disabled` failed
// from the start, the controller warmed up (body::kControllerWarmup steps); then `periods` set with
// every client free (as learning tries a candidate), learning::locked_settle_steps unmeasured,
// and `windows` windows of `window_steps` steps, each measured by body::measure_window.
CombinationMeasure measure_combination(const sim::SimModel& model,
                                       const std::vector<std::size_t>& disabled,
                                       const learning::Periods& periods, int windows,
                                       long window_steps, double threshold_deg);

// The options a reflex landscape walks with: robust mode, the steering reflex with its default
// gains, the spec's threshold, window and period set, every other option at its default.
learning::CompensationOptions landscape_options(const LandscapeSpec& spec);

// Where a reflex landscape's combinations start: the robot and its walk saved when robust mode
// would start learning, and the windows walked to there after the faults' own window.
struct LandscapeStart {
  sim::StepperCheckpoint body;
  learning::CourseWalkState walk;
  // The last one deviated (learning would start with it), or all monitor_windows held (the
  // reflex alone holds: a live run learns nothing).
  std::vector<body::WindowMeasure> windows;
};

// The start of `spec`'s combinations (spec.steering must be reflex): a sim::Stepper started as a
// learning run starts (every leg at 4, warmed up, spec.disabled failed at step 0), walked by
// learning::watch_until_deviation.
LandscapeStart walk_landscape_start(const sim::SimModel& model, const LandscapeSpec& spec);

// One combination of a reflex landscape, from `start`: every client freed (as at a detection),
// then learning::robust_trial over spec.windows windows.
CombinationMeasure measure_from_start(const sim::SimModel& model, const LandscapeSpec& spec,
                                      const LandscapeStart& start,
                                      const learning::Periods& periods);

// Every combination of the period set over the working legs, disabled legs at 4; the first
// working leg varies slowest (5 periods, 5 working legs: 3,125).
std::vector<learning::Periods> landscape_combinations(const LandscapeSpec& spec);

// "R2-4_R3-5_L1-6_L2-8_L3-9": the working legs' periods, the name of the combination's run file.
std::string combination_key(const robot::Morphology& morph,
                            const std::vector<std::size_t>& disabled,
                            const learning::Periods& periods);

// Its windows' steering_effort only with the reflex (landscapes of periods alone read as before).
nlohmann::json to_json(const CombinationMeasure& m, const robot::Morphology& morph,
                       learning::Steering steering);
CombinationMeasure combination_from_json(const nlohmann::json& j, const robot::Morphology& morph);

struct Landscape {
  LandscapeSpec spec;
  std::vector<CombinationMeasure> combinations;  // in landscape_combinations order
  // With the reflex: the windows of its start (LandscapeStart::windows).
  std::vector<body::WindowMeasure> start_windows;
};

// Index of the best combination: the one that holds with the smallest worst deviation (the
// first such in order on ties); empty if none holds.
std::optional<std::size_t> best_combination(const Landscape& landscape);
// Indices of the combinations from the smallest worst deviation up (ties in order).
std::vector<std::size_t> ranked_combinations(const Landscape& landscape);

// Runs every combination not yet saved in out/runs on `jobs` threads (experiments/runner.h;
// resumable, refused for another spec), then writes out/landscape.csv and out/summary.json.
// `learned`: combinations a learner found (every leg's period), placed in the summary.
// `progress_label` as RunnerOptions::progress_label.
Landscape run_landscape(const LandscapeSpec& spec, const std::filesystem::path& out, int jobs,
                        bool progress, const std::vector<learning::Periods>& learned = {},
                        const std::string& progress_label = "");

// Every scenario of `specs` (one landscape each, the same settings; experiments/sweep.h "every"),
// each in OUT/<scenario> as run_landscape does (resumable), then the dataset of them all in
// OUT/landscapes.{csv.gz,json} (learning/landscapes.h).
std::vector<Landscape> run_landscape_set(const std::vector<LandscapeSpec>& specs,
                                         const std::filesystem::path& out, int jobs, bool progress);
// The landscapes as one dataset (learning/landscapes.h), in the order given.
learning::LandscapeDataset landscape_dataset(const std::vector<Landscape>& landscapes);
// OUT/<scenario> of one landscape of a set.
std::filesystem::path landscape_set_dir(const std::filesystem::path& out,
                                        const LandscapeSpec& spec);
// The stem of a set's dataset files: OUT/landscapes.
std::filesystem::path landscape_set_dataset(const std::filesystem::path& out);

// landscape.csv: one row per combination: each working leg's period, per window yaw_deg and
// path_deg, worst_deg, holds, first_window_passes (1/0). Numbers in shortest round-trip form.
std::string landscape_csv(const Landscape& landscape);

// summary.json: the spec, count, holding (count, share), first window passing (count, share),
// best (periods, worst_deg; null if none holds), top (kLandscapeTop smallest worst deviations) and
// learned (each with its worst_deg, holds and rank, 1 = smallest worst deviation).
nlohmann::json landscape_summary(const Landscape& landscape,
                                 const std::vector<learning::Periods>& learned);

// Reads a JSON array of {leg: period} objects naming every working leg (disabled legs may be
// named with any period and are set to 4). Throws BadInput (one line) for anything else or a
// period outside the spec's period set.
std::vector<learning::Periods> parse_learned(const nlohmann::json& j, const LandscapeSpec& spec);
// Whether `periods` is one of the landscape's combinations: every working leg's period in the
// period set (a disabled leg's period does not count).
bool in_landscape(const LandscapeSpec& spec, const learning::Periods& periods);

}  // namespace multicpg::experiments
