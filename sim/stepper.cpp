#include "sim/stepper.h"

#include <algorithm>
#include <string>

#include "common/errors.h"
#include "sim/walk.h"

namespace multicpg::sim {

Stepper::Stepper(const SimModel& model, const StartSpec& start, FaultTimeline faults,
                 Observer* observer, WalkRecord* record, bool record_joints)
    : model_(model),
      state_(start_walk_state(model, start.periods)),
      faults_(std::move(faults)),
      failed_(model.legs.size(), false),
      observer_(observer),
      record_(record),
      record_joints_(record_joints) {
  validate(model.controller.morphology, faults_);
  if (start.warmup < 0) {
    throw BadInput("--warmup must not be negative, got " + std::to_string(start.warmup));
  }
  apply_due_faults();
  warm_up_controller(model_, state_, start.warmup);
  if (record_ != nullptr) {
    record_->legs = model.legs.size();
    append_record(model_, state_, record_joints_, *record_);
  }
}

void Stepper::apply_due_faults() {
  last_faults_.clear();
  while (next_fault_ < faults_.size() && faults_[next_fault_].step <= walked_) {
    const Fault& f = faults_[next_fault_++];
    for (std::size_t leg : f.legs) {
      neural::set_disabled(state_.controller, leg, !f.recover);
      failed_[leg] = !f.recover;
    }
    last_faults_.push_back(f);
    if (observer_ != nullptr) {
      Event e;
      e.kind = f.recover ? EventKind::recovery : EventKind::fault;
      e.step = walked_;
      e.legs = f.legs;
      observer_->on_event(model_, state_, e);
    }
  }
}

void Stepper::step() {
  apply_due_faults();
  if (before_step_) before_step_(*this);
  sim_step(model_, state_);
  ++walked_;
  if (record_ != nullptr) append_record(model_, state_, record_joints_, *record_);
  if (observer_ != nullptr) observer_->on_step(model_, state_);
}

void Stepper::steps(long n) {
  for (long i = 0; i < n; ++i) step();
}

void Stepper::set_failed(const std::vector<std::size_t>& legs, bool failed) {
  FaultTimeline check;
  std::vector<std::size_t> now;
  for (std::size_t leg = 0; leg < failed_.size(); ++leg) {
    if (failed_[leg]) now.push_back(leg);
  }
  if (!now.empty()) check.push_back({walked_, now, false});
  const Fault fault{walked_, legs, !failed};
  check.push_back(fault);
  validate(model_.controller.morphology, check);
  for (std::size_t leg : legs) {
    neural::set_disabled(state_.controller, leg, failed);
    failed_[leg] = failed;
  }
  if (observer_ != nullptr) {
    Event e;
    e.kind = failed ? EventKind::fault : EventKind::recovery;
    e.step = walked_;
    e.legs = legs;
    observer_->on_event(model_, state_, e);
  }
}

StepperCheckpoint Stepper::checkpoint() const {
  return {copy_sim_state(model_, state_), faults_, next_fault_, failed_, walked_};
}

void Stepper::restore(const StepperCheckpoint& checkpoint) {
  state_ = copy_sim_state(model_, checkpoint.state);
  faults_ = checkpoint.faults;
  next_fault_ = checkpoint.next_fault;
  failed_ = checkpoint.failed;
  walked_ = checkpoint.walked;
  last_faults_.clear();
}

void Stepper::emit(Event event) {
  event.step = walked_;
  if (observer_ != nullptr) observer_->on_event(model_, state_, event);
}

Pose2 Stepper::pose() const {
  const Position p = trunk_position(model_, state_);
  return {p.x, p.y, trunk_yaw_deg(model_, state_)};
}

}  // namespace multicpg::sim
