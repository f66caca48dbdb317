#include "experiments/learning_run.h"

#include <algorithm>
#include <stdexcept>

#include "experiments/body_runs.h"

namespace multicpg::experiments {
namespace {

// Where each trial's last window ended, from the learner's own trial_end events.
class TrialEnds final : public sim::Observer {
 public:
  explicit TrialEnds(sim::Observer* next) : next_(next) {}
  void on_start(const sim::SimModel& model, const sim::SimState& state) override {
    if (next_ != nullptr) next_->on_start(model, state);
  }
  void on_step(const sim::SimModel& model, const sim::SimState& state) override {
    if (next_ != nullptr) next_->on_step(model, state);
  }
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override {
    if (event.kind == body::EventKind::trial_end) ends.push_back(event.step);
    if (next_ != nullptr) next_->on_event(model, state, event);
  }
  std::vector<long> ends;

 private:
  sim::Observer* next_;
};

}  // namespace

LearningRun run_learning(const sim::SimModel& model, const RunSpec& spec, long after_steps,
                         sim::Observer* observer) {
  Watchers watchers;
  watchers.observer = observer;
  return run_learning(model, spec, nullptr, after_steps, watchers);
}

LearningRun run_learning(const sim::SimModel& model, const RunSpec& spec,
                         const HardwareSetup* setup, long after_steps, const Watchers& watchers) {
  if (!spec.learning) throw std::invalid_argument("run_learning: the run has no learning options");
  LearningRun run;
  TrialEnds ends(watchers.observer);
  RunSpec started = spec;
  started.start.seed = spec.learning->seed;  // a noisy sensor's draws follow the learning seed
  Watchers own = watchers;
  own.observer = &ends;
  own.record = spec.record.steps ? &run.record : nullptr;
  own.record_joints = true;
  const learning::LearnerData data = learner_data(spec);
  const std::unique_ptr<RunBody> body = open_body(started, model, setup, own);
  BodyLearning learned = guarded(*body, spec, watchers.stopped, [&] {
    BodyLearning l = learn_body(body->body(), *spec.learning, data, after_steps);
    body->finish("the learning run ended");
    return l;
  });
  run.result = std::move(learned.result);
  run.learning_end_step = learned.learning_end_step;
  run.after_windows = std::move(learned.after_windows);
  run.trial_end_steps = std::move(ends.ends);
  run.final_state = body->final_state();
  run.hardware = body->hardware();
  return run;
}

}  // namespace multicpg::experiments
