// multicpg landscape: every combination of working-leg periods of one leg-failure scenario,
// walked and measured, saved as it finishes (resumable), with its map. The ground
// truth the learners are scored against.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/learning_options.h"
#include "apps/learning_output.h"
#include "apps/options.h"
#include "apps/sim_flags.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "experiments/landscape.h"
#include "experiments/processes.h"
#include "experiments/scenarios.h"
#include "experiments/sweep.h"
#include "report/landscape_figure.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {
namespace {

struct LandscapeOptions {
  std::string robot = "hexapod";
  std::string disable;
  bool every_loss = false;
  std::string out;
  std::optional<int> jobs;  // empty = every core
  int windows = experiments::kDefaultLandscapeWindows;
  double threshold = learning::kDefaultThresholdDeg;
  std::vector<int> period_set = learning::AnnealingParams{}.period_set;
  learning::Steering steering = learning::Steering::off;
  std::string learned;
  sim::SimOptions sim;
  BodyFlags body;
  std::int64_t max_runs = experiments::kDefaultMaxRuns;
};

std::vector<learning::Periods> read_learned(const std::string& path,
                                            const experiments::LandscapeSpec& spec) {
  if (path.empty()) return {};
  std::string text;
  try {
    text = read_input_file(path, kMaxRecordBytes, kMaxRecordText, "a list of learned combinations");
  } catch (const BadInput& e) {
    throw BadInput(std::string("--learned: ") + e.what());
  }
  try {
    return experiments::parse_learned(nlohmann::json::parse(text), spec);
  } catch (const nlohmann::json::exception& e) {
    throw BadInput("--learned: '" + path + "' is not JSON (" + e.what() + ")");
  }
}

void run(const LandscapeOptions& o) {
  experiments::LandscapeSpec spec;
  spec.robot = experiments::named_robot(o.robot);
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  if (o.every_loss && !o.disable.empty()) {
    throw BadInput("--every-loss: walks every leg set itself; leave out --disable");
  }
  if (o.every_loss && !o.learned.empty()) {
    throw BadInput(
        "--learned: marks combinations of one scenario; it does not go with --every-loss");
  }
  if (!o.every_loss && o.disable.empty()) {
    throw BadInput("--disable: name at least one leg, e.g. R1 (or --every-loss)");
  }
  if (!o.every_loss) spec.disabled = parse_leg_flag(morph, o.disable, "--disable");
  spec.period_set = o.period_set;
  spec.windows = o.windows;
  spec.threshold_deg = o.threshold;
  spec.steering = o.steering;
  spec.robot.sim = sim_options(o.sim, o.body, spec.robot.kind);
  if (!o.every_loss) experiments::validate(spec);
  if (o.jobs && *o.jobs < 1) {
    throw BadInput("--jobs must be at least 1, got " + std::to_string(*o.jobs));
  }
  const std::vector<learning::Periods> learned = read_learned(o.learned, spec);
  // The same document an experiment file of kind "landscape" holds, resolved the same way.
  nlohmann::json document = experiments::landscape_document(spec);
  if (o.every_loss) document["scenarios"] = "every";
  const experiments::Sweep sweep = experiments::resolve_sweep(document, {o.max_runs, "--max-runs"});
  if (experiments::is_primary_process()) ensure_writable_dir(o.out);
  run_landscapes_and_report(sweep.landscapes, o.out, o.jobs.value_or(experiments::default_jobs()),
                            learned);
}

// One landscape: what holds and the best.
void report_landscape(const experiments::Landscape& landscape,
                      const std::vector<learning::Periods>& learned, const std::string& out) {
  const experiments::LandscapeSpec& spec = landscape.spec;
  const robot::Morphology& morph = experiments::morphology(spec.robot);
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
  } else if (const std::vector<std::size_t> ranked = experiments::ranked_combinations(landscape);
             !ranked.empty()) {
    // What came closest is what a user tries next (another period set, more legs working).
    const experiments::CombinationMeasure& m = landscape.combinations[ranked.front()];
    std::cout << "best: no combination holds; the closest, "
              << robot::period_map_text(morph, m.periods, spec.disabled) << ", worst deviation "
              << std::setprecision(2) << m.worst_deg << " deg\n";
  } else {
    std::cout << "best: no combination holds\n";
  }
  std::cout << "wrote " << out << "/{landscape.csv,summary.json} and " << figure.png.string()
            << "\n";
}

