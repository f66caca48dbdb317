// Online learning on the simulated robot (issue 4): learning::compensate driving a MuJoCo walk.
#pragma once

#include <functional>
#include <vector>

#include "learning/compensation.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace multicpg::experiments {

// Called after every controller step with the robot's state (e.g. to film it).
using StepHook = std::function<void(const sim::SimState&)>;

// learning::Walker over one simulated robot, recording every step when asked.
class SimWalker final : public learning::Walker {
 public:
  // `record` may be null: no per-step record (the experiments' hot path).
  SimWalker(const sim::SimModel& model, sim::WalkRecord* record, StepHook on_step = {});

  void step() override;
  double yaw_deg() const override;
  long step_count() const override { return state_.step; }
  neural::ControllerState& controller() override { return state_.controller; }
  const neural::ControllerModel& controller_model() const override { return model_.controller; }
  void disable(const std::vector<std::size_t>& legs) override;

  const sim::SimState& state() const { return state_; }
  sim::SimState release() { return std::move(state_); }

 private:
  const sim::SimModel& model_;
  sim::SimState state_;
  sim::WalkRecord* record_;
  StepHook on_step_;
};

struct LearningRun {
  learning::LearningResult result;
  sim::WalkRecord record;             // every step, when recorded (row 0 = the start)
  std::vector<long> trial_end_steps;  // step at which each trial's measured window ended
  long learning_end_step = 0;         // steps walked when learning stopped
  sim::SimState final_state;          // the robot at the end
};

// Runs compensation from a healthy, synchronised robot; afterwards walks `after_steps` more
// with the final periods (for "after learning" figures and the tunnel).
LearningRun run_learning(const sim::SimModel& model, const learning::CompensationOptions& options,
                         bool record, long after_steps = 0, const StepHook& on_step = {});

}  // namespace multicpg::experiments
