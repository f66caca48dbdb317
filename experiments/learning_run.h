// Online learning on the simulated robot (docs/learning.md "Online compensation"):
// learning::compensate driving a MuJoCo robot through the one stepping loop (sim::Stepper).
#pragma once

#include <vector>

#include "experiments/bodies.h"
#include "experiments/run_spec.h"
#include "learning/compensation.h"
#include "sim/sim.h"
#include "sim/sim_body.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace multicpg::experiments {

struct LearningRun {
  learning::LearningResult result;
  sim::WalkRecord record;             // every step, when recorded (row 0 = the start)
  std::vector<long> trial_end_steps;  // step at which each trial's measured window ended
  long learning_end_step = 0;         // steps walked when learning stopped
  // Each complete window of the steps walked after learning (does the final
  // controller hold?), measured as robust mode does.
  std::vector<body::WindowMeasure> after_windows;
  sim::SimState final_state;  // the robot at the end (the simulation's)
  nlohmann::json hardware;    // a real robot's record (hw::hardware_json); null in simulation
};

// Runs the learning run `spec` (which must have learning options; the caller validated it) on
// `model`, made from spec.robot (make_model): compensation from its start with its faults, every
// step recorded when spec.record.steps; afterwards walks `after_steps` more with the final
// periods (for "after learning" figures and the tunnel). `observer` (may be null) sees every
// step, fault, detection, trial and episode.
LearningRun run_learning(const sim::SimModel& model, const RunSpec& spec, long after_steps = 0,
                         sim::Observer* observer = nullptr);

// The same on whichever body `spec` names: with spec.hardware the real robot of `setup`
// (hardware_setup; `model` then only poses its steps for the watchers' observer). A run a fault
// or a signal stops leaves a real robot stopped, its record to watchers.stopped, and throws on.
// The record of every step is spec.record.steps' (watchers.record is not read).
LearningRun run_learning(const sim::SimModel& model, const RunSpec& spec,
                         const HardwareSetup* setup, long after_steps, const Watchers& watchers);

}  // namespace multicpg::experiments
