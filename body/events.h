// What happens to a walking robot, as the one stepping loop (sim/stepper.h) and the learner
// (learning/compensation.h) report it to an observer: faults, detections, trials, episodes
// (docs/learning.md). Plain types, no MuJoCo, so the learner and its fake walker can use them
// too.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "body/faults.h"
#include "common/enum_names.h"
#include "neural/controller.h"
#include "robot/morphology.h"

namespace multicpg::body {

// Largest number of steps of any run, settle and warm-up included: 10^8 steps are 43 days of
// walking at 27 Hz; past it step counts would overflow their sums.
inline constexpr long kMaxSteps = 100'000'000;

enum class EventKind {
  fault,        // legs failed
  recovery,     // legs work again
  detection,    // a window deviated more than the threshold: learning starts
  trial_start,  // a candidate combination is set
  trial_end,    // its windows were measured and it was kept or rejected
  episode_end,  // learning stopped: held (converged) or not
};

// Each kind's name on disk (replays, hardware records).
inline constexpr auto kEventKindNames =
    enum_names<EventKind>({{EventKind::fault, "fault"},
                           {EventKind::recovery, "recovery"},
                           {EventKind::detection, "detection"},
                           {EventKind::trial_start, "trial_start"},
                           {EventKind::trial_end, "trial_end"},
                           {EventKind::episode_end, "episode_end"}});
inline std::string_view to_string(EventKind kind) {
  return kEventKindNames.name(kind);
}

struct Event {
  EventKind kind = EventKind::fault;
  long step = 0;                  // controller steps since the run started
  std::vector<std::size_t> legs;  // fault, recovery: the legs struck (none: the sensor)
  std::optional<Fault> fault;     // fault, recovery: what came
  int episode = 0;                // 1-based learning episode (detection .. episode_end)
  int trial = 0;                  // 1-based trial of the episode
  std::vector<int> periods;       // trial_start/end, episode_end: the combination
  double deviation_deg = 0.0;     // detection, trial_end, episode_end
  bool accepted = false;          // trial_end: kept; episode_end: held under the threshold
  // trial_end: the learner's own details of the trial (learning::TrialRecord::details)
  nlohmann::json details = nlohmann::json::object();
};

// Throws BadInput (one line, leg and joint names) for a timeline that is not sorted, has a step
// outside 0..kMaxSteps, names a leg out of range or twice in one event, names a joint where the
// kind strikes whole legs (or none where it strikes joints), locks a joint outside its limits,
// strikes what a fault of its kind already strikes, recovers what is not struck, or disables
// every leg.
void validate(const robot::Morphology& morph, const FaultTimeline& faults);

// Puts a timeline in step order, a recovery before a failure at the same step (so a leg may
// recover and another fail at one step); events of one step otherwise keep their order.
void sort_timeline(FaultTimeline& faults);

// "R1@0" style timeline: the legs fail (leg faults) before step `step`; no legs = no fault.
FaultTimeline fail_at(const std::vector<std::size_t>& legs, long step);

// Every leg that loses its function (a leg fault) at some point of the timeline, in leg order.
std::vector<std::size_t> failing_legs(const FaultTimeline& faults);
// The legs whose leg fault is still in force when the whole timeline has come, in leg order.
std::vector<std::size_t> failed_after(const robot::Morphology& morph, const FaultTimeline& faults);
// The faults in force when the whole timeline has come, one per leg (or the sensor) struck.
FaultTimeline in_force_after(const robot::Morphology& morph, const FaultTimeline& faults);
// Puts one fault (or recovery) into `in_force` (faults in force, one per leg or the sensor).
// Throws BadInput (validate's message) when it cannot happen now; `in_force` may then be
// partly changed.
void take_fault(const robot::Morphology& morph, const Fault& fault, FaultTimeline& in_force);

// A run's faults as they come (docs/faults.md "When faults strike"): its timeline, how much of it
// has come, and what is in force now. The one home of fault bookkeeping: a simulated run keeps it
// in its state (sim::FaultState, which sim::Stepper applies faults through; the learner's fake
// walker keeps one likewise), and the learner, films and the viewer read from it what came and
// what is in force. A leg fault is the controller's (the leg holds its posture,
// neural::set_disabled); every other kind is the physics' (sim/fault_effects.h), which the stepper
// applies to what came.
class FaultSchedule {
 public:
  // No robot and no faults (a state not yet made).
  FaultSchedule() = default;
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
  // A fault (or recovery) now, out of the timeline (the viewer's keys, Python). Throws BadInput
  // (validate's message) when it cannot happen now. The timeline still comes as planned.
  void apply_now(const Fault& fault, neural::ControllerState& controller);

  const FaultTimeline& timeline() const { return timeline_; }
  // Every fault that has come, from the timeline or not, in order.
  const std::vector<Fault>& applied() const { return applied_; }
  // The faults in force now, one per leg (or the sensor) struck, in the order they came.
  const FaultTimeline& in_force() const { return in_force_; }
  // Whether `leg` has lost its function now (a leg fault; false for a leg out of range).
  bool failed(std::size_t leg) const;
  std::vector<std::size_t> failed_legs() const;
  // Faults of the timeline still to come.
  bool pending() const { return next_ < timeline_.size(); }
  // How many faults of the timeline have come.
  std::size_t come() const { return next_; }

 private:
  void apply(const Fault& fault, neural::ControllerState& controller);

  robot::Morphology morph_;
  FaultTimeline timeline_;
  std::size_t next_ = 0;
  std::vector<Fault> applied_;
  FaultTimeline in_force_;
};

// The fault or recovery event a fault makes.
Event fault_event(const Fault& fault);

}  // namespace multicpg::body
