// What happens to a walking robot, as the one stepping loop (sim/stepper.h) and the learner
// (learning/compensation.h) report it to an observer: faults, detections, trials, episodes
// (issue 8). Plain types, no MuJoCo, so the learner and its fake walker can use them too.
#pragma once

#include <cstddef>
#include <vector>

#include "neural/controller.h"
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
  bool operator==(const Fault&) const = default;
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
// disables every leg, or has a step outside 0..kMaxSteps.
void validate(const robot::Morphology& morph, const FaultTimeline& faults);

// Puts a timeline in step order, a recovery before a failure at the same step (so a leg may
// recover and another fail at one step); events of one step otherwise keep their order.
void sort_timeline(FaultTimeline& faults);

// "R1@0" style timeline: the legs fail before step `step`; no legs = no fault.
FaultTimeline fail_at(const std::vector<std::size_t>& legs, long step);

// Every leg that fails at some point of the timeline, in leg order.
std::vector<std::size_t> failing_legs(const FaultTimeline& faults);
// The legs still failed when the whole timeline has come, in leg order.
std::vector<std::size_t> failed_after(const robot::Morphology& morph, const FaultTimeline& faults);

// A run's faults as they come (SPEC §4, issue 8): its timeline, how much of it has come, and the
// legs failed now. The one home of fault bookkeeping: sim::Stepper applies a run's faults through
// it (and the learner's fake walker likewise), and the learner reads from it what came.
class FaultSchedule {
 public:
  // Throws BadInput (validate's message) for a bad timeline.
  FaultSchedule(const robot::Morphology& morph, FaultTimeline timeline);
  // A schedule part-way through its timeline (a checkpoint read back, sim/checkpoint.h): the
  // first `come` faults of the timeline have come, and `applied` is every fault that has, in
  // order. Throws BadInput for a bad timeline, `come` past its end, or an `applied` list that
  // does not hold those faults in order or could not have happened (validate's message).
  FaultSchedule(const robot::Morphology& morph, FaultTimeline timeline, std::size_t come,
                const std::vector<Fault>& applied);

  // Applies to `controller`, in order, the faults due before step `step` (whose step is at most
  // `step`); returns how many came.
  std::size_t apply_due(long step, neural::ControllerState& controller);
  // Legs fail (or work again) now, out of the timeline (the viewer's keys, Python). Throws
  // BadInput (validate's message) for a leg that has already failed, one that has not, or
  // failing every leg. The timeline still comes as planned.
  void apply_now(const robot::Morphology& morph, const Fault& fault,
                 neural::ControllerState& controller);

  const FaultTimeline& timeline() const { return timeline_; }
  // Every fault that has come, from the timeline or not, in order.
  const std::vector<Fault>& applied() const { return applied_; }
  // Whether `leg` has failed now (false for a leg out of range).
  bool failed(std::size_t leg) const { return leg < failed_.size() && failed_[leg]; }
  std::vector<std::size_t> failed_legs() const;
  // Faults of the timeline still to come.
  bool pending() const { return next_ < timeline_.size(); }
  // How many faults of the timeline have come.
  std::size_t come() const { return next_; }

 private:
  void apply(const Fault& fault, neural::ControllerState& controller);

  FaultTimeline timeline_;
  std::size_t next_ = 0;
  std::vector<Fault> applied_;
  std::vector<bool> failed_;
};

// The fault or recovery event a fault makes.
Event fault_event(const Fault& fault);

}  // namespace multicpg::sim
