#include "experiments/learning_run.h"

namespace multicpg::experiments {

SimWalker::SimWalker(const sim::SimModel& model, sim::WalkRecord* record, StepHook on_step)
    : model_(model),
      state_(sim::make_sim_state(model)),
      record_(record),
      on_step_(std::move(on_step)) {
  if (record_ != nullptr) {
    record_->legs = model.legs.size();
    sim::append_record(model_, state_, true, *record_);
  }
}

void SimWalker::step() {
  sim::sim_step(model_, state_);
  if (record_ != nullptr) sim::append_record(model_, state_, true, *record_);
  if (on_step_) on_step_(state_);
}

double SimWalker::yaw_deg() const {
  return sim::trunk_yaw_deg(model_, state_);
}

void SimWalker::disable(const std::vector<std::size_t>& legs) {
  for (std::size_t leg : legs) neural::set_disabled(state_.controller, leg, true);
}

LearningRun run_learning(const sim::SimModel& model, const learning::CompensationOptions& options,
                         bool record, long after_steps, const StepHook& on_step) {
  LearningRun run;
  SimWalker walker(model, record ? &run.record : nullptr, on_step);
  run.result = learning::compensate(walker, options);
  run.learning_end_step = walker.step_count();
  for (long t = 0; t < after_steps; ++t) walker.step();
  // Each trial is settle + one window long and the last one ends where learning stopped.
  const long trial_steps = run.result.settle_steps + options.window_steps;
  for (std::size_t i = 0; i < run.result.trace.size(); ++i) {
    const auto from_end = static_cast<long>(run.result.trace.size() - 1 - i);
    run.trial_end_steps.push_back(run.learning_end_step - from_end * trial_steps);
  }
  run.final_state = walker.release();
  return run;
}

}  // namespace multicpg::experiments
