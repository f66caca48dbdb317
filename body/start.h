// How a run starts, whatever body walks it: the controller's periods, its warm-up before the body
// moves, and the run's random stream. The simulation (sim::Stepper) and a real robot
// (hw::HardwareBody) start the same way from one StartSpec.
#pragma once

#include <cstdint>
#include <vector>

#include "body/events.h"
#include "common/limits.h"
#include "neural/controller.h"

namespace multicpg::body {

// Controller steps that lock the CPGs (p = 4 locks exactly at step 737, neural::lock_steps) and
// fill the delay lines (126 steps at most) before the robot moves. A fresh controller's empty
// delay lines move the right legs alone for the first tau_L = 90 steps and swerve the robot
// about 26 deg left, and p = 4 slips phase until step 737; a warmed-up controller starts the
// robot in its gait, as the paper's robot was walking before anything failed.
inline constexpr long kControllerWarmup = 1000;

// Documented ranges of step counts: a run of at least one step, settles and warm-ups of none.
inline constexpr Limits<long> kRunStepsLimits{1, kMaxSteps};
inline constexpr Limits<long> kStepLimits{0, kMaxSteps};

// How a run starts.
struct StartSpec {
  std::vector<int> periods;  // one per leg; empty = every leg 4. Unequal periods free the clients
  // Controller steps run alone before the body moves; 0 = a cold controller (--cold).
  long warmup = kControllerWarmup;
  // The run's random stream: a noisy sensor's draws (sim/fault_effects.h).
  std::uint64_t seed = 1;
};

// The controller a run starts with, before its warm-up: every leg at `periods` (one per leg;
// empty = every leg 4). Equal periods keep the clients synchronised; unequal ones set each leg's
// period and free the clients (paper §2.3).
neural::ControllerState start_controller(const neural::ControllerModel& model,
                                         const std::vector<int>& periods);

// Runs the neural controller alone for `steps` steps: the body does not move. Throws Interrupted
// when SIGINT or SIGTERM asked the process to stop (a warm-up may be long).
void warm_up_controller(const neural::ControllerModel& model, neural::ControllerState& state,
                        long steps);

// Throws OptionError ("steps", "window", "settle", "faults") for a walk that cannot run: steps or
// window under 1, settle under 0, more than kMaxSteps in all, a fault after its last step.
void validate_walk(const FaultTimeline& faults, long settle, long steps, long window);

}  // namespace multicpg::body
