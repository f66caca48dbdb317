#include "experiments/learning_experiments.h"

#include <stdexcept>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "experiments/scenarios.h"
#include "experiments/sweep.h"
#include "learning/json.h"
#include "sim/json.h"

namespace multicpg::experiments {
namespace {

// The document every preset shares: the spec's robot, runs, seed, options and record.
nlohmann::json preset_document(const ExperimentSpec& spec, robot::RobotKind kind) {
  return {{"robot", robot::to_string(kind)},
          {"runs", spec.runs},
          {"seed", spec.seed},
          {"learning", learning_document(spec.base, 0)},
          {"sim", spec.robot.sim},
          {"record", {{"check_windows", spec.check_windows}}}};
}

// The one- and two-leg losses of a robot file's layout (docs/learning.md "The paper's experiments"
// for any body).
constexpr std::size_t kRobotFileScenarioLegs = 2;

ExperimentTable run_preset(const ExperimentSpec& spec, const nlohmann::json& document) {
  SweepRunOptions options;
  options.out = spec.out;
  if (spec.jobs > 0) options.jobs = spec.jobs;
  options.progress = spec.progress;
  options.progress_label = spec.progress_label;
  return *run_sweep(resolve_sweep(document, spec.limits), options).table;
}

}  // namespace

nlohmann::json scenario_table_document(const ExperimentSpec& spec) {
  nlohmann::json doc = preset_document(spec, spec.robot.kind);
  doc["scenarios"] = "paper";
  if (spec.robot.file) {
    record_robot_file(doc, spec.robot);
    doc["scenarios"] = nlohmann::json::array();
    for (const Scenario& s : leg_loss_scenarios(morphology(spec.robot), kRobotFileScenarioLegs)) {
      doc["scenarios"].push_back(s.name);
    }
  }
  return doc;
}

nlohmann::json beta_study_document(const ExperimentSpec& spec, const std::vector<double>& betas) {
  nlohmann::json doc = preset_document(spec, robot::RobotKind::hexapod);
  doc["scenarios"] = {beta_study_scenario().name};
  doc["learning"]["annealing"]["beta"] = betas;
  return doc;
}

ExperimentTable run_scenario_table(const ExperimentSpec& spec) {
  return run_preset(spec, scenario_table_document(spec));
}

ExperimentTable run_beta_study(const ExperimentSpec& spec, const std::vector<double>& betas) {
  return run_preset(spec, beta_study_document(spec, betas));
}

nlohmann::json experiment_arguments(const ExperimentSpec& spec, ExperimentKind experiment) {
  if (experiment == ExperimentKind::grid) {
    throw std::invalid_argument("a grid is an experiment file's, not a preset's");
  }
  return resolve_sweep(experiment == ExperimentKind::beta
                           ? beta_study_document(spec, kBetaStudyValues)
                           : scenario_table_document(spec))
      .resolved;
}

ExperimentTable read_experiment(const std::filesystem::path& out) {
  const std::filesystem::path file = out / "summary.json";
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw BadInput("no experiment results in '" + out.string() + "' (missing summary.json)");
  }
  const std::string text =
      read_input_file(file, kMaxRecordBytes, kMaxRecordText, "an experiment summary");
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
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
