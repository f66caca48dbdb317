// Walking a simulated robot for a number of controller steps with given CPG periods and a
// fault timeline, measuring distance, speed and heading deviation (docs/learning.md "Deviation").
// Used by `multicpg walk`; rendering and figures reuse it. It steps through sim::Stepper.
#pragma once

#include <cstddef>
#include <vector>

#include "body/deviation.h"
#include "sim/sim.h"
#include "sim/stepper.h"
#include "sim/walk_record.h"

namespace multicpg::sim {

// Paper §4: deviation is measured over windows of 400 controller steps.
inline constexpr long kDefaultWindow = 400;

// Step numbers count controller steps from the start of the run (after the warm-up).
struct WalkSpec {
  body::StartSpec start;       // periods and warm-up (default: a running, locked controller)
  body::FaultTimeline faults;  // legs that fail or recover, and when
  // Steps walked before measuring (docs/learning.md "Deviation": not counted).
  long settle = 0;
  long steps = 1200;             // measured steps, after the settling ones
  long window = kDefaultWindow;  // steps per deviation window
  bool record = true;            // keep joint angles and contacts of every step
  // Keep every step in WalkResult::record. false: the walk is measured as it goes and keeps
  // nothing per step, so its memory does not grow with its length; a per-step record can still
  // stream to a file through `observer` (walk --csv: sim/record_csv.h).
  bool keep_record = true;
  Observer* observer = nullptr;  // sees every step and fault
};

// Measurements over the measured steps (from step `settle` to the end).
struct WalkResult {
  WalkRecord record;        // empty unless WalkSpec::keep_record
  double duration_s = 0.0;  // simulated time measured
  double distance_m = 0.0;  // horizontal displacement of the trunk
  double forward_m = 0.0;   // its component along the heading at the start of measuring
  double lateral_m = 0.0;   // its component to the left of that heading
  double speed_m_s = 0.0;   // distance / duration
  // wrap(yaw(end) - yaw(start)) of each complete window; positive = left turn.
  std::vector<double> window_deviations_deg;
  // Yaw change and Table 1 path angle of each complete window (body/deviation.h).
  std::vector<body::WindowMeasure> windows;
  double final_yaw_deg = 0.0;  // the yaw sensor's reading at the end; the robot starts at yaw 0
  SimState final_state;        // the robot at the end
};

// Fills `result`'s measurements from its record (rows 0..settle+steps) as walk() does: distance,
// speed and windows from row `settle` on, over `steps` measured steps.
void measure_walk(const SimModel& model, long settle, long steps, long window, WalkResult& result);

// Runs spec.settle + spec.steps controller steps through a Stepper. Throws OptionError naming
// the spec's key ("steps", "window", "settle", "start.warmup", "start.periods", "faults") for a
// spec that cannot run (wrong number of periods, a bad fault timeline, steps or window <= 0,
// settle < 0, a fault outside the run, more than kMaxSteps); RuntimeFailure if the physics
// becomes unstable; Interrupted when SIGINT or SIGTERM stops it (common/interrupt.h).
WalkResult walk(const SimModel& model, const WalkSpec& spec);

// Deviations of consecutive complete windows of a yaw trace from row `first`.
std::vector<double> window_deviations(const std::vector<double>& yaw_deg, std::size_t first,
                                      long window);

}  // namespace multicpg::sim
