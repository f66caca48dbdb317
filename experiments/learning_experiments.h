// The paper's learning experiments on the simulated robots (paper §4; docs/learning.md "The paper's
// experiments"): the scenario tables (Figs. 11, 13) and the beta study (Fig. 14), run in parallel
// and resumable (runner.h).
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "experiments/experiment_limits.h"
#include "experiments/run_spec.h"
#include "experiments/tables.h"
#include "learning/compensation.h"
#include "sim/sim.h"

namespace multicpg::experiments {

struct ExperimentSpec {
  RobotSpec robot;  // run_robot.h
  int runs = 10;
  std::uint64_t seed = 1;
  int jobs = 0;  // 0 = every core
  std::filesystem::path out;
  // Settings of every run; each run's seed and disabled legs (and beta) come from its task.
  learning::CompensationOptions base;
  // Windows walked after each run with its final controller, to see whether it holds.
  long check_windows = 0;
  bool progress = true;
  std::string progress_label;                         // RunnerOptions::progress_label
  SweepLimits limits{kDefaultMaxRuns, "--max-runs"};  // more runs are refused (sweep.h)
};

// What decides an experiment's results, as recorded in OUT/experiment.json and compared on
// resume: its resolved document (experiments/sweep.h): robot, scenarios, runs, seed and every
// learning and simulation option.
nlohmann::json experiment_arguments(const ExperimentSpec& spec, ExperimentKind experiment);

// The experiments as documents of experiments/sweep.h (what examples/paper-*.toml hold with
// the default options), run through run_sweep.
// Every scenario of experiments::paper_scenarios(spec.robot.kind), spec.runs runs each; for a robot
// file every one- and two-leg loss of its layout (leg_loss_scenarios).
nlohmann::json scenario_table_document(const ExperimentSpec& spec);
// R1+R2 disabled on the hexapod, spec.runs runs per beta.
nlohmann::json beta_study_document(const ExperimentSpec& spec, const std::vector<double>& betas);

// The scenarios of scenario_table_document, spec.runs runs each.
ExperimentTable run_scenario_table(const ExperimentSpec& spec);

// R1+R2 disabled on the hexapod, spec.runs runs per beta.
ExperimentTable run_beta_study(const ExperimentSpec& spec, const std::vector<double>& betas);

// Reads OUT/summary.json; throws BadInput when it is missing or not an experiment's summary.
ExperimentTable read_experiment(const std::filesystem::path& out);

}  // namespace multicpg::experiments
