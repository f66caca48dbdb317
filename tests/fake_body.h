// A stand-in for the simulated robot, for tests of the learning loop without physics.
#pragma once

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "body/body.h"
#include "body/events.h"
#include "common/angles.h"
#include "learning/compensation.h"
#include "neural/controller.h"

namespace multicpg::learning {

// Yaw rate = gain * (left thrust - right thrust), thrust of a working leg = 1/period, of a
// disabled leg 0. Hexapod, R1 disabled, all 4: 0.25 * 0.38 * 400 = 38 deg per window (Fig. 8:
// 37.86). While clients are synchronised every leg moves with the master's period (paper §2.3).
class FakeBody : public body::Body {
 public:
  static constexpr double kGainDegPerStep = 0.38;

  // `faults` come as sim::Stepper applies them: before the steps they name.
  explicit FakeBody(robot::RobotKind kind, body::FaultTimeline faults = {},
                    double bias_deg_per_step = 0.0)
      : model_(neural::make_controller_model(kind)),
        state_(neural::make_controller_state(model_)),
        faults_(model_.morphology, std::move(faults)),
        bias_(bias_deg_per_step) {
    take_due_faults();
  }

  // It walks kSpeedMPerStep along its heading, so its path angle equals its mean heading.
  static constexpr double kSpeedMPerStep = 0.002;

  void step() override {
    take_due_faults();
    yaw_ = wrap_degrees(yaw_ + rate());
    const double heading = yaw_ * std::numbers::pi / 180.0;
    x_ += kSpeedMPerStep * std::cos(heading);
    y_ += kSpeedMPerStep * std::sin(heading);
    ++state_.step;
  }
  body::Senses senses() const override { return {yaw_, body::Position2{x_, y_}}; }
  long step_count() const override { return state_.step; }
  neural::ControllerState& controller() override { return state_; }
  const neural::ControllerModel& controller_model() const override { return model_; }
  const body::FaultSchedule& faults() const override { return faults_; }
  void emit(const body::Event& event) override { events.push_back(event); }

  std::vector<body::Event> events;  // the faults that came and what the learner reported

 private:
  void take_due_faults() {
    const std::size_t first = faults_.applied().size();
    faults_.apply_due(state_.step, state_);
    for (std::size_t i = first; i < faults_.applied().size(); ++i) {
      events.push_back(body::fault_event(faults_.applied()[i]));
    }
  }

  double rate() const {
    double turn = bias_;
    for (std::size_t i = 0; i < state_.legs.size(); ++i) {
      const neural::LegState& leg = state_.legs[i];
      if (leg.disabled) continue;
      const int period =
          neural::follows_master(state_, i) ? state_.legs[0].cpg.period : leg.cpg.period;
      const double sign = model_.morphology.legs[i].side == robot::Side::left ? 1.0 : -1.0;
      turn += sign * kGainDegPerStep / period;
    }
    return turn;
  }

  neural::ControllerModel model_;
  neural::ControllerState state_;
  body::FaultSchedule faults_;
  double bias_;
  double yaw_ = 0.0;
  double x_ = 0.0;
  double y_ = 0.0;
};

}  // namespace multicpg::learning
