// The argument descriptions the run-making calls share (python/keywords.h): the faults of a run
// (Simulation, learn, tunnel), the learning options (learn, tunnel and multicpg.env, each
// keyword listed once here) and how a call is watched; what each gives, and the whole run
// checked as the CLI checks it.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>

#include "body/events.h"
#include "experiments/bodies.h"
#include "experiments/run_spec.h"
#include "learning/compensation.h"
#include "python/keywords.h"
#include "python/robots.h"

namespace multicpg::python {

namespace py = pybind11;

// disable, disable_at, faults, recoveries: what fails when (`disable` at `disable_at`, then
// `faults` and `recoveries`, in step order).
Params fault_params();
body::FaultTimeline fault_timeline(const robot::Morphology& morph, const Keywords& k);

// mode, learner, learner_options, steering, hold_windows, monitor_windows, max_episodes,
// period_learning, beta, threshold, window, settle, max_trials, step_budget, seed: the options
// of `multicpg learn` (the numeric ones from learning/number_options.h).
Params learning_params();
// The robust-mode ones among them: given with mode='paper', they are refused.
Params robust_params();
// The learning options of `k` for a run of `robot` under `faults`; learner=None is the run's
// default (learning::default_learner), left the paper's annealing when `robot` is null (options
// checked apart from any run).
learning::CompensationOptions learning_options(const Keywords& k,
                                               const experiments::RobotSpec* robot,
                                               const body::FaultTimeline& faults = {});
// Adds the numeric learning options of `o` (learning/number_options.h) to `out` under their
// keywords; settle is None when the run works it out.
void add_number_options(py::dict& out, const learning::CompensationOptions& o);

// progress (True, False or a callable, python/watch.h).
Params progress_params();

// hardware (a hardware file, docs/hardware.md: a real robot walks the run) and lock_step (no
// pacing: the emulator's rehearsal), as `--hardware` and `--lock-step`.
Params hardware_params();
// The run's hardware from those arguments: sets spec.hardware and returns what the run needs of
// it, checked before any port opens (a ValueError naming the argument); nothing without one.
std::optional<experiments::HardwareSetup> hardware_setup(const Keywords& k,
                                                         experiments::RunSpec& spec);

// A run checked whole (experiments::validate); a bad value is a ValueError naming its argument.
experiments::RunSpec run_spec(const Robot& robot, body::StartSpec start, body::FaultTimeline faults,
                              std::optional<learning::CompensationOptions> learning);

}  // namespace multicpg::python
