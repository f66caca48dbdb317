// What a whole experiment of learning runs writes besides its run files (sweep.h): table.csv and
// table.md (one row per scenario, beta or grid point; tables.h), runs.csv (one row per run),
// trials.csv (one row per trial) and summary.json.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "common/table.h"
#include "experiments/sweep.h"
#include "experiments/tables.h"

namespace multicpg::experiments {

// Writes the experiment's tables, CSVs and summary into `out` from its results (one per planned
// run, in their order) and returns its table.
ExperimentTable write_results(const Sweep& sweep, const std::filesystem::path& out,
                              const std::vector<nlohmann::json>& results);

// runs.csv and trials.csv of an experiment's results (in run order).
Table runs_table(const Sweep& sweep, const std::vector<nlohmann::json>& results);
Table trials_table(const Sweep& sweep, const std::vector<nlohmann::json>& results);

}  // namespace multicpg::experiments
