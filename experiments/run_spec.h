// What one run is: which robot in which world, how it starts, what fails when, how it learns and
// what is kept. The CLI, experiment files, the presets, rerun and the Python API all build one;
// it is checked once here (validate), carried by every run, and turned into JSON only where a
// run is saved or read back (experiments/run_json.h).
#pragma once

#include <memory>
#include <optional>

#include "experiments/run_robot.h"
#include "learning/compensation.h"
#include "robot/morphology.h"
#include "sim/events.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::experiments {

// Windows walked after learning with the final controller (does it hold? docs/learning.md).
inline constexpr Limits<long> kCheckWindowsLimits{0, 1000};

// What a run keeps besides its result.
struct RecordSpec {
  bool steps = false;      // every step: trunk, joints, contacts (CSV, NumPy)
  long check_windows = 0;  // learning runs: windows walked after learning (holds_after)
  bool trace = true;       // learning runs: every trial
};

struct RunSpec {
  // The built-in robot, or with a robot file the built-in whose layout it has (its legs,
  // controller, servos and fault geometry; robot/robot_file.h).
  robot::RobotKind robot = robot::RobotKind::hexapod;
  std::shared_ptr<const RunRobotFile> robot_file;  // null: the built-in robot
  sim::SimOptions sim;        // time steps, servos, scene, the controller's parameters
  sim::StartSpec start;       // periods and warm-up
  sim::FaultTimeline faults;  // what fails, and recovers, when
  // How the robot learns to compensate; none = it walks as it started.
  std::optional<learning::CompensationOptions> learning;
  RecordSpec record;
};

// How a learning run starts: paper mode from a cold controller with every CPG reset, as the
// authors' code did (docs/learning.md "Where the authors' code differs"); robust mode from a
// running, locked one, as a robot that was walking when a leg failed.
sim::StartSpec learning_start(learning::Mode mode);

// Throws OptionError naming the key of the first bad value: "sim.control_dt",
// "start.periods", "start.warmup", "faults", "learning.annealing.beta", "record.check_windows"
// (a value out of its range, a period that gives no gait or the wrong number of them, a fault
// timeline that cannot happen, a learning run without a fault or with unequal start periods),
// "learning.mode" for faults the learning mode cannot take; with a robot file "sim.model" and
// "sim.body.<key>" for a body parameter other than the controller's (its body is its model).
void validate(const RunSpec& spec);

// The leg layout of the run's robot.
const robot::Morphology& morphology(const RunSpec& spec);

// The simulation the run walks in: its robot with its simulation options (or `options`).
sim::SimModel make_run_model(const RunSpec& spec);
sim::SimModel make_run_model(const RunSpec& spec, const sim::SimOptions& options);

}  // namespace multicpg::experiments
