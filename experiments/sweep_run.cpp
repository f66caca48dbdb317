// Running an experiment's planned runs (sweep.h) on the runner (runner.h), resuming it, and
// merging the directories of its shards.
#include <map>
#include <set>

#include "body/deviation.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/json_diff.h"
#include "common/provenance.h"
#include "experiments/learning_run.h"
#include "experiments/processes.h"
#include "experiments/sweep.h"
#include "experiments/sweep_tables.h"
#include "sim/json.h"
#include "sim/sim.h"

namespace multicpg::experiments {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// OUT/experiment.json's arguments, if OUT holds an experiment. A landscape's directory is
// refused: its runs are combinations, not runs of a sweep, and it resumes by running again.
std::optional<json> stored_arguments(const fs::path& out) {
  const fs::path path = out / "experiment.json";
  const std::optional<json> sealed = read_sealed(path);
  if (!sealed) return std::nullopt;
  const json& record = *sealed;
  if (!record.contains("arguments")) {
    throw BadInput("'" + path.string() + "' records no experiment arguments");
  }
  if (record.at("arguments").value("experiment", json()) == "landscape") {
    throw BadInput("'" + out.string() +
                   "' holds a landscape, which is not rerun or merged: run the same landscape "
                   "again into it to resume it");
  }
  std::optional<json> arguments;
  arguments.emplace(record.at("arguments"));
  return arguments;
}

json arguments_of(const Sweep& sweep, const Shard& shard) {
  json args = sweep.resolved;
  if (shard.count > 1) args["shard"] = to_string(shard);
  return args;
}

json task_result(const sim::SimModel& model, const RunSpec& spec, sim::Observer* observer) {
  const robot::Morphology& morph = model.controller.morphology;
  const learning::CompensationOptions& options = *spec.learning;
  const long check_windows = spec.record.check_windows;
  const LearningRun run = run_learning(model, spec, check_windows * options.window_steps, observer);
  json out = learning::to_json(run.result, morph, body::failing_legs(spec.faults));
  if (check_windows > 0) {
    json windows = json::array();
    bool holds = true;
    for (const body::WindowMeasure& m : run.after_windows) {
      windows.push_back({{"yaw_deg", m.yaw_deg}, {"path_deg", m.path_deg}});
      holds = holds && body::holds(m.worst_deg(), options.search.threshold_deg);
    }
    out["after_windows"] = windows;
    out["holds_after"] = holds;
  }
  if (!spec.record.trace) out.erase("trace");
  return out;
}

}  // namespace

SweepOutcome run_sweep(const Sweep& sweep, const SweepRunOptions& options) {
  const json arguments = arguments_of(sweep, options.shard);
  if (is_primary_process()) ensure_writable_dir(options.out);
  RunnerOptions runner;
  runner.out_dir = options.out;
  runner.jobs = options.jobs;
  runner.arguments = arguments;
  runner.progress = options.progress;
  runner.progress_label = options.progress_label;
  runner.provenance = provenance(mj_versionString());
  validate(runner);
  // The shard's runs by key, each with its model: one per distinct robot, made before any run
  // and shared read-only by the threads.
  struct ShardRun {
    const RunSpec* spec;
    std::shared_ptr<const sim::SimModel> model;
  };
  std::vector<Task> tasks;
  std::map<std::string, ShardRun> runs;
  ModelCache models;
  for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(options.shard.count)) ==
        options.shard.index) {
      const PlannedRun& run = sweep.runs[i];
      tasks.push_back(run.task);
      runs.emplace(run.task.key, ShardRun{&run.spec, models.model(run.spec.robot)});
    }
  }
  const RunnerOutcome outcome = run_tasks(
      tasks,
      [&](const Task& task) {
        const ShardRun& run = runs.at(task.key);
        return task_result(*run.model, *run.spec, nullptr);
      },
      runner);
  SweepOutcome result;
  result.tasks = tasks.size();
  result.loaded = outcome.loaded;
  result.ran = outcome.ran;
  if (options.shard.count > 1) return result;
  // Every process of an MPI job gets here; the primary writes OUT (processes.h).
  result.table = is_primary_process()
                     ? write_results(sweep, options.out, outcome.results)
                     : ExperimentTable{sweep.table, std::string(robot::to_string(sweep.robot)), {}};
  return result;
}

