// What `learn` and `tunnel --learn` print of a learning run (docs/learning.md "What learn
// prints"): the header at once, each trial's row as it is decided, a line where an episode starts
// and ends, a line on stderr while a long walk goes on without a decision, and at the end the
// outcome with every number it prints defined. A run on hardware prints the same table from its
// result when it has ended.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "body/events.h"
#include "experiments/run_spec.h"
#include "learning/compensation.h"
#include "sim/stepper.h"

namespace multicpg::apps {

// Steps walked without a printed line before a progress line goes to stderr: 10,000 steps are
// 6 min of walking at 27 Hz and a few seconds of simulation; the default window and settle
// (400 + 863 steps) never go that long without a decision.
inline constexpr long kProgressEverySteps = 10'000;

// "1 trial", "3 trials".
std::string counted(long n, const std::string& noun);

// What the run walks on, where its robot file and terrain and body model apply:
// "hexapod", "quadruped from examples/robots/dog12.toml (dog12)"; "terrain slope:10:0, body model
// real".
std::string robot_text(const experiments::RobotSpec& robot);
std::string world_text(const experiments::RunSpec& spec);

// The learning run's header: robot, mode, faults, learner and search, then the world, and the
// table's column header.
void print_learning_header(std::ostream& out, const experiments::RunSpec& spec, long settle_steps);

// Fig. 8's table, one row per learning event, trials numbered across episodes; flushed after
// every line so that a pipe sees each as it comes.
class LearningTable {
 public:
  LearningTable(std::ostream& out, const experiments::RunSpec& spec);
  // A detection, trial_end or episode_end prints its line; others print nothing.
  void event(const body::Event& event);
  int trials() const { return trials_; }

 private:
  // `cell` in the predicted column when the learner forecasts each trial (learning/learners.h
  // forecasts); nothing, and no column, otherwise.
  std::optional<std::string> predicted(const std::string& cell) const;

  std::ostream& out_;
  const experiments::RunSpec& spec_;
  std::vector<std::size_t> disabled_;
  bool forecasts_ = false;
  int trials_ = 0;
};

// The table as the learner's events come (the simulation's observer): `out` gets its rows,
// `progress` a line whenever kProgressEverySteps steps went by without one.
class LearningStream final : public sim::Observer {
 public:
  LearningStream(std::ostream& out, std::ostream& progress, const experiments::RunSpec& spec);
  void on_step(const sim::SimModel& model, const sim::SimState& state) override;
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override;

 private:
  LearningTable table_;
  std::ostream& progress_;
  long steps_ = 0;
  long last_line_ = 0;
  std::string doing_ = "walking, watching for a deviation";
};

// The events a run's result holds (detections, trials, episode ends), for printing a run whose
// events were not streamed (hardware).
std::vector<body::Event> result_events(const learning::LearningResult& result);

// After the table: the episodes, the windows after learning, the outcome and what its numbers
// are, and, where the reflex did the work or nothing was learned, how to see period learning.
void print_learning_end(std::ostream& out, const experiments::RunSpec& spec,
                        const learning::LearningResult& result);

}  // namespace multicpg::apps
