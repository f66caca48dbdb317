// multicpg learner-benchmark: every learner replayed against a landscape dataset's scenarios
// over many seeds and scored against the truth (docs/learning.md "Learner benchmark").
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/table.h"
#include "experiments/learner_benchmark.h"
#include "experiments/runner.h"
#include "learning/compensation.h"
#include "learning/landscapes.h"
#include "report/benchmark_figure.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {
namespace {

struct BenchmarkOptions {
  std::string dataset;  // empty: the repository's hexapod dataset walked as --steering says
  std::vector<std::string> learners = experiments::kBenchmarkLearners;
  std::vector<std::string> learner_options;  // LEARNER.KEY=VALUE
  std::vector<std::string> scenarios;
  int seeds = experiments::kDefaultBenchmarkSeeds;
  std::uint64_t seed = 1;
  bool live_seeds = false;
  bool told_nothing = false;
  int budget = experiments::kDefaultBenchmarkBudget;
  int max_trials = learning::kDefaultMaxTrials;
  std::string mode = "robust";
  std::optional<learning::Steering> steering;  // empty: reflex in robust mode, off in paper mode
  int hold_windows = learning::kDefaultHoldWindows;
  int episodes = 1;
  std::string window_order;  // empty: the dataset's (drawn, or walked for a reflex dataset)
  std::optional<int> jobs;
  std::string out;
};

void run(const BenchmarkOptions& o) {
  const learning::Mode mode = learning::parse_mode(o.mode);
  if (mode == learning::Mode::paper && o.steering == learning::Steering::reflex) {
    throw BadInput("--steering reflex: paper mode walks without the reflex");
  }
  if (!o.dataset.empty() && o.steering) {
    throw BadInput(
        "--steering picks the repository's dataset; --dataset names one (leave out "
        "one of them)");
  }
  const bool reflex =
      o.steering.value_or(mode == learning::Mode::paper
                              ? learning::Steering::off
                              : learning::Steering::reflex) == learning::Steering::reflex;
  const std::filesystem::path path =
      o.dataset.empty() ? learning::repository_dataset(robot::RobotKind::hexapod, reflex)
                        : std::filesystem::path(o.dataset);
  const learning::LandscapeDataset probe = learning::read_landscape_dataset(path);
  experiments::LearnerBenchmarkSpec spec = experiments::benchmark_spec(path, probe);
  const robot::Morphology& morph = robot::morphology(probe.robot);
  spec.seeds = o.seeds;
  spec.seed = o.seed;
  spec.live_seeds = o.live_seeds;
  spec.told_nothing = o.told_nothing;
  spec.budget = o.budget;
  spec.search.max_trials = o.max_trials;
  spec.protocol.yaw_only = mode == learning::Mode::paper;
  spec.protocol.hold_windows = o.hold_windows;
  spec.protocol.episodes = o.episodes;
  spec.protocol.window_order =
      o.window_order.empty()
          ? (probe.reflex ? learning::WindowOrder::walked : learning::WindowOrder::drawn)
          : learning::parse_window_order(o.window_order);
  try {
    learning::check_episodes(spec.protocol);
  } catch (const BadInput& e) {
    throw BadInput(std::string("--episodes: ") + e.what());
  }
  if (o.hold_windows > probe.windows) {
    throw BadInput("--hold-windows: the dataset measured " + std::to_string(probe.windows) +
                   " windows per combination, got " + std::to_string(o.hold_windows));
  }
  std::map<std::string, nlohmann::json> given;  // each learner's --learner-option values
  for (const std::string& item : o.learner_options) {
    const std::size_t dot = item.find('.');
    if (dot == std::string::npos || dot == 0 ||
        std::find(o.learners.begin(), o.learners.end(), item.substr(0, dot)) == o.learners.end()) {
      throw BadInput(
          "--learner-option: expected LEARNER.KEY=VALUE for a learner of --learners, "
          "got '" +
          item + "'");
    }
    auto [key, value] = learner_option(item.substr(dot + 1), "--learner-option");
    nlohmann::json& options = given[item.substr(0, dot)];
    if (options.contains(key)) throw BadInput("--learner-option: " + item + " is given twice");
    options[key] = std::move(value);
  }
  for (const std::string& name : o.learners) {
    learning::LearnerChoice choice;
    choice.name = name;
    if (given.count(name)) choice.options = given.at(name);
    try {
      spec.learners.push_back(experiments::resolve_benchmark_learner(choice, spec.dataset));
    } catch (const OptionError& e) {
      throw BadInput("--learners: " + name + ": " + e.key() + " " + std::string(e.what()));
    }
  }
  for (const std::string& s : o.scenarios) {
    spec.scenarios.push_back(parse_leg_flag(morph, s, "--scenarios"));
  }
  ensure_writable_dir(o.out);
  const experiments::LearnerBenchmark b =
      experiments::run_learner_benchmark(spec, o.jobs.value_or(experiments::default_jobs()));
  experiments::write_learner_benchmark(b, o.out);

  const std::optional<report::FigureFiles> figure = report::draw_learner_benchmark(b, o.out);
  const nlohmann::json summary = experiments::benchmark_summary(b);
  const std::size_t holding = experiments::holding_scenarios(b);
  std::cout << morph.name << ", "
            << counted(static_cast<long>(experiments::benchmark_scenarios(b)), "scenario") << " x "
            << counted(spec.seeds, "seed") << " of " << path.string() << " (walked with "
            << probe.walked() << "), " << o.mode << " trials, held within " << spec.budget
            << " trials, pooled over the " << counted(static_cast<long>(holding), "scenario")
            << " where a combination holds (share held with its 95% interval):\n";
  if (holding > 0) {
    std::cout << std::fixed << std::setprecision(1);
    for (const nlohmann::json& l : summary.at("learners")) {
      const auto text = [](const nlohmann::json& v) {
        std::ostringstream s;
        if (v.is_null()) {
          s << "never";
        } else {
          s << std::fixed << std::setprecision(0) << v.get<double>();
        }
        return s.str();
      };
      std::cout << "  " << std::left << std::setw(10) << experiments::benchmark_label(l)
                << std::right << " held " << std::setw(5)
                << 100.0 * l.at("share_held").get<double>() << "% (95% interval "
                << 100.0 * l.at("share_low").get<double>() << "–"
                << 100.0 * l.at("share_high").get<double>() << "%), trials to held: median "
                << text(l.at("median_trials")) << " (quartiles " << text(l.at("q1_trials")) << "–"
                << text(l.at("q3_trials")) << "), false stops " << l.at("false_stops") << "\n";
    }
  } else {
    std::cout << "  nothing pooled: " << report::no_benchmark_figure(b) << "\n";
  }
  std::cout << std::fixed << std::setprecision(1) << "replayed in " << b.seconds << " s; wrote "
            << o.out << "/benchmark.{csv,md}, "
            << (figure ? "benchmark-figure.{png,svg,csv}, " : "") << "runs.csv and summary.json"
            << (figure ? "" : "; no figure: nothing pooled") << "\n";
}

}  // namespace