// A landscape of one scenario keeps OUT/runs and OUT/landscape.csv, a set (--every-loss)
// OUT/<scenario>/runs and OUT/landscapes.{csv.gz,json}: one resumed into the other's directory
// would mix them, so it is refused before anything walks.
void require_landscape_dir(const std::filesystem::path& out, bool set) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (set) {
    for (const char* plain : {"runs", "landscape.csv"}) {
      if (fs::exists(out / plain, ec)) {
        throw BadInput("--out: '" + out.string() + "' holds a landscape of one scenario ('" +
                       (out / plain).string() +
                       "'); a set of every loss (--every-loss) needs a directory of its own");
      }
    }
    return;
  }
  fs::path found;
  if (fs::exists(out / "landscapes.json", ec)) found = out / "landscapes.json";
  for (const fs::directory_entry& e : fs::directory_iterator(out, ec)) {
    if (found.empty() && e.path().filename() != "runs" && fs::is_directory(e.path() / "runs", ec)) {
      found = e.path() / "runs";
    }
  }
  if (!found.empty()) {
    throw BadInput("--out: '" + out.string() + "' holds a set of every loss (--every-loss: '" +
                   found.string() + "'); a landscape of one scenario needs a directory of its own");
  }
}

}  // namespace

void run_landscapes_and_report(const std::vector<experiments::LandscapeSpec>& specs,
                               const std::string& out, int jobs,
                               const std::vector<learning::Periods>& learned) {
  require_landscape_dir(out, specs.size() > 1);
  if (specs.size() == 1) {
    const experiments::Landscape landscape =
        experiments::run_landscape(specs.front(), out, jobs, /*progress=*/true, learned);
    if (experiments::is_primary_process()) report_landscape(landscape, learned, out);
    return;
  }
  const std::vector<experiments::Landscape> landscapes =
      experiments::run_landscape_set(specs, out, jobs, /*progress=*/true);
  if (!experiments::is_primary_process()) return;  // the primary draws, writes and prints
  for (const experiments::Landscape& l : landscapes) {
    report::draw_landscape(l, {}, experiments::landscape_set_dir(out, l.spec));
  }
  const robot::Morphology& morph = experiments::morphology(specs.front().robot);
  std::cout << robot_text(specs.front().robot) << ", " << specs.size()
            << " scenarios (share of combinations that hold):\n";
  std::cout << std::fixed << std::setprecision(1);
  for (const experiments::Landscape& l : landscapes) {
    const nlohmann::json summary = experiments::landscape_summary(l, {});
    std::cout << "  " << std::left << std::setw(10) << robot::leg_set_name(morph, l.spec.disabled)
              << std::right << std::setw(6) << summary.at("holding").get<std::size_t>() << " of "
              << std::setw(5) << summary.at("count").get<std::size_t>() << "  ("
              << 100.0 * summary.at("share_holding").get<double>() << "%)\n";
  }
  std::cout << "wrote " << out << "/<scenario>/ and the dataset "
            << experiments::landscape_set_dataset(out).string() << ".{csv.gz,json}\n";
}

void register_landscape(CLI::App& app) {
  auto o = std::make_shared<LandscapeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "landscape",
      "walk every combination of working-leg periods of one scenario and map which hold "
      "(resumable)");
  cmd->add_option("--robot", o->robot,
                  "hexapod, quadruped, octopod or a robot file FILE.toml (docs/robots.md)")
      ->check(robot_name())
      ->capture_default_str();
  cmd->add_option("--disable", o->disable, "legs that fail, e.g. R1 or R1,L2");
  cmd->add_flag("--every-loss", o->every_loss,
                "every loss of one to three legs, each in OUT/<legs>, and their dataset "
                "OUT/landscapes.{csv.gz,json} (docs/learning.md \"The landscape dataset\")");
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
  cmd->add_option_function<std::string>(
         "--steering",
         [o](const std::string& text) { o->steering = learning::parse_steering(text); },
         "off: periods alone, every window walked; reflex: as the default robust run walks, each "
         "combination a first trial with the steering reflex, until its first window over the "
         "threshold (docs/learning.md \"The landscape dataset\")")
      ->check(one_of(steering_names(), "steering"))
      ->default_str(std::string(learning::to_string(o->steering)));
  cmd->add_option("--learned", o->learned,
                  "JSON array of learned combinations ({leg: period} objects) to mark");
  add_sim_flags(*cmd, o->sim, o->body);
  add_max_runs_flag(*cmd, o->max_runs);
  cmd->callback([o] { run(*o); });
}

}  // namespace multicpg::apps
