#include "learning/course_walk.h"

#include <cmath>
#include <utility>

#include "common/errors.h"

namespace multicpg::learning {

CourseWalk::CourseWalk(Walker& walker, const CompensationOptions& options)
    : walker_(walker), options_(options) {
  if (options.mode == Mode::robust && options.steering == Steering::reflex) {
    state_.steering = start_steering(walker.pose());
  }
  take_faults();  // those due at the start came with the walker's start
}

CourseWalk::CourseWalk(Walker& walker, const CompensationOptions& options, CourseWalkState saved)
    : walker_(walker), options_(options), state_(std::move(saved)) {}

void CourseWalk::steps(long n) {
  for (long i = 0; i < n; ++i) {
    if (state_.steering) {
      neural::ControllerState& c = walker_.controller();
      c.drive = steer(options_.steering_params, *state_.steering, walker_.pose(), c.drive);
      state_.cut_sum += std::abs(state_.steering->last_cut);
    }
    walker_.step();
    take_faults();
  }
}

sim::WindowMeasure CourseWalk::measured_window() {
  const sim::Pose2 start = walker_.pose();
  state_.cut_sum = 0.0;
  steps(options_.window_steps);
  sim::WindowMeasure m =
      sim::measure_window(start, walker_.pose(), course_yaw_deg(state_.steering));
  if (!std::isfinite(m.yaw_deg) || !std::isfinite(m.path_deg)) {
    throw RuntimeFailure("the walker's pose is not a finite number");
  }
  state_.effort = state_.cut_sum / static_cast<double>(options_.window_steps);
  m.steering_effort = state_.effort;
  return m;
}

long CourseWalk::walked() const {
  return walker_.step_count();
}

bool CourseWalk::failed() const {
  return state_.any_failed_ever || walker_.faults().timeline().empty();
}

std::vector<std::size_t> CourseWalk::failed_now() const {
  return walker_.faults().failed_legs();
}

bool CourseWalk::faults_pending() const {
  return walker_.faults().pending();
}

int CourseWalk::take_fault_count() {
  return std::exchange(state_.fault_count, 0);
}

bool CourseWalk::take_full_recovery() {
  return std::exchange(state_.full_recovery, false);
}

void CourseWalk::take_faults() {
  const std::vector<sim::Fault>& came = walker_.faults().applied();
  if (state_.faults_seen == came.size()) return;
  bool recovered = false;
  for (; state_.faults_seen < came.size(); ++state_.faults_seen) {
    state_.any_failed_ever = state_.any_failed_ever || !came[state_.faults_seen].recover;
    recovered = recovered || came[state_.faults_seen].recover;
    ++state_.fault_count;
  }
  if (recovered && walker_.faults().in_force().empty()) state_.full_recovery = true;
}

Measurement robust_trial(CourseWalk& walk, const CompensationOptions& options,
                         const Periods& periods, int windows) {
  Walker& walker = walk.walker();
  const neural::ControllerModel& model = walker.controller_model();
  neural::set_periods(model, walker.controller(), periods);
  walk.steps(options.settle_steps.value_or(locked_settle_steps(model, periods)));
  Measurement m;
  for (int w = 0; w < windows; ++w) {
    m.windows.push_back(walk.measured_window());
    m.deviation_deg = std::max(m.deviation_deg, robust_deviation(options, m.windows.back()));
    if (!sim::holds(m.deviation_deg, options.annealing.threshold_deg)) break;
  }
  return m;
}

std::vector<sim::WindowMeasure> watch_until_deviation(CourseWalk& walk,
                                                      const CompensationOptions& options) {
  std::vector<sim::WindowMeasure> out;
  while (static_cast<long>(out.size()) < options.monitor_windows) {
    const sim::WindowMeasure m = walk.measured_window();
    if (walk.take_fault_count() > 0) {
      out.clear();  // the faults' own window: their transient
      continue;
    }
    out.push_back(m);
    if (!sim::holds(robust_deviation(options, m), options.annealing.threshold_deg)) break;
  }
  return out;
}

}  // namespace multicpg::learning
