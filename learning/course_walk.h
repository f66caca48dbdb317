// How a learning run walks a body between its decisions (docs/learning.md "Online compensation"):
// step by step, the steering reflex (learning/steering.h) setting the VRN's steering inputs from
// the sensed pose before every step when the run steers, the faults that came counted, and each
// window measured against the course the run keeps. The one steering hook: the online loop, the
// landscape, the walk after learning, the tunnel and Python all walk through it, so they measure
// the same run the same way.
#pragma once

#include <optional>
#include <vector>

#include "body/deviation.h"
#include "learning/compensation.h"
#include "learning/steering.h"

namespace multicpg::learning {

// What a CourseWalk is doing between two steps, apart from its body: saved with the body's own
// checkpoint, it lets a walk go on from there exactly (the landscape's trials start from one).
struct CourseWalkState {
  std::optional<SteeringState> steering;  // the reflex, when the run steers
  std::size_t faults_seen = 0;            // of the body's applied faults
  bool any_failed_ever = false;
  int fault_count = 0;  // faults and recoveries not yet taken
  bool full_recovery = false;
  double cut_sum = 0.0;  // |swing cut| summed over the window being walked
  double effort = 0.0;   // mean |swing cut| of the last window
};

class CourseWalk {
 public:
  // Starts the reflex at the body's sensed pose when `options` steer (robust mode with
  // Steering::reflex); the faults due at the start came with the body's start.
  CourseWalk(body::Body& body, const CompensationOptions& options);
  // Goes on from `saved` (the body restored to where it was saved).
  CourseWalk(body::Body& body, const CompensationOptions& options, CourseWalkState saved);

  // n controller steps, steering before each when the run steers.
  void steps(long n);
  // One window of options.window_steps: yaw change and path angle against the course (the
  // reflex's line, else the heading at the window's start), and the reflex's mean effort.
  // Throws RuntimeFailure when the body's pose is not finite.
  body::WindowMeasure measured_window();

  long walked() const;
  // Paper mode's "after the failure": a leg has failed (a healthy robot's run, with no fault,
  // counts its windows from the start).
  bool failed() const;
  std::vector<std::size_t> failed_now() const;
  bool faults_pending() const;
  // Faults and recoveries since the last call.
  int take_fault_count();
  // A recovery that left no fault in force, since the last call.
  bool take_full_recovery();
  double effort() const { return state_.effort; }
  const std::optional<SteeringState>& steering() const { return state_.steering; }
  const CourseWalkState& state() const { return state_; }
  body::Body& body() { return body_; }

 private:
  void take_faults();

  body::Body& body_;
  const CompensationOptions& options_;
  CourseWalkState state_;
};

// Robust mode's trial (docs/learning.md "Compensation that holds"): sets `periods` (every CPG
// reset together), walks the settle, then measures up to `windows` windows; E is the worst
// window's robust_deviation, and the trial stops at the first window over the threshold.
Measurement robust_trial(CourseWalk& walk, const CompensationOptions& options,
                         const Periods& periods, int windows);

// Robust mode's watch before its first episode, for a body whose every fault came at its start
// (the landscape's start, experiments/landscape.h): the window the faults came in is skipped (it
// measures their transient), then windows are walked until one does not hold (the detecting
// window, last) or options.monitor_windows have held. What compensate() walks up to its first
// detection (tests/test_learning_sim.cpp holds them equal).
std::vector<body::WindowMeasure> watch_until_deviation(CourseWalk& walk,
                                                       const CompensationOptions& options);

}  // namespace multicpg::learning
