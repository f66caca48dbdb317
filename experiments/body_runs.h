// walk, learn and the tunnel's walk, written once for every body (experiments/bodies.h): the
// simulation and a real robot run the same code, measure through the same senses and steer
// through the one steering hook (learning/course_walk.h).
#pragma once

#include <optional>
#include <vector>

#include "body/body.h"
#include "body/deviation.h"
#include "experiments/bodies.h"
#include "learning/compensation.h"
#include "learning/steering.h"

namespace multicpg::experiments {

// walk: `settle` steps, then `steps` measured: the pose as the body senses it where measuring
// began, at each complete window of `window` steps and at the end (body::measure_walk makes the
// measures of them).
struct BodyWalk {
  long steps = 0;  // measured
  std::vector<body::Pose2> boundaries;
  body::Pose2 last;
};
BodyWalk walk_body(body::Body& body, long settle, long steps, long window);
// (body::validate_walk checks its numbers.)

// learn: learning::compensate on the body, then `after_steps` more with the learned controller
// (its periods and, with the reflex, its steering), each complete window measured as robust mode
// measures (does the final controller hold? docs/learning.md).
struct BodyLearning {
  learning::LearningResult result;
  long learning_end_step = 0;  // steps walked when learning stopped
  std::vector<body::WindowMeasure> after_windows;
};
// The learner learns from `data` (learner_data(spec), resolved before the body opens).
BodyLearning learn_body(body::Body& body, const learning::CompensationOptions& options,
                        const learning::LearnerData& data, long after_steps);

// The tunnel's walk (paper §5, Table 1): from where the body stands, step by step until it has
// gone `length_m` along the ground (a simulated body's scene) or along its start heading (a body
// that senses its position), touches a wall (where the body can tell), or `max_steps` have
// passed. With `steering` the reflex holds the line the robot starts on.
struct TunnelWalk {
  long steps = 0;
  bool touched_wall = false;
  std::optional<bool> passed;  // empty: the body senses no position, so nobody can tell
  // The trunk's displacement along the tunnel's axis (RunBody::corridor_heading_deg, else the
  // start heading) and across it, + = left; NaN without a sensed position.
  double forward_m = 0.0;
  double lateral_m = 0.0;
  double yaw_change_deg = 0.0;  // as sensed
};
TunnelWalk walk_tunnel(RunBody& body, double length_m, long max_steps,
                       const std::optional<learning::SteeringParams>& steering);

}  // namespace multicpg::experiments
