// What a trial's E is made of (docs/learning.md "Deviation" and "What learn prints"): the paper's
// |yaw change| over one window (paper §3); robust mode's worst of |yaw change| and |path angle|;
// and, while the steering reflex steers, its mean swing cut too, scaled so that the most a
// window may ask of it (SteeringParams::max_effort) reads as the threshold. One home for it: the
// online loop, the landscapes, the benchmark and the learners' models all judge a window by it.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "body/deviation.h"

namespace multicpg::learning {

// Robust mode: consecutive windows a combination must hold to be accepted.
inline constexpr int kDefaultHoldWindows = 3;

struct Criterion {
  bool path = true;  // robust mode: the path angle counts
  // With the reflex: its effort `max_effort` reads as `threshold_deg`; max_effort 0 = no reflex.
  double threshold_deg = 0.0;
  double max_effort = 0.0;
  // The windows a trial walks, each of which must hold: paper mode's one, robust mode's
  // hold_windows.
  int trial_windows = kDefaultHoldWindows;

  bool steers() const { return max_effort > 0.0; }
  // The reflex's mean swing cut (0..1) in degrees of E; 0 without the reflex.
  double effort_deg(double effort) const {
    return steers() ? threshold_deg * effort / max_effort : 0.0;
  }
  // E of one window.
  double error(double yaw_deg, double path_deg, double effort) const {
    double e = std::abs(yaw_deg);
    if (path) e = std::max(e, std::abs(path_deg));
    if (steers()) e = std::max(e, effort_deg(effort));
    return e;
  }
  double error(const body::WindowMeasure& w) const {
    return error(w.yaw_deg, w.path_deg, w.steering_effort);
  }
  // E of a trial: its worst window (paper mode walks one; robust mode up to hold_windows,
  // stopping at the first over the threshold).
  double error(const std::vector<body::WindowMeasure>& windows) const {
    double e = 0.0;
    for (const body::WindowMeasure& w : windows) e = std::max(e, error(w));
    return e;
  }
  bool operator==(const Criterion&) const = default;
};

// The paper's: |yaw change| alone, one window a trial.
inline constexpr Criterion kPaperCriterion{false, 0.0, 0.0, 1};
// Robust mode without the reflex: the worst of |yaw change| and |path angle|.
inline constexpr Criterion kPeriodsAloneCriterion{true, 0.0, 0.0, kDefaultHoldWindows};
// Robust mode with the reflex, its effort limit `max_effort` read as `threshold_deg`.
inline Criterion reflex_criterion(double threshold_deg, double max_effort) {
  return {true, threshold_deg, max_effort, kDefaultHoldWindows};
}

}  // namespace multicpg::learning
