#include "experiments/body_runs.h"

#include <cmath>
#include <numbers>
#include <string>

#include "body/start.h"
#include "common/angles.h"
#include "common/errors.h"
#include "common/limits.h"
#include "learning/course_walk.h"

namespace multicpg::experiments {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// The options a walk that only steers is made with: robust mode's reflex of `steering`, or none.
learning::CompensationOptions steering_options(
    const std::optional<learning::SteeringParams>& steering) {
  learning::CompensationOptions o;
  o.mode = learning::Mode::robust;
  o.steering = steering ? learning::Steering::reflex : learning::Steering::off;
  if (steering) o.steering_params = *steering;
  return o;
}

}  // namespace

BodyWalk walk_body(body::Body& body, long settle, long steps, long window) {
  for (long i = 0; i < settle; ++i) body.step();
  BodyWalk out;
  out.boundaries.push_back(body.pose());
  for (long i = 1; i <= steps; ++i) {
    body.step();
    if (i % window == 0) out.boundaries.push_back(body.pose());
  }
  out.steps = steps;
  out.last = body.pose();
  return out;
}

BodyLearning learn_body(body::Body& body, const learning::CompensationOptions& options,
                        const learning::LearnerData& data, long after_steps) {
  BodyLearning out;
  out.result = learning::compensate(body, options, data);
  out.learning_end_step = body.step_count();
  if (after_steps <= 0) return out;
  // Walk on as the learner left the robot: its periods and its steering reflex, every fault that
  // came already taken.
  learning::CourseWalkState state;
  state.steering = out.result.steering;
  state.faults_seen = body.faults().applied().size();
  learning::CourseWalk walk(body, options, state);
  long walked = 0;
  for (; walked + options.window_steps <= after_steps; walked += options.window_steps) {
    out.after_windows.push_back(walk.measured_window());
  }
  walk.steps(after_steps - walked);
  out.result.steering = walk.steering();
  return out;
}

TunnelWalk walk_tunnel(RunBody& run, double length_m, long max_steps,
                       const std::optional<learning::SteeringParams>& steering) {
  body::Body& body = run.body();
  const learning::CompensationOptions options = steering_options(steering);
  learning::CourseWalk walk(body, options);
  TunnelWalk out;
  const body::Pose2 start = body.pose();
  const double heading = run.corridor_heading_deg().value_or(start.yaw_deg) * kRadPerDeg;
  // How far along the tunnel: the simulated scene's ground, else the sensed position along the
  // start heading (nothing without one).
  const auto along = [&]() -> std::optional<double> {
    if (const std::optional<double> ground = run.along_ground_m()) return ground;
    const body::Pose2 p = body.pose();
    if (!p.has_position() || !start.has_position()) return std::nullopt;
    return (p.x - start.x) * std::cos(heading) + (p.y - start.y) * std::sin(heading);
  };
  bool known = along().has_value();
  while (out.steps < max_steps) {
    walk.steps(1);
    ++out.steps;
    if (run.touches_wall()) {
      out.touched_wall = true;
      break;
    }
    const std::optional<double> a = along();
    known = known || a.has_value();
    if (a && *a >= length_m) {
      out.passed = true;
      break;
    }
  }
  if (!out.passed && known) out.passed = false;
  const body::Pose2 end = body.pose();
  const double dx = end.x - start.x;
  const double dy = end.y - start.y;
  out.forward_m = dx * std::cos(heading) + dy * std::sin(heading);
  out.lateral_m = -dx * std::sin(heading) + dy * std::cos(heading);
  out.yaw_change_deg = wrap_degrees(end.yaw_deg - start.yaw_deg);
  return out;
}

}  // namespace multicpg::experiments
