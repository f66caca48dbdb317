// What one run is: which robot in which world, how it starts, what fails when, how it learns and
// what is kept. The CLI, experiment files, the presets, rerun and the Python API all build one;
// it is checked once here (validate), carried by every run, and turned into JSON only where a
// run is saved or read back (experiments/run_json.h).
#pragma once

#include <optional>
#include <string>

#include "body/events.h"
#include "experiments/run_robot.h"
#include "learning/compensation.h"
#include "robot/morphology.h"
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

// A real robot the run walks instead of the simulation (docs/hardware.md "Running it").
struct HardwareSpec {
  std::string file;        // its hardware file
  bool lock_step = false;  // no pacing: each step as soon as the last one's answers came (emulator)
  bool operator==(const HardwareSpec&) const = default;
};

struct RunSpec {
  RobotSpec robot;             // which robot, in which world (run_robot.h)
  body::StartSpec start;       // periods and warm-up
  body::FaultTimeline faults;  // what fails, and recovers, when
  // How the robot learns to compensate; none = it walks as it started.
  std::optional<learning::CompensationOptions> learning;
  RecordSpec record;
  // The real robot that walks the run (its leg layout and controller are robot's); none = the
  // simulation of robot.
  std::optional<HardwareSpec> hardware;
};

// How a learning run starts: paper mode from a cold controller with every CPG reset, as the
// authors' code did (docs/learning.md "Where the authors' code differs"); robust mode from a
// running, locked one, as a robot that was walking when a leg failed.
body::StartSpec learning_start(learning::Mode mode);

// Throws OptionError naming the key of the first bad value: the robot's ("sim.control_dt",
// "sim.model", validate(const RobotSpec&)), "start.periods", "start.warmup", "faults",
// "learning.annealing.beta", "record.check_windows" (a value out of its range, a period that
// gives no gait or the wrong number of them, a fault timeline that cannot happen, a learning run
// without a fault or with unequal start periods), "learning.mode" for faults the learning mode
// cannot take.
void validate(const RunSpec& spec);

// What the learner of the learning run `spec` learns from besides its trials (its dataset,
// learning::learner_data), read and checked against the run once before its body opens; empty
// for a learner that needs none. Throws OptionError or BadInput as validate does.
learning::LearnerData learner_data(const RunSpec& spec);

}  // namespace multicpg::experiments