json run_sweep_task(const RunSpec& spec, sim::Observer* observer) {
  return task_result(make_model(spec.robot), spec, observer);
}

RecordedSweep read_sweep(const fs::path& dir) {
  std::optional<json> arguments = stored_arguments(dir);
  if (!arguments) {
    throw BadInput("no experiment in '" + dir.string() + "' (missing experiment.json)");
  }
  RecordedSweep out;
  if (arguments->contains("shard")) {
    out.shard = parse_shard(arguments->at("shard").get<std::string>());
    arguments->erase("shard");
  }
  // It ran, so it was within some --max-runs: the most that flag allows.
  const SweepLimits recorded{kMaxRunsLimits.hi, "--max-runs"};
  try {
    out.sweep = resolve_sweep(*arguments, recorded);
  } catch (const OptionError& e) {
    throw BadInput("'" + (dir / "experiment.json").string() + "': " + e.key() + " " + e.what());
  }
  return out;
}

ExperimentTable merge_sweeps(const fs::path& out, const std::vector<fs::path>& dirs,
                             bool progress) {
  if (dirs.empty()) throw BadInput("name at least one shard directory to merge");
  std::optional<json> base;
  std::map<std::string, fs::path> where;  // run key -> the shard directory holding it
  std::set<int> shards;
  int count = 0;
  for (const fs::path& dir : dirs) {
    std::optional<json> args = stored_arguments(dir);
    if (!args) throw BadInput("no experiment in '" + dir.string() + "' (missing experiment.json)");
    const Shard shard =
        args->contains("shard") ? parse_shard(args->at("shard").get<std::string>()) : Shard{};
    args->erase("shard");
    if (!base) {
      base = *args;
      count = shard.count;
    } else if (const std::vector<std::string> keys = json_differences(*base, *args);
               !keys.empty()) {
      throw BadInput("'" + dir.string() + "' is not a shard of the experiment in '" +
                     dirs.front().string() + "' (" + keys.front() + " differs)");
    }
    if (shard.count != count || !shards.insert(shard.index).second) {
      throw BadInput("'" + dir.string() + "' holds shard " + to_string(shard) +
                     ", which repeats or does not fit shards of " + std::to_string(count));
    }
    for (const auto& run : fs::directory_iterator(dir / "runs")) {
      if (run.path().extension() == ".json") where.emplace(run.path().stem().string(), dir);
    }
  }
  const Sweep sweep = read_sweep(dirs.front()).sweep;
  const std::vector<Task> tasks = tasks_of(sweep);
  for (const Task& t : tasks) {
    if (!where.count(t.key)) {
      throw BadInput("run " + t.key + " is in none of the directories (a shard missing or " +
                     "not finished)");
    }
  }
  RunnerOptions runner;
  runner.out_dir = out;
  runner.arguments = sweep.resolved;
  runner.progress = progress;
  runner.provenance = provenance(mj_versionString());
  ensure_writable_dir(out);
  // The run files are taken as saved, after their checksum and their task are checked.
  const RunnerOutcome outcome = run_tasks(
      tasks,
      [&](const Task& t) {
        const fs::path path = where.at(t.key) / "runs" / (t.key + ".json");
        const std::optional<json> sealed = read_sealed(path);
        if (!sealed) throw BadInput("cannot read '" + path.string() + "'");
        const json& saved = *sealed;
        const json expected{{"key", t.key},
                            {"group", t.group},
                            {"run", t.run},
                            {"seed", t.seed},
                            {"params", t.params}};
        for (const auto& item : expected.items()) {
          if (saved.value(item.key(), json()) != item.value()) {
            throw BadInput("'" + path.string() + "' is not the run " + t.key + " (" + item.key() +
                           " differs)");
          }
        }
        return saved.at("result");
      },
      runner);
  return write_results(sweep, out, outcome.results);
}

}  // namespace multicpg::experiments
