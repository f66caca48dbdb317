#include "sim/events.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/errors.h"

namespace multicpg::sim {

const char* to_string(EventKind kind) {
  switch (kind) {
    case EventKind::fault:
      return "fault";
    case EventKind::recovery:
      return "recovery";
    case EventKind::detection:
      return "detection";
    case EventKind::trial_start:
      return "trial_start";
    case EventKind::trial_end:
      return "trial_end";
    case EventKind::episode_end:
      return "episode_end";
  }
  return "event";
}

void validate(const robot::Morphology& morph, const FaultTimeline& faults) {
  std::vector<bool> failed(morph.size(), false);
  long previous = 0;
  for (const Fault& f : faults) {
    const char* what = f.recover ? "a recovery" : "a fault";
    if (f.step < 0 || f.step > kMaxSteps) {
      throw BadInput(std::string(what) + "'s step must be in 0.." + std::to_string(kMaxSteps) +
                     ", got " + std::to_string(f.step));
    }
    if (f.step < previous) throw BadInput("faults must be listed in step order");
    previous = f.step;
    if (f.legs.empty()) throw BadInput(std::string(what) + " names no leg");
    std::vector<bool> seen(morph.size(), false);
    for (std::size_t leg : f.legs) {
      if (leg >= morph.size()) {
        throw BadInput("the " + morph.name + " has no leg number " + std::to_string(leg));
      }
      const std::string& name = morph.legs[leg].name;
      if (seen[leg]) throw BadInput("leg " + name + " is listed twice in one fault");
      seen[leg] = true;
      if (f.recover && !failed[leg]) {
        throw BadInput("leg " + name + " recovers at step " + std::to_string(f.step) +
                       " but has not failed before");
      }
      if (!f.recover && failed[leg]) {
        throw BadInput("leg " + name + " fails at step " + std::to_string(f.step) +
                       " but has already failed");
      }
      failed[leg] = !f.recover;
    }
    if (std::all_of(failed.begin(), failed.end(), [](bool b) { return b; })) {
      throw BadInput("every leg of the " + morph.name + " has failed at step " +
                     std::to_string(f.step) + ": it cannot walk");
    }
  }
}

void sort_timeline(FaultTimeline& faults) {
  std::stable_sort(faults.begin(), faults.end(), [](const Fault& a, const Fault& b) {
    return a.step != b.step ? a.step < b.step : a.recover && !b.recover;
  });
}

FaultTimeline fail_at(const std::vector<std::size_t>& legs, long step) {
  if (legs.empty()) return {};
  return {Fault{step, legs, false}};
}

std::vector<std::size_t> failing_legs(const FaultTimeline& faults) {
  std::vector<std::size_t> legs;
  for (const Fault& f : faults) {
    if (!f.recover) legs.insert(legs.end(), f.legs.begin(), f.legs.end());
  }
  std::sort(legs.begin(), legs.end());
  legs.erase(std::unique(legs.begin(), legs.end()), legs.end());
  return legs;
}

std::vector<std::size_t> failed_after(const robot::Morphology& morph, const FaultTimeline& faults) {
  std::vector<bool> failed(morph.size(), false);
  for (const Fault& f : faults) {
    for (std::size_t leg : f.legs) failed.at(leg) = !f.recover;
  }
  std::vector<std::size_t> legs;
  for (std::size_t leg = 0; leg < failed.size(); ++leg) {
    if (failed[leg]) legs.push_back(leg);
  }
  return legs;
}

FaultSchedule::FaultSchedule(const robot::Morphology& morph, FaultTimeline timeline)
    : timeline_(std::move(timeline)), failed_(morph.size(), false) {
  validate(morph, timeline_);
}

FaultSchedule::FaultSchedule(const robot::Morphology& morph, FaultTimeline timeline,
                             std::size_t come, const std::vector<Fault>& applied)
    : FaultSchedule(morph, std::move(timeline)) {
  if (come > timeline_.size()) {
    throw BadInput(std::to_string(come) + " faults have come of a timeline of " +
                   std::to_string(timeline_.size()));
  }
  // Replayed on a scratch controller: each fault checked as apply_now checks it.
  neural::ControllerState scratch;
  scratch.legs.resize(morph.size());
  std::size_t from_timeline = 0;
  for (const Fault& f : applied) {
    if (from_timeline < come && f == timeline_[from_timeline]) ++from_timeline;
    apply_now(morph, f, scratch);
  }
  if (from_timeline != come) {
    throw BadInput("the faults that came do not hold the first " + std::to_string(come) +
                   " of the timeline");
  }
  next_ = come;
}

std::size_t FaultSchedule::apply_due(long step, neural::ControllerState& controller) {
  std::size_t came = 0;
  for (; next_ < timeline_.size() && timeline_[next_].step <= step; ++next_, ++came) {
    apply(timeline_[next_], controller);
  }
  return came;
}

void FaultSchedule::apply_now(const robot::Morphology& morph, const Fault& fault,
                              neural::ControllerState& controller) {
  // Validated as a timeline of two events: the legs failed now, then this fault.
  FaultTimeline check;
  const std::vector<std::size_t> now = failed_legs();
  if (!now.empty()) check.push_back({fault.step, now, false});
  check.push_back(fault);
  validate(morph, check);
  apply(fault, controller);
}

void FaultSchedule::apply(const Fault& fault, neural::ControllerState& controller) {
  for (std::size_t leg : fault.legs) {
    neural::set_disabled(controller, leg, !fault.recover);
    failed_[leg] = !fault.recover;
  }
  applied_.push_back(fault);
}

std::vector<std::size_t> FaultSchedule::failed_legs() const {
  std::vector<std::size_t> legs;
  for (std::size_t leg = 0; leg < failed_.size(); ++leg) {
    if (failed_[leg]) legs.push_back(leg);
  }
  return legs;
}

Event fault_event(const Fault& fault) {
  Event e;
  e.kind = fault.recover ? EventKind::recovery : EventKind::fault;
  e.step = fault.step;
  e.legs = fault.legs;
  return e;
}

}  // namespace multicpg::sim
