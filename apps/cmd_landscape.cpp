// multicpg landscape: every combination of working-leg periods of one leg-failure scenario,
// walked and measured, saved as it finishes (resumable), with its map. The ground
// truth the learners are scored against.
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "experiments/landscape.h"
#include "experiments/processes.h"
#include "experiments/scenarios.h"
#include "experiments/sweep.h"
#include "report/landscape_figure.h"
#include "robot/leg_sets.h"
#include "sim/robot_file.h"

namespace multicpg::apps {
namespace {

struct LandscapeOptions {
  std::string robot = "hexapod";
  std::string disable;
  std::string out;
  std::optional<int> jobs;  // empty = every core
  int windows = experiments::kDefaultLandscapeWindows;
  double threshold = learning::kDefaultThresholdDeg;
  std::vector<int> period_set = learning::AnnealingParams{}.period_set;
  std::string learned;
  sim::SimOptions sim;
  BodyFlags body;
  std::int64_t max_runs = experiments::kDefaultMaxRuns;
};

std::vector<learning::Periods> read_learned(const std::string& path,
                                            const experiments::LandscapeSpec& spec) {
  if (path.empty()) return {};
  std::ifstream in(path);
  if (!in) throw BadInput("--learned: cannot read '" + path + "'");
  try {
    return experiments::parse_learned(nlohmann::json::parse(in), spec);
  } catch (const nlohmann::json::exception& e) {
    throw BadInput("--learned: '" + path + "' is not JSON (" + e.what() + ")");
  }
}

void run(const LandscapeOptions& o) {
  experiments::LandscapeSpec spec;
  if (sim::is_robot_file(o.robot)) {
    spec.robot_file = experiments::load_run_robot_file(o.robot);
    spec.kind = spec.robot_file->file.layout;
  } else {
    spec.kind = robot::parse_robot(o.robot);
  }
  const robot::Morphology& morph = robot::morphology(spec.kind);
  if (o.disable.empty()) throw BadInput("--disable: name at least one leg, e.g. R1");
  spec.disabled = parse_leg_flag(morph, o.disable, "--disable");
  spec.period_set = o.period_set;
  spec.windows = o.windows;
  spec.threshold_deg = o.threshold;
  spec.sim = sim_options(o.sim, o.body, spec.kind);
  experiments::validate(spec);
  if (o.jobs && *o.jobs < 1) {
    throw BadInput("--jobs must be at least 1, got " + std::to_string(*o.jobs));
  }
  const std::vector<learning::Periods> learned = read_learned(o.learned, spec);
  // The same document an experiment file of kind "landscape" holds, resolved the same way.
  const experiments::Sweep sweep =
      experiments::resolve_sweep(experiments::landscape_document(spec), {o.max_runs, "--max-runs"});
  if (experiments::is_primary_process()) ensure_writable_dir(o.out);
  run_landscape_and_report(*sweep.landscape, o.out, o.jobs.value_or(experiments::default_jobs()),
                           learned);
}

}  // namespace

void run_landscape_and_report(const experiments::LandscapeSpec& spec, const std::string& out,
                              int jobs, const std::vector<learning::Periods>& learned) {
  const robot::Morphology& morph = robot::morphology(spec.kind);
  const experiments::Landscape landscape =
      experiments::run_landscape(spec, out, jobs, /*progress=*/true, learned);
  if (!experiments::is_primary_process()) return;  // the primary draws, writes and prints
  const report::FigureFiles figure = report::draw_landscape(landscape, learned, out);

  const nlohmann::json summary = experiments::landscape_summary(landscape, learned);
  std::cout << std::fixed << std::setprecision(1) << morph.name << ", "
            << robot::leg_set_name(morph, spec.disabled) << " disabled: " << summary.at("count")
            << " combinations, " << summary.at("holding") << " hold ("
            << 100.0 * summary.at("share_holding").get<double>() << "%), "
            << 100.0 * summary.at("share_first_window_passing").get<double>()
            << "% pass the first window\n";
  if (const std::optional<std::size_t> best = experiments::best_combination(landscape)) {
    const experiments::CombinationMeasure& m = landscape.combinations[*best];
    std::cout << "best: " << robot::period_map_text(morph, m.periods, spec.disabled)
              << ", worst deviation " << std::setprecision(2) << m.worst_deg << " deg\n";
  } else {
    std::cout << "best: no combination holds\n";
  }
  std::cout << "wrote " << out << "/{landscape.csv,summary.json} and " << figure.png.string()
            << "\n";
}

void register_landscape(CLI::App& app) {
  auto o = std::make_shared<LandscapeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "landscape",
      "walk every combination of working-leg periods of one scenario and map which hold "
      "(resumable)");
  cmd->add_option("--robot", o->robot,
                  "hexapod, quadruped, octopod or a robot file FILE.toml (docs/robots.md)")
      ->capture_default_str();
  cmd->add_option("--disable", o->disable, "legs that fail, e.g. R1 or R1,L2")->required();
  cmd->add_option("--out", o->out, "directory for the runs, CSV, summary and figure (resumes)")
      ->required();
  cmd->add_option("--jobs", o->jobs, "parallel combinations (default: every core)")
      ->check(in(experiments::kJobsLimits));
  cmd->add_option("--windows", o->windows, "400-step windows measured per combination")
      ->check(in(experiments::kLandscapeWindowsLimits))
      ->capture_default_str();
  cmd->add_option("--threshold", o->threshold,
                  "a combination holds when every window's yaw change and path angle are under "
                  "this (deg)")
      ->check(in(learning::kThresholdLimits))
      ->capture_default_str();
  cmd->add_option("--periods-set", o->period_set, "periods each working leg takes")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--learned", o->learned,
                  "JSON array of learned combinations ({leg: period} objects) to mark");
  add_sim_flags(*cmd, o->sim, o->body);
  add_max_runs_flag(*cmd, o->max_runs);
  cmd->callback([o] { run(*o); });
}

}  // namespace multicpg::apps