void register_learner_benchmark(CLI::App& app) {
  auto o = std::make_shared<BenchmarkOptions>();
  CLI::App* cmd = app.add_subcommand(
      "learner-benchmark",
      "replay every learner against a landscape dataset's scenarios and score it against the "
      "truth (docs/learning.md \"Learner benchmark\")");
  cmd->add_option("--dataset", o->dataset,
                  "the landscape dataset (learning/landscapes.h): DIR/NAME of NAME.csv.gz and "
                  "NAME.json (default: the repository's hexapod dataset walked as --steering "
                  "says, data/landscapes/hexapod-reflex in robust mode, data/landscapes/hexapod "
                  "in paper mode)");
  cmd->add_option("--learners", o->learners, "learners to replay, e.g. annealing,bayes")
      ->delimiter(',')
      ->check(one_of(learner_name_list(), "learner"))
      ->capture_default_str();
  cmd->add_option("--learner-option", o->learner_options,
                  "LEARNER.KEY=VALUE, one of a learner's options (repeatable), e.g. bayes.kappa=2");
  cmd->add_option("--scenarios", o->scenarios,
                  "leg sets to replay, e.g. R1,R1+R3 (default: every one of the dataset)")
      ->delimiter(',');
  cmd->add_option("--seeds", o->seeds, "runs per scenario and learner")
      ->check(in(experiments::kBenchmarkSeedsLimits))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "base seed of the runs")
      ->check(seed_value())
      ->capture_default_str();
  cmd->add_flag("--live-seeds", o->live_seeds,
                "seed run k's learner with --seed + k, as `learn --seed` seeds a live run's (with "
                "--window-order walked a replay then retraces that run)");
  cmd->add_flag("--told-nothing", o->told_nothing,
                "also replay every learner told nothing about the fault: it searches every leg's "
                "period, the failed legs' too (docs/learning.md \"What a learner is told\")");
  cmd->add_option("--budget", o->budget, "trials within which a run counts as held")
      ->check(in(experiments::kBenchmarkBudgetLimits))
      ->capture_default_str();
  cmd->add_option("--max-trials", o->max_trials, "each learner's trial cap")
      ->check(in(learning::kMaxTrialsLimits))
      ->capture_default_str();
  cmd->add_option("--mode", o->mode,
                  "how a trial is measured: robust (worst of yaw and path over up to "
                  "--hold-windows windows) or paper (one window's yaw)")
      ->check(one_of(mode_names(), "mode"))
      ->capture_default_str();
  cmd->add_option_function<std::string>(
         "--steering",
         [o](const std::string& text) { o->steering = learning::parse_steering(text); },
         "which of the repository's hexapod datasets: reflex (walked as the default robust run "
         "walks, the default in robust mode) or off (periods alone; paper mode's)")
      ->check(one_of(steering_names(), "steering"));
  cmd->add_option("--hold-windows", o->hold_windows, "robust mode: windows a trial must hold")
      ->check(in(learning::kHoldWindowsLimits))
      ->capture_default_str();
  cmd->add_option("--episodes", o->episodes,
                  "robust mode: learning episodes a run may have; 1: a stop on a combination that "
                  "drifts over the threshold in a later window ends the run (a false stop); "
                  "more: that window starts another episode, its learner told what the earlier "
                  "ones walked, as a live run's monitoring does (walked window order)")
      ->check(in(learning::kMaxEpisodesLimits))
      ->capture_default_str();
  cmd->add_option("--window-order", o->window_order,
                  "which measured windows a trial walks: drawn (a permutation drawn by the seed, "
                  "trial noise) or walked (in the order the landscape walked them, as the "
                  "simulation does); default: drawn, walked for a dataset walked with the "
                  "reflex (it holds each combination's windows only up to the first over the "
                  "threshold)")
      ->check(one_of({std::string(learning::to_string(learning::WindowOrder::drawn)),
                      std::string(learning::to_string(learning::WindowOrder::walked))},
                     "window order"));
  cmd->add_option("--jobs", o->jobs, "threads (default: every core)")
      ->check(in(experiments::kJobsLimits));
  cmd->add_option(
         "--out", o->out,
         "directory for benchmark.{csv,md}, benchmark-figure.{png,svg,csv}, runs.csv, summary.json")
      ->required();
  cmd->callback([o] { run(*o); });
}

}  // namespace multicpg::apps
