// The learner benchmark (docs/learning.md "Learner benchmark"): every learner replayed against
// every scenario of a landscape dataset (learning/benchmark.h) over many seeds, scored against
// the truth, beside the two exact baselines of each landscape (random search's expected trials,
// the oracle's one).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/limits.h"
#include "common/table.h"
#include "learning/benchmark.h"
#include "learning/landscapes.h"
#include "learning/learners.h"

namespace multicpg::experiments {

// Trials within which a run counts as held: the paper's annealing needs about 20 (paper §4).
inline constexpr int kDefaultBenchmarkBudget = 20;
inline constexpr int kDefaultBenchmarkSeeds = 100;
inline constexpr Limits<int> kBenchmarkSeedsLimits{1, 100'000};
inline constexpr Limits<int> kBenchmarkBudgetLimits{1, 100'000};

struct LearnerBenchmarkSpec {
  std::filesystem::path dataset;                  // learning/landscapes.h
  std::vector<learning::LearnerChoice> learners;  // resolved
  int seeds = kDefaultBenchmarkSeeds;
  std::uint64_t seed = 1;  // run k of a scenario has seed derive_seed(seed, "<scenario>#k")
  // Run k's learner is seeded with seed + k, as `learn --seed <seed + k>` seeds a live run's,
  // instead of from its run seed (learning::replay_run's learner_seed).
  bool live_seeds = false;
  int budget = kDefaultBenchmarkBudget;
  learning::SearchBounds search;  // the dataset's period set and threshold; the trial cap
  learning::TrialProtocol protocol;
  std::vector<std::vector<std::size_t>> scenarios;  // empty: every scenario of the dataset
  // Also replay every learner told nothing about the fault (the price of not knowing,
  // docs/learning.md "What a learner is told"), beside it told the failed legs.
  bool told_nothing = false;
};

// One learner as a benchmark replays it: its choice, what it is told, and its name in the
// tables ("prior", "prior, told nothing").
struct BenchmarkEntry {
  std::size_t learner = 0;  // index into LearnerBenchmarkSpec::learners
  learning::Told told = learning::Told::failed_legs;
  std::string label;
};
// Each learner told the failed legs, then (told_nothing) each told nothing: the cells' order
// within a scenario.
std::vector<BenchmarkEntry> benchmark_entries(const LearnerBenchmarkSpec& spec);

// One learner on one scenario over its seeds.
struct BenchmarkCell {
  std::string scenario;
  std::string learner;
  std::size_t combinations = 0;
  std::size_t holding = 0;  // in the landscape
  int runs = 0;
  int deviated = 0;         // runs whose start deviated (the others never learn)
  int held_within = 0;      // stopped, held, on a holding combination within the budget
  double share_held = 0.0;  // held_within / runs
  double share_low = 0.0;   // its 95% Wilson interval
  double share_high = 0.0;
  // Quartiles of the trials to a held combination over all runs (a run that never held counts
  // as more than any); empty where more than that share of runs never held.
  std::optional<double> q1, median, q3;
  int false_stops = 0;
  double mean_trials = 0.0;                   // over the runs, however they ended
  double mean_gap_deg = 0.0;                  // answer's worst deviation minus the landscape's best
  std::optional<double> random_expected;      // (N + 1) / (K + 1), none when nothing holds
  std::vector<learning::ReplayRun> run_list;  // each seed's run
};

struct LearnerBenchmark {
  LearnerBenchmarkSpec spec;
  learning::LandscapeDataset dataset;
  std::vector<BenchmarkCell> cells;  // scenario by scenario, each learner in spec order
  double seconds = 0.0;              // wall time of the replays
};

// Wilson's score interval (95 %) of a binomial share (Wilson 1927): well behaved at 0 and 1,
// where the normal approximation is not; {0, 0} for no trials.
std::pair<double, double> wilson_interval(int successes, int n);

// The learners the benchmark replays unless told otherwise: the paper's and every other one.
inline const std::vector<std::string> kBenchmarkLearners{"annealing", "random", "greedy", "bayes",
                                                         "prior"};

// A spec for `dataset`, read from `path`: its period set and threshold, the default protocol
// and no learner yet.
LearnerBenchmarkSpec benchmark_spec(const std::filesystem::path& path,
                                    const learning::LandscapeDataset& dataset);
// `asked` resolved for a benchmark over `dataset`: a learner that learns from landscapes and is
// not told which learns from the other scenarios of this dataset. Throws OptionError as
// learning::resolve_learner does.
learning::LearnerChoice resolve_benchmark_learner(learning::LearnerChoice asked,
                                                  const std::filesystem::path& dataset);

// Throws BadInput for an unreadable dataset, an unknown scenario, or search bounds that do not
// fit it. Runs on `jobs` threads; the results do not depend on them.
LearnerBenchmark run_learner_benchmark(const LearnerBenchmarkSpec& spec, int jobs);

// benchmark.csv: a row per scenario and learner. runs.csv: a row per run.
Table benchmark_table(const LearnerBenchmark& b);
Table benchmark_runs_table(const LearnerBenchmark& b);
// The per-learner totals over the scenarios with at least one holding combination (pooled
// runs), and the options that decided the results.
nlohmann::json benchmark_summary(const LearnerBenchmark& b);
// A summary learner's name in tables: its name, with ", told nothing" when it was told nothing.
std::string benchmark_label(const nlohmann::json& summary_learner);
// How many scenarios `b` replayed.
std::size_t benchmark_scenarios(const LearnerBenchmark& b);
// How many scenarios of `b` have a combination that holds: those the pooled scores sum.
std::size_t holding_scenarios(const LearnerBenchmark& b);
// benchmark.md, for reading: a caption (what was replayed, how a run is scored), a row per
// scenario and learner in words ("never" for a quartile among the runs that never held) and a
// pooled row per learner.
std::string benchmark_markdown(const LearnerBenchmark& b);
// Writes OUT/benchmark.{csv,md}, OUT/runs.csv, OUT/summary.json.
void write_learner_benchmark(const LearnerBenchmark& b, const std::filesystem::path& out);

}  // namespace multicpg::experiments
