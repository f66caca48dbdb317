// A learner driven from outside, one trial at a time (docs/learning.md "Ask and tell"): whoever
// walks the trials (another simulator, a real robot's own stack, a function of the periods)
// asks it for the next periods and tells it what the trial measured. It is made as a run makes
// an episode's learner (learning/learners.h) and judges a trial's windows as the run does
// (learning/criterion.h), so driven by our own simulation it gives the trials `learn` gives for
// the same seed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "body/deviation.h"
#include "learning/criterion.h"
#include "learning/learner.h"
#include "learning/learners.h"
#include "learning/search_bounds.h"
#include "robot/morphology.h"

namespace multicpg::learning {

// What an ask/tell learner is made from.
struct AskTellSetup {
  LearnerChoice learner;  // its name and options (resolved when it is made)
  robot::RobotKind robot = robot::RobotKind::hexapod;  // the leg layout (a robot file's too)
  ToldFault told;                                      // what it is told about the fault
  SearchBounds search;                                 // period set, threshold, trial cap
  // What a trial's E is made of: criterion(CompensationOptions) of the run it stands for.
  Criterion criterion = kPeriodsAloneCriterion;
  Periods start;  // C0, one period per leg; empty: every leg at kStartPeriod
  // What C0 measured: its windows (E their worst, and what a model learns from), or its E alone.
  std::vector<body::WindowMeasure> start_windows;
  std::optional<double> start_deviation_deg;
  std::uint64_t seed = 0;  // as `learn --seed`: the first episode's
};

class AskTell {
 public:
  // Resolves the learner and its data (learner_data) and checks them as a run does. Throws
  // OptionError naming the key, or BadInput (a start outside the period set, C0 without windows
  // nor E, ...).
  explicit AskTell(const AskTellSetup& setup);

  // The next periods to walk (every leg), or nothing when it is done (held, the trial cap, or no
  // untried combination left). Throws std::logic_error when the last asked periods were not told.
  std::optional<Periods> ask();
  // What the trial of the asked periods measured: its windows (E = the criterion's worst) or its
  // E alone. Returns the trial's record. Throws std::logic_error when nothing was asked.
  TrialRecord tell(const std::vector<body::WindowMeasure>& windows);
  TrialRecord tell(double deviation_deg);

  // Starts the next episode, as robust mode's monitoring does when the combination walked on
  // deviates (docs/learning.md "Memory across episodes"): a new learner from C0 = `start` with
  // what it measured, drawing from the seed + the episodes before it, and told every trial of
  // the earlier episodes since the last forget(). Throws std::logic_error when the last asked
  // periods were not told; OptionError("start") or ("start_windows") as the constructor.
  void next_episode(const Periods& start, const std::vector<body::WindowMeasure>& windows);
  void next_episode(const Periods& start, double deviation_deg);
  // What the earlier trials measured no longer describes the body (a fault came, as the run
  // forgets): the next episode is told none of them.
  void forget() { memory_.clear(); }
  int episode() const { return episode_; }

  bool done() const { return learner_->stop() != StopReason::running; }
  StopReason reason() const { return learner_->stop(); }
  Answer answer() const { return learner_->answer(); }
  const LearnerSetup& setup() const { return setup_; }
  const LearnerChoice& learner() const { return choice_; }
  const LearnerData& data() const { return data_; }
  const std::vector<TrialRecord>& trace() const { return trace_; }

 private:
  TrialRecord record(const Measurement& m);
  void start_episode(AskTellSetup next);

  AskTellSetup asked_setup_;  // as made, for the next episode's learner
  LearnerChoice choice_;
  LearnerSetup setup_;
  LearnerData data_;
  std::unique_ptr<Learner> learner_;
  bool asked_ = false;
  int episode_ = 1;
  std::vector<EarlierTrial> memory_;  // every trial told since the last forget()
  std::vector<TrialRecord> trace_;
};

}  // namespace multicpg::learning
