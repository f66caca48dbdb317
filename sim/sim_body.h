// The simulated robot as a body (body/body.h): a sim::Stepper walking a MuJoCo model, its
// learner's events shown to the stepper's observer.
#pragma once

#include "body/body.h"
#include "sim/stepper.h"

namespace multicpg::sim {

class SimBody final : public body::Body {
 public:
  explicit SimBody(Stepper& stepper) : stepper_(stepper) {}

  void step() override { stepper_.step(); }
  // What the robot senses: a faulty yaw sensor misleads the learner as it would a real robot;
  // the trunk's position is the simulation's own.
  body::Senses senses() const override {
    const body::Pose2 p = stepper_.sensed_pose();
    return {p.yaw_deg, body::Position2{p.x, p.y}};
  }
  long step_count() const override { return stepper_.step_count(); }
  neural::ControllerState& controller() override { return stepper_.state().controller; }
  const neural::ControllerModel& controller_model() const override {
    return stepper_.model().controller;
  }
  const body::FaultSchedule& faults() const override { return stepper_.faults(); }
  void emit(const body::Event& event) override { stepper_.emit(event); }
  Stepper& stepper() { return stepper_; }

 private:
  Stepper& stepper_;
};

}  // namespace multicpg::sim
