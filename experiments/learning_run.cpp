#include "experiments/learning_run.h"

#include <algorithm>
#include <stdexcept>

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
  if (!spec.learning) throw std::invalid_argument("run_learning: the run has no learning options");
  const learning::CompensationOptions& options = *spec.learning;
  LearningRun run;
  TrialEnds ends(observer);
  body::StartSpec start = spec.start;
  start.seed = options.seed;  // a noisy sensor's draws follow the learning run's seed
  sim::Stepper stepper(model, start, spec.faults, &ends, spec.record.steps ? &run.record : nullptr);
  sim::SimBody body(stepper);
  run.result = learning::compensate(body, options);
  run.learning_end_step = stepper.step_count();
  if (run.result.steering) {
    // Walk on as the learner left the robot: its periods and its steering reflex.
    stepper.set_before_step([&run, &options](sim::Stepper& s) {
      neural::ControllerState& c = s.state().controller;
      c.drive =
          learning::steer(options.steering_params, *run.result.steering, s.sensed_pose(), c.drive);
    });
  }
  for (long walked = 0; walked < after_steps;) {
    const long n = std::min(options.window_steps, after_steps - walked);
    const body::Pose2 start = stepper.pose();
    stepper.steps(n);
    if (n == options.window_steps) {
      run.after_windows.push_back(body::measure_window(
          start, stepper.pose(), learning::course_yaw_deg(run.result.steering)));
    }
    walked += n;
  }
  run.trial_end_steps = std::move(ends.ends);
  run.final_state = std::move(stepper.state());
  return run;
}

}  // namespace multicpg::experiments
