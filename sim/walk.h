// Walking a simulated robot for a number of controller steps with given CPG periods and a
// leg-fault schedule, measuring distance, speed and heading deviation (SPEC §6, issue 3).
// Used by `multicpg walk`; learning, rendering and figures reuse it.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "sim/sim.h"

namespace multicpg::sim {

// SPEC §6: deviation is measured over windows of 400 controller steps.
inline constexpr long kDefaultWindow = 400;

// Controller steps that lock the CPGs (p = 4 locks at step 737) and fill the delay lines (126
// steps at most) before the robot moves. A fresh controller's empty delay lines move the right
// legs alone for the first tau_L = 90 steps and swerve the robot about 26 deg left before any
// gait shows; a warmed-up controller starts the robot in its gait, as a robot already walking.
inline constexpr long kControllerWarmup = 1000;

// Most controller steps a walk's steps, settle or warmup may ask for: 10^8 (about 43 days of
// simulated time at 0.037 s, months of computing), so their sum stays far inside a long and a
// mistyped huge number is refused instead of overflowing.
inline constexpr long kMaxSteps = 100'000'000;

// Step numbers count controller steps from the start of the run.
struct WalkSpec {
  std::vector<int> periods;           // one per leg; empty = every leg 4
  std::vector<std::size_t> disabled;  // legs that fail...
  long disable_at = 0;                // ...before this step (0 = from the start)
  // Steps walked before measuring, so the CPGs lock and the delay lines fill (SPEC §6: settling
  // steps are not counted). Until the longest delay line has filled, only some legs move.
  long settle = 0;
  // Controller steps run alone before the physics starts (see kControllerWarmup); 0 = the robot
  // starts with a fresh controller.
  long controller_warmup = 0;
  long steps = 1200;                             // measured steps, after the settling ones
  long window = kDefaultWindow;                  // steps per deviation window
  bool record = true;                            // keep joint angles and contacts of every step
  std::function<void(const SimState&)> on_step;  // called after every controller step
};

// Per-step sensor record of the whole run, settling included; row k is the state after k
// controller steps (row 0 = the start).
struct WalkRecord {
  std::size_t legs = 0;
  std::vector<double> time;     // s
  std::vector<double> x, y, z;  // trunk position, m
  std::vector<double> yaw_deg;  // front trunk yaw, (-180, 180]
  // Only with WalkSpec::record, indexed [row * legs * 3 + leg * 3 + joint] (TC, CTr, FTi):
  std::vector<double> command;         // motor command m in [-1, 1] (SPEC §4)
  std::vector<double> target;          // commanded joint angle, rad
  std::vector<double> actual;          // joint angle, rad
  std::vector<unsigned char> contact;  // [row * legs + leg], 1 = foot touches the ground

  std::size_t rows() const { return time.size(); }
};

// Measurements over the measured steps (from step `settle` to the end).
struct WalkResult {
  WalkRecord record;
  double duration_s = 0.0;  // simulated time measured
  double distance_m = 0.0;  // horizontal displacement of the trunk
  double forward_m = 0.0;   // its component along the heading at the start of measuring
  double lateral_m = 0.0;   // its component to the left of that heading
  double speed_m_s = 0.0;   // distance / duration
  // wrap(yaw(end) - yaw(start)) of each complete window; positive = left turn (SPEC §6).
  std::vector<double> window_deviations_deg;
  double final_yaw_deg = 0.0;  // front trunk yaw at the end; the robot starts at yaw 0
};

// Runs spec.settle + spec.steps controller steps from start_walk_state. Throws BadInput for a spec
// that cannot run (wrong number of periods, a leg out of range, every leg disabled, steps or window
// <= 0, settle < 0, disable_at outside the run); RuntimeFailure if the physics becomes unstable.
WalkResult walk(const SimModel& model, const WalkSpec& spec);

// The state walk() starts from: make_sim_state, then `periods` (one per leg; empty = all 4).
// Equal periods keep the clients synchronised; unequal ones set each leg's period and free the
// clients (SPEC §5). Throws BadInput for a wrong number of periods or a period outside 1-9.
SimState start_walk_state(const SimModel& model, const std::vector<int>& periods);

// Runs the neural controller alone for `steps` steps: the robot does not move.
void warm_up_controller(const SimModel& model, SimState& state, long steps);

// Appends the state as one row of `record` (its `legs` must be set); joint angles, commands and
// contacts only if `joints`.
void append_record(const SimModel& model, const SimState& state, bool joints, WalkRecord& record);

// Deviations of consecutive complete windows of a yaw trace from row `first` (SPEC §6).
std::vector<double> window_deviations(const std::vector<double>& yaw_deg, std::size_t first,
                                      long window);

}  // namespace multicpg::sim
