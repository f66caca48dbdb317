// What a learner is: it proposes the next combination of the working legs' periods, observes
// what the body measured for it, and decides whether it is done (held) or gives up with the
// best it found. The online loop (learning/compensation.h) and the replay benchmark
// (learning/benchmark.h) drive every learner the same way (run_episode), so a learner never knows
// whether a trial walked a MuJoCo robot, a real one, or was looked up in a landscape.
//
// To add a learner (docs/learning.md "Learners"):
//   1. Write learning/<name>.cpp: a class derived from Learner, its options as a struct read with
//      read_learner_options (learning/learners.h), and two functions:
//        nlohmann::json <name>_options(const nlohmann::json& asked);  // defaults filled, checked
//        std::unique_ptr<Learner> make_<name>(const LearnerSetup&, const nlohmann::json& options,
//                                             const LearnerData& data);
//      Draw every random number from the setup's seed; record every option that decides the
//      result in its options (they are saved with every run). A learner that learns from data
//      besides its trials (as the prior) also gives the table how to resolve and check them.
//   2. Declare both and add one row to the table in learning/learners.cpp.
//   3. Add the file to learning/CMakeLists.txt.
//   4. Test it (tests/test_learners.cpp runs every registered learner through the common checks).
// Every command, experiment file, the Python API and the benchmark take it by its name.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "body/deviation.h"
#include "learning/criterion.h"
#include "learning/forecast.h"
#include "learning/search_bounds.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// What a learner is told about the fault (docs/learning.md "What a learner is told"): the legs
// that failed, whose periods it then never picks (paper §3), or nothing, when it searches every
// leg's period, the failed legs' too. Changing a lost leg's period does nothing to the body, so
// a learner told nothing spends trials on combinations that differ only there: the price of not
// knowing.
class ToldFault {
 public:
  // Told nothing.
  ToldFault() = default;
  static ToldFault nothing() { return {}; }
  // Told that `legs` (morphology indices) failed.
  static ToldFault legs(std::vector<std::size_t> legs) {
    std::sort(legs.begin(), legs.end());
    return ToldFault(std::move(legs));
  }

  bool told() const { return told_; }
  // The legs it is told failed, in leg order, which it never picks; none when told nothing.
  const std::vector<std::size_t>& failed() const { return failed_; }
  bool operator==(const ToldFault&) const = default;

 private:
  explicit ToldFault(std::vector<std::size_t> legs) : told_(true), failed_(std::move(legs)) {}
  bool told_ = false;
  std::vector<std::size_t> failed_;
};

// A combination an earlier episode of the same run walked under the faults still in force, with
// the windows it measured (docs/learning.md "Memory across episodes"): in robust mode a
// combination that held can drift over the threshold later and start another episode.
struct EarlierTrial {
  Periods periods;
  std::vector<body::WindowMeasure> windows;
};

// What every learner is told when an episode starts.
struct LearnerSetup {
  robot::RobotKind robot = robot::RobotKind::hexapod;
  Periods start;   // C0: the combination walking when the deviation was seen (every leg)
  ToldFault told;  // what it is told about the fault
  double start_deviation_deg = 0.0;                // E of C0 (the detecting window)
  std::vector<body::WindowMeasure> start_windows;  // the detecting window, signed
  // What E is made of (learning/criterion.h): the paper's |yaw change| alone, robust mode's worst
  // of |yaw change| and |path angle|, and with the steering reflex its effort.
  Criterion criterion = kPeriodsAloneCriterion;
  // The search's bounds, the same for every learner: its period set, the threshold E must get
  // under and the trial cap (a learner's own constants, such as the annealing's beta, are its
  // options).
  SearchBounds search;
  std::uint64_t seed = 0;  // every random draw of the episode comes from it
  // What the run's earlier episodes walked under the same faults, oldest first: no learner walks
  // them again (the models are told their windows; the others count them as tried;
  // docs/learning.md "Memory across episodes").
  std::vector<EarlierTrial> earlier;

  // The legs whose period may change, in morphology order: every leg but the ones it is told
  // failed.
  std::vector<std::size_t> working() const;
};

// What the body measured for one trial.
struct Measurement {
  // E: what the trial is judged by, as the mode measures it (paper mode: |yaw change| of one
  // window; robust mode: the worst window error of up to hold_windows windows).
  double deviation_deg = 0.0;
  std::vector<body::WindowMeasure> windows;  // each window walked for the trial, in order
};

// One trial, the same for every learner (paper Fig. 8 row): what was tried, what it measured,
// whether it became the learner's answer; the learner's own details beside them (the annealing's
// acceptance probability, a model's prediction, ...), written into the trial's JSON as they are.
struct TrialRecord {
  int trial = 0;  // 1-based within its episode
  Periods periods;
  double deviation_deg = 0.0;
  bool accepted = false;  // the combination is now the learner's answer
  nlohmann::json details = nlohmann::json::object();
};

// A detail as a number: a boolean as 1 or 0, NaN when the trial has no number under `key`.
double detail_number(const TrialRecord& trial, const std::string& key);

// The learner's answer: the combination the robot walks on with, and its measured E.
struct Answer {
  Periods periods;
  double deviation_deg = 0.0;
};

class Learner {
 public:
  virtual ~Learner() = default;
  // The next combination to try (every leg's period; the legs told failed unchanged), or nothing
  // when no untried combination is left (the learner gives up: StopReason::space_exhausted).
  virtual std::optional<Periods> propose() = 0;
  // The measurement of the combination propose() returned: the trial's record. Afterwards
  // stop() says whether the episode is over.
  virtual TrialRecord observe(const Measurement& measurement) = 0;
  // running while the learner wants another trial; below_threshold when it holds; trial_cap or
  // space_exhausted when it gives up with answer().
  virtual StopReason stop() const = 0;
  virtual Answer answer() const = 0;
  // A model-based learner's forecasts of the `count` combinations its model now gives the best
  // chance to hold, best first (docs/learning.md "Inside the model"); none from a learner
  // without a model.
  virtual std::vector<Forecast> best_forecasts(std::size_t /*count*/) const { return {}; }
};

// What an episode needs of whoever walks its trials.
struct EpisodeHooks {
  // Walks (or looks up) one trial of `periods`, the `trial`-th of the episode.
  std::function<Measurement(int trial, const Periods& periods)> measure;
  // Told each decided trial; returning true ends the episode there (a fault came: interrupted).
  std::function<bool(const TrialRecord&)> decided;
};

struct EpisodeEnd {
  StopReason reason = StopReason::running;  // running: interrupted by the hooks
  int trials = 0;
  std::vector<TrialRecord> trace;
  Answer answer;
};

// Runs `learner` until it stops or the hooks interrupt it. A learner that has already stopped
// (C0 under the threshold) runs no trial.
EpisodeEnd run_episode(Learner& learner, const EpisodeHooks& hooks);

}  // namespace multicpg::learning
