#include "experiments/learning_experiments.h"

#include <fstream>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/provenance.h"
#include "experiments/learning_run.h"
#include "experiments/processes.h"
#include "experiments/runner.h"
#include "experiments/scenarios.h"
#include "learning/json.h"
#include "sim/json.h"

namespace multicpg::experiments {
namespace {}  // namespace

nlohmann::json experiment_arguments(const ExperimentSpec& spec, ExperimentKind experiment) {
  // The option structs whole (their JSON type macros), so a new option is recorded and compared
  // on resume without a line here; each task sets its own legs, seed and (beta study) beta.
  return {{"experiment", to_string(experiment)},
          {"robot", robot::to_string(spec.kind)},
          {"runs", spec.runs},
          {"seed", spec.seed},
          {"learning", spec.base},
          {"check_windows", spec.check_windows},
          {"sim", spec.sim}};
}

namespace {

// One learning run of a task: its disabled legs, seed and (beta study) beta.
nlohmann::json run_task(const sim::SimModel& model, const learning::CompensationOptions& base,
                        long check_windows, const Task& task) {
  const robot::Morphology& morph = model.controller.morphology;
  learning::CompensationOptions options = base;
  options.disabled.clear();
  options.faults.clear();
  for (const nlohmann::json& name : task.params.at("disabled")) {
    options.disabled.push_back(robot::leg_index(morph, name.get<std::string>()));
  }
  if (task.params.contains("beta")) options.annealing.beta = task.params.at("beta").get<double>();
  options.seed = task.seed;
  const LearningRun run =
      run_learning(model, options, /*record=*/false, check_windows * options.window_steps);
  nlohmann::json out = learning::to_json(run.result, morph, options.disabled);
  if (check_windows > 0) {
    nlohmann::json windows = nlohmann::json::array();
    bool holds = true;
    for (const sim::WindowMeasure& m : run.after_windows) {
      windows.push_back({{"yaw_deg", m.yaw_deg}, {"path_deg", m.path_deg}});
      holds = holds && m.worst_deg() <= options.annealing.threshold_deg;
    }
    out["after_windows"] = windows;
    out["holds_after"] = holds;
  }
  return out;
}

ExperimentTable run_tasks_to_table(const ExperimentSpec& spec, ExperimentKind experiment,
                                   const std::vector<Task>& tasks) {
  RunnerOptions runner;
  runner.out_dir = spec.out;
  if (spec.jobs > 0) runner.jobs = spec.jobs;
  runner.arguments = experiment_arguments(spec, experiment);
  runner.provenance = provenance(mj_versionString());
  runner.progress = spec.progress;
  validate(runner);
  const sim::SimModel model = sim::make_sim_model(spec.kind, spec.sim);  // shared, read-only
  const RunnerOutcome outcome = run_tasks(
      tasks, [&](const Task& task) { return run_task(model, spec.base, spec.check_windows, task); },
      runner);

  ExperimentTable table{experiment, std::string(robot::to_string(spec.kind)),
                        summarize(model.controller.morphology, tasks, outcome.results)};
  if (!is_primary_process()) return table;  // the primary writes OUT
  const bool beta = experiment == ExperimentKind::beta;
  write_file_atomic(spec.out / "table.csv",
                    to_csv(beta ? beta_data(table.rows) : scenario_data(table.rows)));
  write_file_atomic(spec.out / "table.md",
                    to_markdown(beta ? beta_table(table.rows) : scenario_table(table.rows)));
  nlohmann::json rows = nlohmann::json::array();
  for (const GroupSummary& row : table.rows) rows.push_back(to_json(row));
  nlohmann::json summary = experiment_arguments(spec, experiment);
  summary["rows"] = rows;
  write_file_atomic(spec.out / "summary.json", summary.dump(2) + "\n");
  return table;
}

}  // namespace

ExperimentTable run_scenario_table(const ExperimentSpec& spec) {
  const robot::Morphology& morph = robot::morphology(spec.kind);
  return run_tasks_to_table(
      spec, ExperimentKind::table,
      scenario_tasks(morph, paper_scenarios(spec.kind), spec.runs, spec.seed));
}

ExperimentTable run_beta_study(const ExperimentSpec& spec, const std::vector<double>& betas) {
  ExperimentSpec hexapod = spec;
  hexapod.kind = robot::RobotKind::hexapod;
  return run_tasks_to_table(hexapod, ExperimentKind::beta, beta_tasks(betas, spec.runs, spec.seed));
}

std::string_view to_string(ExperimentKind kind) {
  return kind == ExperimentKind::beta ? "beta" : "table";
}

ExperimentKind parse_experiment_kind(std::string_view text) {
  if (text == "table") return ExperimentKind::table;
  if (text == "beta") return ExperimentKind::beta;
  throw BadInput("unknown experiment '" + std::string(text) + "' (table or beta)");
}

ExperimentTable read_experiment(const std::filesystem::path& out) {
  const std::filesystem::path file = out / "summary.json";
  std::ifstream in(file);
  if (!in) throw BadInput("no experiment results in '" + out.string() + "' (missing summary.json)");
  nlohmann::json j;
  try {
    in >> j;
    ExperimentTable table{parse_experiment_kind(j.at("experiment").get<std::string>()),
                          j.at("robot").get<std::string>(),
                          {}};
    for (const nlohmann::json& row : j.at("rows"))
      table.rows.push_back(group_summary_from_json(row));
    return table;
  } catch (const std::exception& e) {
    throw BadInput("'" + file.string() + "' is not an experiment summary: " + e.what());
  }
}

}  // namespace multicpg::experiments
