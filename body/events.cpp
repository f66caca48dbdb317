#include "body/events.h"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <string>
#include <utility>

#include "common/errors.h"
#include "robot/joint_map.h"

namespace multicpg::body {

namespace {

bool is_leg_fault(const Fault& f) {
  return std::holds_alternative<LegFault>(f.kind);
}

// What an atom of a fault strikes, for messages: "leg R1", "R2.CTr", "L1" or "the yaw sensor".
std::string target_name(const robot::Morphology& morph, const Fault& atom) {
  if (atom.legs.empty()) return "the yaw sensor";
  const std::string& leg = morph.legs[atom.legs.front()].name;
  if (is_leg_fault(atom)) return "leg " + leg;
  return atom.joint ? leg + "." + std::string(robot::to_string(*atom.joint)) : leg;
}

// The fault split into what it strikes: one fault per leg, or the sensor fault itself.
FaultTimeline atoms(const Fault& f) {
  if (f.legs.empty()) return {f};
  FaultTimeline out;
  for (std::size_t leg : f.legs) {
    Fault a = f;
    a.legs = {leg};
    out.push_back(std::move(a));
  }
  return out;
}

// The shape of one fault: its step, legs, joint and value as its kind allows.
void check_shape(const robot::Morphology& morph, const Fault& f, long previous) {
  const std::string what = f.recover ? "a recovery" : "a fault";
  if (f.step < 0 || f.step > kMaxSteps) {
    throw BadInput(what + "'s step must be in 0.." + std::to_string(kMaxSteps) + ", got " +
                   std::to_string(f.step));
  }
  if (f.step < previous) throw BadInput("faults must be listed in step order");
  const std::string kind(kind_name(f.kind));
  const Strikes s = strikes(f.kind);
  if (s == Strikes::sensor) {
    if (!f.legs.empty() || f.joint) throw BadInput(kind + " strikes the yaw sensor, not legs");
    return;
  }
  if (f.legs.empty()) throw BadInput(what + " names no leg");
  std::vector<bool> seen(morph.size(), false);
  for (std::size_t leg : f.legs) {
    if (leg >= morph.size()) {
      throw BadInput("the " + morph.name + " has no leg number " + std::to_string(leg));
    }
    if (seen[leg]) {
      throw BadInput("leg " + morph.legs[leg].name + " is listed twice in one fault");
    }
    seen[leg] = true;
  }
  if (s == Strikes::legs && f.joint) {
    throw BadInput(kind + " strikes whole legs, not one joint: write LEGS:" + kind);
  }
  if (s == Strikes::joints && !f.joint) {
    throw BadInput(kind + " strikes one joint of a leg: write LEG.JOINT:" + kind +
                   " (joints TC, CTr, FTi)");
  }
  if (const auto* locked = std::get_if<LockedJoint>(&f.kind); locked && locked->value) {
    for (std::size_t leg : f.legs) {
      const robot::AngleRange r = robot::joint_limits(morph.legs[leg].type, *f.joint);
      const double deg = 180.0 / std::numbers::pi;
      if (*locked->value < r.lo * deg || *locked->value > r.hi * deg) {
        throw BadInput(fmt::format("{}.{} cannot lock at {} deg: its limits are {:.0f}..{:.0f} deg",
                                   morph.legs[leg].name, robot::to_string(*f.joint), *locked->value,
                                   r.lo * deg, r.hi * deg));
      }
    }
  }
}

}  // namespace

void take_fault(const robot::Morphology& morph, const Fault& f, FaultTimeline& in_force) {
  const std::string at = " at step " + std::to_string(f.step);
  const std::string kind(kind_name(f.kind));
  for (const Fault& atom : atoms(f)) {
    const std::string target = target_name(morph, atom);
    if (f.recover) {
      const auto match = std::find_if(in_force.begin(), in_force.end(), [&](const Fault& a) {
        return a.kind.index() == atom.kind.index() && a.legs == atom.legs && a.joint == atom.joint;
      });
      if (match == in_force.end()) {
        throw BadInput(is_leg_fault(atom)
                           ? target + " recovers" + at + " but has not failed before"
                           : target + " recovers from " + kind + at + " but is not " + kind);
      }
      in_force.erase(match);
      continue;
    }
    if (std::any_of(in_force.begin(), in_force.end(),
                    [&](const Fault& a) { return same_target(a, atom); })) {
      throw BadInput(is_leg_fault(atom) ? target + " fails" + at + " but has already failed"
                                        : target + " is already " + kind + at);
    }
    Fault stored = atom;
    stored.recover = false;
    in_force.push_back(std::move(stored));
  }
  std::vector<bool> failed(morph.size(), false);
  for (const Fault& a : in_force) {
    if (is_leg_fault(a)) failed[a.legs.front()] = true;
  }
  if (std::all_of(failed.begin(), failed.end(), [](bool b) { return b; })) {
    throw BadInput("every leg of the " + morph.name + " has failed" + at + ": it cannot walk");
  }
}

void validate(const robot::Morphology& morph, const FaultTimeline& faults) {
  FaultTimeline in_force;
  long previous = 0;
  for (const Fault& f : faults) {
    check_shape(morph, f, previous);
    previous = f.step;
    take_fault(morph, f, in_force);
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
    if (!f.recover && is_leg_fault(f)) legs.insert(legs.end(), f.legs.begin(), f.legs.end());
  }
  std::sort(legs.begin(), legs.end());
  legs.erase(std::unique(legs.begin(), legs.end()), legs.end());
  return legs;
}

FaultTimeline in_force_after(const robot::Morphology& morph, const FaultTimeline& faults) {
  FaultTimeline in_force;
  for (const Fault& f : faults) take_fault(morph, f, in_force);
  return in_force;
}

std::vector<std::size_t> failed_after(const robot::Morphology& morph, const FaultTimeline& faults) {
  std::vector<std::size_t> legs;
  for (const Fault& a : in_force_after(morph, faults)) {
    if (is_leg_fault(a)) legs.push_back(a.legs.front());
  }
  std::sort(legs.begin(), legs.end());
  return legs;
}

FaultSchedule::FaultSchedule(const robot::Morphology& morph, FaultTimeline timeline)
    : morph_(morph), timeline_(std::move(timeline)) {
  validate(morph_, timeline_);
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
    apply_now(f, scratch);
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

void FaultSchedule::apply_now(const Fault& fault, neural::ControllerState& controller) {
  check_shape(morph_, fault, fault.step);
  FaultTimeline check = in_force_;
  take_fault(morph_, fault, check);
  apply(fault, controller);
}

void FaultSchedule::apply(const Fault& fault, neural::ControllerState& controller) {
  // Validated with the whole timeline (or by apply_now): this cannot throw.
  take_fault(morph_, fault, in_force_);
  if (is_leg_fault(fault)) {
    for (std::size_t leg : fault.legs) neural::set_disabled(controller, leg, !fault.recover);
  }
  applied_.push_back(fault);
}

bool FaultSchedule::failed(std::size_t leg) const {
  return std::any_of(in_force_.begin(), in_force_.end(),
                     [&](const Fault& a) { return is_leg_fault(a) && a.legs.front() == leg; });
}

std::vector<std::size_t> FaultSchedule::failed_legs() const {
  std::vector<std::size_t> legs;
  for (const Fault& a : in_force_) {
    if (is_leg_fault(a)) legs.push_back(a.legs.front());
  }
  std::sort(legs.begin(), legs.end());
  return legs;
}

Event fault_event(const Fault& fault) {
  Event e;
  e.kind = fault.recover ? EventKind::recovery : EventKind::fault;
  e.step = fault.step;
  e.legs = fault.legs;
  e.fault = fault;
  return e;
}

}  // namespace multicpg::body
