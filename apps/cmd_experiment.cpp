// multicpg experiment table|beta|results: the paper's learning experiments on every core
// (paper Figs. 11, 13, 14; docs/learning.md "The paper's experiments") and the page that sets them
// beside the paper.
#include <iostream>
#include <optional>
#include <utility>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/learning_experiments.h"
#include "experiments/processes.h"
#include "experiments/results_page.h"
#include "experiments/scenarios.h"

namespace multicpg::apps {
namespace {

struct ExperimentOptions {
  std::string robot = "hexapod";
  int runs = experiments::kScenarioRuns;
  std::optional<int> jobs;  // empty = every core
  std::string out;
  LearningFlags learning;
  long check_windows = 0;
  sim::SimOptions sim;
  BodyFlags body;
  std::int64_t max_runs = experiments::kDefaultMaxRuns;
};

experiments::ExperimentSpec spec_of(const ExperimentOptions& o, experiments::RobotSpec robot) {
  experiments::ExperimentSpec spec;
  spec.robot = std::move(robot);
  spec.runs = o.runs;
  spec.seed = o.learning.options.seed;
  spec.jobs = o.jobs.value_or(0);
  spec.out = o.out;
  spec.robot.sim = sim_options(o.sim, o.body, spec.robot.kind);
  // The presets' scenarios are leg losses. Checked with each run (resolve_sweep).
  spec.base = learning_options(o.learning, spec.robot, {});
  spec.check_windows = o.check_windows;
  spec.limits.max_runs = o.max_runs;
  if (experiments::is_primary_process()) ensure_writable_dir(spec.out);
  return spec;
}

void print_table(const experiments::ExperimentTable& t, const std::string& out) {
  if (!experiments::is_primary_process()) return;
  std::cout << (t.experiment == experiments::ExperimentKind::beta
                    ? to_markdown(experiments::beta_table(t.rows))
                    : to_markdown(experiments::scenario_table(t.rows)))
            << "\nwrote " << out << "/{table.csv,table.md,summary.json,runs.csv,trials.csv} and "
            << out << "/runs/\n";
}

void add_common(CLI::App& cmd, ExperimentOptions& o, int default_runs, bool with_beta) {
  o.runs = default_runs;
  // These are the paper's experiments: its algorithm unless --mode robust is asked for.
  o.learning.options.mode = learning::Mode::paper;
  cmd.add_option("--runs", o.runs, "learning runs per scenario")
      ->check(in(experiments::kRunsLimits))
      ->capture_default_str();
  cmd.add_option("--out", o.out, "directory for the runs and tables (resumes what is there)")
      ->required()
      ->check(kNotEmpty);
  cmd.add_option("--jobs", o.jobs, "parallel runs (default: every core)")
      ->check(in(experiments::kJobsLimits));
  add_learning_flags(cmd, o.learning, with_beta);
  // The beta study is the annealing's (paper Fig. 14): its learner unless another is named.
  if (!with_beta) o.learning.learner_named = true;
  cmd.add_option("--check-windows", o.check_windows,
                 "windows walked after each run with its final controller; the run files say "
                 "whether every one held (holds_after)")
      ->check(in(experiments::kCheckWindowsLimits))
      ->capture_default_str();
  add_sim_flags(cmd, o.sim, o.body);
  add_max_runs_flag(cmd, o.max_runs);
}

}  // namespace

void register_experiment(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("experiment", "the paper's learning experiments (paper §4)");
  cmd->require_subcommand(1);

  auto table = std::make_shared<ExperimentOptions>();
  CLI::App* t = cmd->add_subcommand(
      "table", "every malfunction scenario, N learning runs each (paper Figs. 11, 13)");
  t->add_option("--robot", table->robot,
                "hexapod (24 scenarios), quadruped (4) or a robot file FILE.toml (its layout's "
                "one- and two-leg losses; docs/robots.md)")
      ->check(robot_name())
      ->capture_default_str();
  add_common(*t, *table, experiments::kScenarioRuns, true);
  t->callback([table] {
    const experiments::RobotSpec chosen = experiments::named_robot(table->robot);
    if (!chosen.file && chosen.kind == robot::RobotKind::octopod) {
      throw BadInput(
          "--robot octopod: the paper has scenario tables for the hexapod and "
          "quadruped only");
    }
    print_table(experiments::run_scenario_table(spec_of(*table, chosen)), table->out);
  });

  auto beta = std::make_shared<ExperimentOptions>();
  CLI::App* b = cmd->add_subcommand(
      "beta", "R1+R2 disabled, N runs per beta in 0, 0.1, 0.3, 0.5, 1, 5, 10 (paper Fig. 14)");
  add_common(*b, *beta, experiments::kBetaRuns, false);
  b->callback([beta] {
    print_table(
        experiments::run_beta_study(spec_of(*beta, {robot::RobotKind::hexapod, nullptr, {}}),
                                    experiments::kBetaStudyValues),
        beta->out);
  });

  struct ResultsOptions {
    std::string hexapod, quadruped, beta, out;
  };
  auto results = std::make_shared<ResultsOptions>();
  CLI::App* r = cmd->add_subcommand(
      "results", "write the results page (docs/results.md) from experiment directories");
  r->add_option("--hexapod", results->hexapod, "directory of `experiment table --robot hexapod`");
  r->add_option("--quadruped", results->quadruped,
                "directory of `experiment table --robot quadruped`");
  r->add_option("--beta", results->beta, "directory of `experiment beta`");
  r->add_option("--out", results->out, "the Markdown file to write")->required();
  r->callback([results] {
    experiments::ResultsInputs in;
    in.command = "multicpg experiment results";
    if (!results->hexapod.empty()) {
      in.hexapod = experiments::read_experiment(results->hexapod);
      in.command += " --hexapod " + results->hexapod;
    }
    if (!results->quadruped.empty()) {
      in.quadruped = experiments::read_experiment(results->quadruped);
      in.command += " --quadruped " + results->quadruped;
    }
    if (!results->beta.empty()) {
      in.beta = experiments::read_experiment(results->beta);
      in.command += " --beta " + results->beta;
    }
    if (!in.hexapod && !in.quadruped && !in.beta) {
      throw BadInput("name at least one of --hexapod, --quadruped, --beta");
    }
    in.command += " --out " + results->out;
    write_file_atomic(results->out, experiments::results_markdown(in));
    std::cout << "wrote " << results->out << "\n";
  });
}

}  // namespace multicpg::apps
