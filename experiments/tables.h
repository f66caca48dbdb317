// Tables of an experiment's runs (paper Fig. 11, 13, 14): per scenario or beta the
// mean and SD of final deviation and trials, the share converged and the most frequent final
// combination, as common/table.h Tables with fixed decimals, so equal runs give byte-equal tables.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "common/table.h"
#include "experiments/runner.h"
#include "robot/morphology.h"

namespace multicpg::experiments {

// Mean and sample standard deviation (n - 1; 0 for a single run).
struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;
};

MeanSd mean_sd(const std::vector<double>& values);
double median(std::vector<double> values);

struct GroupSummary {
  std::string group;  // scenario name or beta
  int runs = 0;
  int converged = 0;
  int no_deviation = 0;          // runs whose deviation never exceeded the threshold (0 trials)
  MeanSd initial_deviation_deg;  // the deviation that started learning, over all runs
  MeanSd final_deviation_deg;    // over all runs
  MeanSd trials;                 // over all runs
  double median_trials = 0.0;
  int within_paper_trials = 0;  // runs converged within paper::kMostTrials
  // Most frequent final periods of the working legs among converged runs, "R2=5 R3=4 L1=5";
  // ties go to the alphabetically first; empty when no run converged.
  std::string best_periods;
  int best_count = 0;

  double share_converged() const;
};

// One summary per group, in the order groups first appear in `tasks`. `results[i]` is the
// learning result JSON (learning::to_json) of tasks[i]. Throws RuntimeFailure if a result lacks
// a field.
std::vector<GroupSummary> summarize(const robot::Morphology& morph, const std::vector<Task>& tasks,
                                    const std::vector<nlohmann::json>& results);

nlohmann::json to_json(const GroupSummary& row);
GroupSummary group_summary_from_json(const nlohmann::json& row);

// Scenario tables (Fig. 11, 13): shown (table.md, results.md, index.html; mean ± SD cells) and
// data (table.csv; one number per cell).
// `group_title` heads the first column (a grid's rows are its points and scenarios).
Table scenario_table(const std::vector<GroupSummary>& rows,
                     const std::string& group_title = "Disabled");
Table scenario_data(const std::vector<GroupSummary>& rows,
                    const std::string& group_title = "scenario");
// Beta tables (Fig. 14): groups are betas.
Table beta_table(const std::vector<GroupSummary>& rows);
Table beta_data(const std::vector<GroupSummary>& rows);

// The tables of learning experiments: the paper's two, and a grid of options (sweep.h).
enum class ExperimentKind { table, beta, grid };
std::string_view to_string(ExperimentKind kind);              // "table", "beta", "grid"
ExperimentKind parse_experiment_kind(std::string_view text);  // throws BadInput

// An experiment's results: one summary row per scenario, beta or grid point, written to OUT as
// table.csv, table.md and summary.json.
struct ExperimentTable {
  ExperimentKind experiment = ExperimentKind::table;
  std::string robot;
  std::vector<GroupSummary> rows;
};

}  // namespace multicpg::experiments
