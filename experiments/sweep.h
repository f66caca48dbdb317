// Experiments as data: one document (an experiment file read by experiment_file.h,
// or a preset built in memory) says everything that decides an experiment's runs; it is
// resolved once (every default filled in, every value checked) into tasks for the runner
// (runner.h), and the resolved document is what OUT/experiment.json records, so any run can be
// rerun, any shard merged, and a resumed experiment refused when its document changed.
// Resolution is sweep.cpp, with the document's schema checks (document_schema.h) and its
// scenarios (document_scenarios.h); running, resuming and merging sweep_run.cpp; the tables and
// CSVs written at the end sweep_tables.h.
//
// Document keys:
//   kind       "learning" (default): learning runs, tables per scenario or grid point;
//              "landscape": every period combination of each leg set walked without learning
//              (landscape.h), with a "landscape" table (period_set, windows, window_steps,
//              threshold_deg) and "sim", no grid; several leg sets make a landscape dataset
//              (landscape.h run_landscape_set)
//   robot      "hexapod" (default), "quadruped", "octopod" or a robot file "FILE.toml" (relative
//              to the working directory; an experiment file's own folder, experiment_file.h),
//              resolved as its layout's name and robot_file, its record (run_robot.h), which is
//              checked against the file when a resolved document is read back
//   scenarios  "paper" (paper_scenarios), "all" (mirror_scenarios up to 3 legs), "every"
//              (every_leg_loss up to 3 legs) or a list of disabled leg sets ("R1+R3") and fault
//              timelines
//              ({name, faults = [{step, legs, recover}]})
//   runs       runs per grid point and scenario (default kScenarioRuns); seed: the base seed
//   learning   learning::CompensationOptions keys (JSON names), except disabled, faults and
//              seed, which each run sets
//   sim        sim::SimOptions keys
//   record     check_windows (windows walked after learning) and trace (the trial list)
// Any learning or sim value may be a list (for a list-valued option: a list of lists); the
// lists form a grid, and each grid point x scenario x run is one planned run.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "body/events.h"
#include "experiments/document_schema.h"
#include "experiments/experiment_limits.h"
#include "experiments/landscape.h"
#include "experiments/run_spec.h"
#include "experiments/runner.h"
#include "experiments/tables.h"
#include "learning/compensation.h"
#include "robot/morphology.h"
#include "sim/sim.h"
#include "sim/stepper.h"

namespace multicpg::experiments {

// The tasks a job of a job array runs: those whose index % count == index.
struct Shard {
  int index = 0;
  int count = 1;
};

// "i/N" with 0 <= i < N; throws BadInput (one line) for anything else.
Shard parse_shard(std::string_view text);
std::string to_string(const Shard& shard);

// Where a run sits in its sweep: its scenario and its grid values (dotted key -> value), what
// runs.csv and trials.csv start its rows with.
struct RunLabel {
  std::string scenario;
  nlohmann::json grid = nlohmann::json::object();
};

// One run a sweep plans: the runner's task (its key, group, seed and the record saved with its
// result), the run itself and its label.
struct PlannedRun {
  Task task;
  RunSpec spec;
  RunLabel label;
};

struct Sweep {
  nlohmann::json resolved;  // the document with every default filled in
  robot::RobotKind robot = robot::RobotKind::hexapod;
  std::shared_ptr<const RunRobotFile> robot_file;  // null: the built-in robot
  std::vector<GridAxis> grid;                      // in key order; the first varies slowest
  std::vector<PlannedRun> runs;                    // grid point by grid point, scenario, run
  // table: no grid, one row per scenario (Figs. 11, 13); beta: beta alone swept on one
  // scenario (Fig. 14); grid: one row per grid point and scenario. Unused for a landscape.
  ExperimentKind table = ExperimentKind::table;
  // kind "landscape" (then no runs): one landscape per scenario, the same settings.
  std::vector<LandscapeSpec> landscapes;
};

// Resolves a document; throws OptionError whose key is the dotted path of the first bad value
// ("learning.annealing.beta", "scenarios[2]") for a wrong type, an unknown key, an empty list,
// a bad leg name or an out-of-range value (learning::validate and sim checks, before any run),
// a list longer than kMaxListValues or nesting deeper than kMaxExperimentDepth (checked first,
// without recursion). Throws BadInput naming the grid's axes and their product when the runs
// (or a landscape's combinations) are more than `limits` allow, before any run is made.
Sweep resolve_sweep(const nlohmann::json& document, const SweepLimits& limits = {});

// The document of a landscape (what examples/landscape-*.toml hold; `multicpg landscape`).
nlohmann::json landscape_document(const LandscapeSpec& spec);

// The learning options as a document's "learning": every key but those each run sets (seed),
// and fail_step, the step at which a scenario's leg set fails.
nlohmann::json learning_document(const learning::CompensationOptions& options, long fail_step);

// The runner's tasks of the sweep's runs, in their order.
std::vector<Task> tasks_of(const Sweep& sweep);

// The planned run whose key is `key` ("R1_run003", a run file's name), or null.
const PlannedRun* find_run(const Sweep& sweep, std::string_view key);

struct SweepRunOptions {
  std::filesystem::path out;
  int jobs = default_jobs();
  Shard shard;
  bool progress = true;
  std::string progress_label;  // RunnerOptions::progress_label
};

struct SweepOutcome {
  std::size_t tasks = 0;  // of the shard
  int loaded = 0;
  int ran = 0;
  std::optional<ExperimentTable> table;  // written when the shard is the whole experiment
};

// Runs the shard's tasks in OUT (resumable; refused when OUT holds another resolved document,
// naming the first differing key). The whole experiment also writes table.csv, table.md,
// summary.json, runs.csv (one row per run) and trials.csv (one row per trial).
SweepOutcome run_sweep(const Sweep& sweep, const SweepRunOptions& options);

// The result of one run of a sweep, computed as run_sweep does; `observer` (may be null) sees
// every step.
nlohmann::json run_sweep_task(const RunSpec& spec, sim::Observer* observer = nullptr);

// The experiment recorded in DIR/experiment.json, and its shard. Throws BadInput for a
// directory without one, and for a landscape's (which is resumed, never rerun or merged).
struct RecordedSweep {
  Sweep sweep;
  Shard shard;
};
RecordedSweep read_sweep(const std::filesystem::path& dir);

// Copies the runs of the shard directories (each checked against its checksum and its task)
// into OUT and writes the tables and CSVs, as one run_sweep of the whole would. Throws BadInput
// when the directories are not shards of one resolved document or a run is missing.
ExperimentTable merge_sweeps(const std::filesystem::path& out,
                             const std::vector<std::filesystem::path>& dirs, bool progress);

}  // namespace multicpg::experiments
