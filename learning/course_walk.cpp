#include "learning/course_walk.h"

#include <cmath>
#include <utility>

#include "common/errors.h"

namespace multicpg::learning {

CourseWalk::CourseWalk(body::Body& body, const CompensationOptions& options)
    : body_(body), options_(options) {
  if (options.mode == Mode::robust && options.steering == Steering::reflex) {
    state_.steering = start_steering(body.pose());
  }
  take_faults();  // those due at the start came with the body's start
}

CourseWalk::CourseWalk(body::Body& body, const CompensationOptions& options, CourseWalkState saved)
    : body_(body), options_(options), state_(std::move(saved)) {}

void CourseWalk::steps(long n) {
  for (long i = 0; i < n; ++i) {
    if (state_.steering) {
      state_.cut_sum += steer_body(options_.steering_params, *state_.steering, body_);
    }
    body_.step();
    take_faults();
  }
}

body::WindowMeasure CourseWalk::measured_window() {
  const body::Pose2 start = body_.pose();
  state_.cut_sum = 0.0;
  steps(options_.window_steps);
  body::WindowMeasure m =
      body::measure_window(start, body_.pose(), course_yaw_deg(state_.steering));
  if (!std::isfinite(m.yaw_deg) || !std::isfinite(m.path_deg)) {
    throw RuntimeFailure("the body's pose is not a finite number");
  }
  state_.effort = state_.cut_sum / static_cast<double>(options_.window_steps);
  m.steering_effort = state_.effort;
  return m;
}

long CourseWalk::walked() const {
  return body_.step_count();
}

bool CourseWalk::failed() const {
  return state_.any_failed_ever || body_.faults().timeline().empty();
}

std::vector<std::size_t> CourseWalk::failed_now() const {
  return body_.faults().failed_legs();
}

bool CourseWalk::faults_pending() const {
  return body_.faults().pending();
}

int CourseWalk::take_fault_count() {
  return std::exchange(state_.fault_count, 0);
}

bool CourseWalk::take_full_recovery() {
  return std::exchange(state_.full_recovery, false);
}

void CourseWalk::take_faults() {
  const std::vector<body::Fault>& came = body_.faults().applied();
  if (state_.faults_seen == came.size()) return;
  bool recovered = false;
  for (; state_.faults_seen < came.size(); ++state_.faults_seen) {
    state_.any_failed_ever = state_.any_failed_ever || !came[state_.faults_seen].recover;
    recovered = recovered || came[state_.faults_seen].recover;
    ++state_.fault_count;
  }
  if (recovered && body_.faults().in_force().empty()) state_.full_recovery = true;
}

Measurement robust_trial(CourseWalk& walk, const CompensationOptions& options,
                         const Periods& periods, int windows) {
  body::Body& body = walk.body();
  const neural::ControllerModel& model = body.controller_model();
  neural::set_periods(model, body.controller(), periods);
  walk.steps(options.settle_steps.value_or(locked_settle_steps(model, periods)));
  Measurement m;
  for (int w = 0; w < windows; ++w) {
    m.windows.push_back(walk.measured_window());
    m.deviation_deg = std::max(m.deviation_deg, robust_deviation(options, m.windows.back()));
    if (!body::holds(m.deviation_deg, options.search.threshold_deg)) break;
  }
  return m;
}

std::vector<body::WindowMeasure> watch_until_deviation(CourseWalk& walk,
                                                       const CompensationOptions& options) {
  std::vector<body::WindowMeasure> out;
  while (static_cast<long>(out.size()) < options.monitor_windows) {
    const body::WindowMeasure m = walk.measured_window();
    if (walk.take_fault_count() > 0) {
      out.clear();  // the faults' own window: their transient
      continue;
    }
    out.push_back(m);
    if (!body::holds(robust_deviation(options, m), options.search.threshold_deg)) break;
  }
  return out;
}

}  // namespace multicpg::learning
