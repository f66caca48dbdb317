#include "sim/stepper.h"

#include <algorithm>
#include <string>
#include <utility>

#include "common/errors.h"
#include "common/interrupt.h"
#include "common/limits.h"
#include "sim/fault_effects.h"

namespace multicpg::sim {

SimState start_walk_state(const SimModel& model, const std::vector<int>& periods) {
  SimState state = make_sim_state(model);
  state.controller = body::start_controller(model.controller, periods);
  return state;
}

Stepper::Stepper(const SimModel& model, const body::StartSpec& start, body::FaultTimeline faults,
                 Observer* observer, WalkRecord* record, bool record_joints)
    : model_(model),
      state_(start_walk_state(model, start.periods)),
      observer_(observer),
      record_(record),
      record_joints_(record_joints) {
  state_.faults.schedule = body::FaultSchedule(model.controller.morphology, std::move(faults));
  require_in("start.warmup", start.warmup, body::kStepLimits);
  state_.faults.sensor.random.seed(start.seed);
  apply_due_faults();
  body::warm_up_controller(model_.controller, state_.controller, start.warmup);
  if (record_ != nullptr) {
    record_->legs = model.legs.size();
    append_record(model_, state_, record_joints_, *record_);
  }
  if (observer_ != nullptr) observer_->on_start(model_, state_);
}

Stepper Stepper::resume(const SimModel& model, const StepperCheckpoint& checkpoint,
                        Observer* observer) {
  return Stepper(model, checkpoint, observer, Resumed{});
}

Stepper::Stepper(const SimModel& model, const StepperCheckpoint& checkpoint, Observer* observer,
                 Resumed)
    : model_(model),
      state_(copy_sim_state(model, checkpoint.state)),
      observer_(observer),
      record_(nullptr),
      record_joints_(false),
      walked_(checkpoint.walked) {}

void Stepper::apply_due_faults() {
  body::FaultSchedule& schedule = state_.faults.schedule;
  const std::size_t first = schedule.applied().size();
  if (schedule.apply_due(walked_, state_.controller) > 0) take_faults(first);
}

void Stepper::take_faults(std::size_t first) {
  const std::vector<body::Fault>& applied = state_.faults.schedule.applied();
  for (std::size_t i = first; i < applied.size(); ++i) {
    apply_fault_effect(model_, state_, applied[i]);
    if (observer_ != nullptr) observer_->on_event(model_, state_, fault_event(applied[i]));
  }
}

void Stepper::step() {
  check_interrupted();
  apply_due_faults();
  if (before_step_) before_step_(*this);
  sim_step(model_, state_);
  advance_sensor(model_, state_);
  ++walked_;
  if (record_ != nullptr) append_record(model_, state_, record_joints_, *record_);
  if (observer_ != nullptr) observer_->on_step(model_, state_);
}

void Stepper::steps(long n) {
  for (long i = 0; i < n; ++i) step();
}

void Stepper::apply_now(body::Fault fault) {
  fault.step = walked_;
  const std::size_t first = state_.faults.schedule.applied().size();
  state_.faults.schedule.apply_now(fault, state_.controller);
  take_faults(first);
}

StepperCheckpoint Stepper::checkpoint() const {
  return {copy_sim_state(model_, state_), walked_};
}

void Stepper::restore(const StepperCheckpoint& checkpoint) {
  state_ = copy_sim_state(model_, checkpoint.state);
  walked_ = checkpoint.walked;
}

void Stepper::emit(body::Event event) {
  event.step = walked_;
  if (observer_ != nullptr) observer_->on_event(model_, state_, event);
}

body::Pose2 Stepper::pose() const {
  const Position p = trunk_position(model_, state_);
  return {p.x, p.y, trunk_yaw_deg(model_, state_)};
}

body::Pose2 Stepper::sensed_pose() const {
  const Position p = trunk_position(model_, state_);
  return {p.x, p.y, sensed_yaw_deg(model_, state_)};
}

}  // namespace multicpg::sim
