// What happens to a walking robot, as the one stepping loop (sim/stepper.h) and the learner
// (learning/compensation.h) report it to an observer: faults, detections, trials, episodes
// (issue 8). Plain types, no MuJoCo, so the learner and its fake walker can use them too.
#pragma once

#include <cstddef>
#include <vector>

#include "robot/morphology.h"

namespace multicpg::sim {

// Largest number of steps of any run, settle and warm-up included: 10^8 steps are 43 days of
// walking at 27 Hz; past it step counts would overflow their sums.
inline constexpr long kMaxSteps = 100'000'000;

// Legs that fail (or recover) before controller step `step` of a run (SPEC §4: any step).
struct Fault {
  long step = 0;
  std::vector<std::size_t> legs;
  bool recover = false;
};
// Sorted by step; several events may share a step.
using FaultTimeline = std::vector<Fault>;

enum class EventKind {
  fault,        // legs failed
  recovery,     // legs work again
  detection,    // a window deviated more than the threshold: learning starts
  trial_start,  // a candidate combination is set
  trial_end,    // its windows were measured and it was kept or rejected
  episode_end,  // learning stopped: held (converged) or not
};

struct Event {
  EventKind kind = EventKind::fault;
  long step = 0;                  // controller steps since the run started
  std::vector<std::size_t> legs;  // fault, recovery
  int episode = 0;                // 1-based learning episode (detection .. episode_end)
  int trial = 0;                  // 1-based trial of the episode
  std::vector<int> periods;       // trial_start/end, episode_end: the combination
  double deviation_deg = 0.0;     // detection, trial_end, episode_end
  bool accepted = false;          // trial_end: kept; episode_end: held under the threshold
};

const char* to_string(EventKind kind);

// Throws BadInput (one line, leg names) for a timeline that is not sorted, names a leg out of
// range or twice in one event, fails a leg that has already failed, recovers one that has not,
// disables every leg, or has a negative step.
void validate(const robot::Morphology& morph, const FaultTimeline& faults);

}  // namespace multicpg::sim
