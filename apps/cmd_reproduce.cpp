// multicpg reproduce: every figure, table and video of the paper into one folder.
#include <algorithm>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/sim_flags.h"
#include "common/errors.h"
#include "experiments/runner.h"
#include "report/figures.h"
#include "report/reproduce.h"

namespace multicpg::apps {
namespace {

std::string known_names() {
  std::string out;
  for (const report::FigureInfo& f : report::known_figures()) {
    out += (out.empty() ? "" : ", ") + std::string(f.name);
  }
  return out;
}

}  // namespace

void register_reproduce(CLI::App& app) {
  struct Options {
    report::ReproduceOptions run;
    std::optional<int> jobs;
    BodyFlags body;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "reproduce", "run every experiment of the paper and write DIR/index.html (resumable)");
  cmd->add_option("--out", o->run.out, "folder for the report")->required();
  cmd->add_flag("--quick", o->run.quick,
                "one learning run per scenario and per β, Table 1 side by side on this run's body "
                "alone, shorter and faster videos (measured: 71 s on 2 idle cores; "
                "docs/benchmarks.md)");
  cmd->add_option("--jobs", o->jobs, "parallel learning runs (default: every core)")
      ->check(in(experiments::kJobsLimits));
  cmd->add_option("--seed", o->run.seed, "base seed of every learning run")
      ->check(seed_value())
      ->capture_default_str();
  add_body_flags(*cmd, o->body);
  cmd->callback([o] {
    if (o->jobs && *o->jobs < 1) {
      throw BadInput("--jobs must be at least 1, got " + std::to_string(*o->jobs));
    }
    o->run.jobs = o->jobs.value_or(0);
    // One body for every stage: the hexapod's and the quadruped's experiments.
    sim_options({}, o->body, robot::RobotKind::quadruped);
    o->run.sim = sim_options({}, o->body, robot::RobotKind::hexapod);
    report::reproduce(o->run);
    std::cout << "open " << (o->run.out / "index.html").string() << "\n";
  });
}

void register_figure(CLI::App& app) {
  struct Options {
    std::vector<std::string> names;
    report::ReproduceOptions run;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "figure", "draw some of the paper's figures (and their CSV) into DIR: " + known_names());
  cmd->add_option("names", o->names, "figure names")->required();
  cmd->add_option("--out", o->run.out, "folder for the figures and index.html")->required();
  cmd->add_flag("--quick", o->run.quick, "few learning runs for the learning tables");
  cmd->add_option("--seed", o->run.seed, "base seed of the learning runs")
      ->check(seed_value())
      ->capture_default_str();
  cmd->callback([o] {
    for (const std::string& name : o->names) {
      const std::string stage = report::stage_of_figure(name);
      if (std::find(o->run.only.begin(), o->run.only.end(), stage) == o->run.only.end()) {
        o->run.only.push_back(stage);
      }
    }
    report::reproduce(o->run);
    std::cout << "figures in " << (o->run.out / "figures").string() << "; open "
              << (o->run.out / "index.html").string() << "\n";
  });
}

}  // namespace multicpg::apps
