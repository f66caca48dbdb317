#include "experiments/learner_benchmark.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <set>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/interrupt.h"
#include "common/worker_threads.h"
#include "experiments/runner.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {
namespace {

constexpr int kJsonIndent = 2;
// benchmark.md's words for what has no number: a quartile among the runs that never held, and a
// baseline of a scenario where nothing holds.
constexpr const char* kNever = "never";
constexpr const char* kNoneHolds = "none holds";
constexpr double kZ95 = 1.959963984540054;  // the normal quantile of a two-sided 95% interval

// The q-quantile (nearest rank) of `values` where `missing` more values are larger than any;
// none when the rank falls among the missing.
std::optional<double> quantile(std::vector<double> values, std::size_t missing, double q) {
  const std::size_t n = values.size() + missing;
  if (n == 0) return std::nullopt;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(n)));
  const std::size_t index = rank == 0 ? 0 : rank - 1;
  if (index >= values.size()) return std::nullopt;
  std::sort(values.begin(), values.end());
  return values[index];
}

BenchmarkCell score(const learning::ScenarioLandscape& s, const std::string& name,
                    const std::string& learner, std::vector<learning::ReplayRun> runs, int budget) {
  BenchmarkCell c;
  c.scenario = name;
  c.learner = learner;
  c.combinations = s.points.size();
  c.holding = s.holding();
  c.runs = static_cast<int>(runs.size());
  c.random_expected = learning::random_expected_trials(s);
  std::vector<double> held;
  const double best = s.points[s.best()].worst_deg;
  double trials = 0.0;
  double gap = 0.0;
  for (const learning::ReplayRun& r : runs) {
    c.deviated += r.deviated ? 1 : 0;
    // A start that never deviated holds in its first window, but counts as held only if it
    // holds in truth (then it needed no trial).
    const std::optional<int> at = r.deviated       ? r.held_at
                                  : r.answer_holds ? std::optional<int>(0)
                                                   : std::nullopt;
    if (at && *at <= budget) ++c.held_within;
    if (at) held.push_back(*at);
    c.false_stops += r.false_stop || (!r.deviated && !r.answer_holds) ? 1 : 0;
    trials += r.trials;
    gap += r.answer_worst_deg - best;
  }
  c.share_held = c.runs == 0 ? 0.0 : static_cast<double>(c.held_within) / c.runs;
  std::tie(c.share_low, c.share_high) = wilson_interval(c.held_within, c.runs);
  const std::size_t missing = runs.size() - held.size();
  c.q1 = quantile(held, missing, 0.25);
  c.median = quantile(held, missing, 0.5);
  c.q3 = quantile(held, missing, 0.75);
  c.mean_trials = c.runs == 0 ? 0.0 : trials / c.runs;
  c.mean_gap_deg = c.runs == 0 ? 0.0 : gap / c.runs;
  c.run_list = std::move(runs);
  return c;
}

std::string optional_cell(const std::optional<double>& v, int decimals) {
  return v ? fixed(*v, decimals) : "-";
}

}  // namespace

LearnerBenchmark run_learner_benchmark(const LearnerBenchmarkSpec& spec, int jobs) {
  LearnerBenchmark b;
  b.spec = spec;
  b.dataset = learning::read_landscape_dataset(spec.dataset);
  const robot::Morphology& morph = robot::morphology(b.dataset.robot);
  std::vector<const learning::ScenarioLandscape*> scenarios;
  if (spec.scenarios.empty()) {
    for (const learning::ScenarioLandscape& s : b.dataset.scenarios) scenarios.push_back(&s);
  }
  for (const std::vector<std::size_t>& legs : spec.scenarios) {
    const learning::ScenarioLandscape* s = b.dataset.find(legs);
    if (s == nullptr) {
      throw BadInput("the dataset has no scenario " + robot::leg_set_name(morph, legs));
    }
    scenarios.push_back(s);
  }
  // Each learner's data resolved once, checked for every scenario it replays with that scenario
  // withheld, as replay_run withholds it.
  const learning::Criterion criterion = learning::replay_criterion(b.dataset, spec.protocol);
  std::vector<learning::LearnerData> data;
  for (const learning::LearnerChoice& l : spec.learners) {
    data.push_back(learning::learner_data(l, b.dataset.robot, criterion));
    for (const learning::ScenarioLandscape* s : scenarios) {
      learning::LearnerData unseen = data.back();
      unseen.withheld = {s->failed};
      learning::check_learner(l, unseen, b.dataset.robot, learning::ToldFault::legs(s->failed),
                              criterion);
      if (spec.told_nothing) {
        learning::check_learner(l, unseen, b.dataset.robot, learning::ToldFault::nothing(),
                                criterion);
      }
    }
  }

  // One job per scenario and entry, its seeds in order; results land in their own cell.
  const std::vector<BenchmarkEntry> entries = benchmark_entries(spec);
  const std::size_t cells = scenarios.size() * entries.size();
  b.cells.resize(cells);
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto start = std::chrono::steady_clock::now();
  const auto work = [&] {
    for (std::size_t i = next++; i < cells; i = next++) {
      const learning::ScenarioLandscape& s = *scenarios[i / entries.size()];
      const BenchmarkEntry& e = entries[i % entries.size()];
      const learning::LearnerChoice& l = spec.learners[e.learner];
      const learning::LearnerData& d = data[e.learner];
      const std::string name = robot::leg_set_name(morph, s.failed);
      try {
        std::vector<learning::ReplayRun> runs;
        for (int k = 0; k < spec.seeds; ++k) {
          check_interrupted();  // a replay takes milliseconds: SIGINT stops the threads at once
          const std::uint64_t seed = derive_seed(spec.seed, name + "#" + std::to_string(k));
          std::optional<std::uint64_t> learner_seed;
          if (spec.live_seeds) learner_seed = spec.seed + static_cast<std::uint64_t>(k);
          runs.push_back(learning::replay_run(b.dataset, s, l, d, spec.search, spec.protocol, seed,
                                              learner_seed, e.told));
        }
        b.cells[i] = score(s, name, e.label, std::move(runs), spec.budget);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = cells;
      }
    }
  };
  WorkerThreads(static_cast<std::size_t>(std::max(1, jobs)), work).join();
  if (error) std::rethrow_exception(error);
  b.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return b;
}

Table benchmark_table(const LearnerBenchmark& b) {
  Table t;
  for (const char* c : {"scenario", "learner"}) t.columns.push_back({c, Align::left});
  for (const char* c :
       {"combinations", "holding", "runs", "held_within_budget", "share_held", "share_low",
        "share_high", "q1_trials", "median_trials", "q3_trials", "false_stops", "mean_trials",
        "mean_gap_deg", "random_expected_trials", "oracle_trials"}) {
    t.columns.push_back({c});
  }
  for (const BenchmarkCell& c : b.cells) {
    t.add_row({c.scenario, c.learner, std::to_string(c.combinations), std::to_string(c.holding),
               std::to_string(c.runs), std::to_string(c.held_within), fixed(c.share_held, 3),
               fixed(c.share_low, 3), fixed(c.share_high, 3), optional_cell(c.q1, 0),
               optional_cell(c.median, 0), optional_cell(c.q3, 0), std::to_string(c.false_stops),
               fixed(c.mean_trials, 1), fixed(c.mean_gap_deg, 2),
               optional_cell(c.random_expected, 1), c.holding > 0 ? "1" : "-"});
  }
  return t;
}

Table benchmark_runs_table(const LearnerBenchmark& b) {
  Table t;
  for (const char* c : {"scenario", "learner"}) t.columns.push_back({c, Align::left});
  for (const char* c : {"run", "deviated", "trials", "episodes", "reason", "held_at", "false_stop",
                        "answer_holds", "answer_worst_deg", "first_holding_tried"}) {
    t.columns.push_back({c});
  }
  for (const BenchmarkCell& c : b.cells) {
    for (std::size_t k = 0; k < c.run_list.size(); ++k) {
      const learning::ReplayRun& r = c.run_list[k];
      t.add_row({c.scenario, c.learner, std::to_string(k), r.deviated ? "1" : "0",
                 std::to_string(r.trials), std::to_string(r.episodes),
                 r.deviated ? std::string(learning::to_string(r.reason)) : "no deviation",
                 r.held_at ? std::to_string(*r.held_at) : "", r.false_stop ? "1" : "0",
                 r.answer_holds ? "1" : "0", shortest(r.answer_worst_deg),
                 r.first_holding_tried ? std::to_string(*r.first_holding_tried) : ""});
    }
  }
  return t;
}

std::pair<double, double> wilson_interval(int successes, int n) {
  if (n == 0) return {0.0, 0.0};
  const double p = static_cast<double>(successes) / n;
  const double z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = kZ95 / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  // At p = 0 and p = 1 the bound is exactly 0 or 1; rounding would put the share outside.
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half),
          successes == n ? 1.0 : std::min(1.0, centre + half)};
}

LearnerBenchmarkSpec benchmark_spec(const std::filesystem::path& path,
                                    const learning::LandscapeDataset& dataset) {
  LearnerBenchmarkSpec spec;
  spec.dataset = path;
  spec.search.period_set = dataset.period_set;
  spec.search.threshold_deg = dataset.threshold_deg;
  return spec;
}

learning::LearnerChoice resolve_benchmark_learner(learning::LearnerChoice asked,
                                                  const std::filesystem::path& dataset) {
  learning::LearnerChoice resolved = learning::resolve_learner(asked);
  if (resolved.options.contains("dataset") && !asked.options.contains("dataset")) {
    asked.options["dataset"] = dataset.string();
    resolved = learning::resolve_learner(asked);
  }
  return resolved;
}

nlohmann::json benchmark_summary(const LearnerBenchmark& b) {
  const LearnerBenchmarkSpec& s = b.spec;
  nlohmann::json learners = nlohmann::json::array();
  for (const BenchmarkEntry& e : benchmark_entries(s)) {
    const learning::LearnerChoice& l = s.learners[e.learner];
    // Pooled over the scenarios where something holds.
    int runs = 0;
    int held = 0;
    int false_stops = 0;
    std::vector<double> trials;
    std::size_t missing = 0;
    double worst_share = 1.0;
    for (const BenchmarkCell& c : b.cells) {
      if (c.learner != e.label || c.holding == 0) continue;
      runs += c.runs;
      held += c.held_within;
      false_stops += c.false_stops;
      worst_share = std::min(worst_share, c.share_held);
      for (const learning::ReplayRun& r : c.run_list) {
        const std::optional<int> at = r.deviated       ? r.held_at
                                      : r.answer_holds ? std::optional<int>(0)
                                                       : std::nullopt;
        if (at) {
          trials.push_back(*at);
        } else {
          ++missing;
        }
      }
    }
    const auto [low, high] = wilson_interval(held, runs);
    const auto q = [&](double p) {
      const std::optional<double> v = quantile(trials, missing, p);
      return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    learners.push_back({{"learner", l},
                        {"runs", runs},
                        {"held_within_budget", held},
                        {"share_held", runs == 0 ? 0.0 : static_cast<double>(held) / runs},
                        {"share_low", low},
                        {"share_high", high},
                        {"worst_scenario_share_held", worst_share},
                        {"q1_trials", q(0.25)},
                        {"median_trials", q(0.5)},
                        {"q3_trials", q(0.75)},
                        {"false_stops", false_stops}});
    if (e.told == learning::Told::nothing) learners.back()["told"] = "nothing";
  }
  return {{"dataset", s.dataset.string()},
          {"robot", robot::to_string(b.dataset.robot)},
          {"seeds", s.seeds},
          {"seed", s.seed},
          {"live_seeds", s.live_seeds},
          {"budget", s.budget},
          {"max_trials", s.search.max_trials},
          {"threshold_deg", s.search.threshold_deg},
          {"yaw_only", s.protocol.yaw_only},
          {"hold_windows", s.protocol.hold_windows},
          {"window_order", learning::to_string(s.protocol.window_order)},
          {"episodes", s.protocol.episodes},
          {"scenarios", benchmark_scenarios(b)},
          {"holding_scenarios", holding_scenarios(b)},
          {"learners", learners}};
}

std::vector<BenchmarkEntry> benchmark_entries(const LearnerBenchmarkSpec& spec) {
  std::vector<BenchmarkEntry> out;
  for (std::size_t i = 0; i < spec.learners.size(); ++i) {
    out.push_back({i, learning::Told::failed_legs, spec.learners[i].name});
  }
  if (spec.told_nothing) {
    for (std::size_t i = 0; i < spec.learners.size(); ++i) {
      out.push_back({i, learning::Told::nothing, spec.learners[i].name + ", told nothing"});
    }
  }
  return out;
}

std::string benchmark_label(const nlohmann::json& summary_learner) {
  const std::string name = summary_learner.at("learner").at("name").get<std::string>();
  return summary_learner.value("told", "") == "nothing" ? name + ", told nothing" : name;
}

std::size_t benchmark_scenarios(const LearnerBenchmark& b) {
  return b.cells.size() / std::max<std::size_t>(1, benchmark_entries(b.spec).size());
}

std::size_t holding_scenarios(const LearnerBenchmark& b) {
  std::set<std::string> holding;
  for (const BenchmarkCell& c : b.cells) {
    if (c.holding > 0) holding.insert(c.scenario);
  }
  return holding.size();
}

std::string benchmark_markdown(const LearnerBenchmark& b) {
  const LearnerBenchmarkSpec& s = b.spec;
  const std::string budget = std::to_string(s.budget);
  Table t;
  for (const char* c : {"scenario", "learner"}) t.columns.push_back({c, Align::left});
  for (const std::string& c :
       {std::string("combinations"), std::string("holding"), std::string("runs"),
        "held within " + budget + " trials", std::string("share held")}) {
    t.columns.push_back({c});
  }
  t.columns.push_back({"95 % interval", Align::left});
  t.columns.push_back({"trials to held: median (quartiles)", Align::left});
  for (const char* c : {"false stops", "mean trials", "gap to best (°)",
                        "random search: expected trials", "oracle: trials"}) {
    t.columns.push_back({c});
  }
  const auto percent = [](double share) { return fixed(100.0 * share, 1) + " %"; };
  const auto trials = [](const std::optional<double>& median, const std::optional<double>& q1,
                         const std::optional<double>& q3) {
    const auto text = [](const std::optional<double>& v) {
      return v ? fixed(*v, 0) : std::string(kNever);
    };
    return text(median) + " (" + text(q1) + "–" + text(q3) + ")";
  };
  for (const BenchmarkCell& c : b.cells) {
    t.add_row({c.scenario, c.learner, std::to_string(c.combinations), std::to_string(c.holding),
               std::to_string(c.runs), std::to_string(c.held_within), percent(c.share_held),
               percent(c.share_low) + "–" + percent(c.share_high), trials(c.median, c.q1, c.q3),
               std::to_string(c.false_stops), fixed(c.mean_trials, 1), fixed(c.mean_gap_deg, 2),
               c.random_expected ? fixed(*c.random_expected, 1) : std::string(kNoneHolds),
               c.holding > 0 ? "1" : kNoneHolds});
  }
  const std::size_t holding = holding_scenarios(b);
  const nlohmann::json summary = benchmark_summary(b);
  const auto optional = [](const nlohmann::json& v) {
    return v.is_null() ? std::nullopt : std::optional<double>(v.get<double>());
  };
  if (holding > 0) {
    for (const nlohmann::json& l : summary.at("learners")) {
      t.add_row({"pooled (" + counted(static_cast<long>(holding), "scenario") + ")",
                 benchmark_label(l), "", "", std::to_string(l.at("runs").get<int>()),
                 std::to_string(l.at("held_within_budget").get<int>()),
                 percent(l.at("share_held").get<double>()),
                 percent(l.at("share_low").get<double>()) + "–" +
                     percent(l.at("share_high").get<double>()),
                 trials(optional(l.at("median_trials")), optional(l.at("q1_trials")),
                        optional(l.at("q3_trials"))),
                 std::to_string(l.at("false_stops").get<int>()), "", "", "", ""});
    }
  }
  const std::string scenarios = counted(static_cast<long>(benchmark_scenarios(b)), "scenario");
  const std::string protocol =
      s.protocol.yaw_only
          ? "paper trials (one window's yaw)"
          : "robust trials (up to " + counted(s.protocol.hold_windows, "window") +
                ", worst of yaw and path angle" +
                (s.protocol.episodes > 1
                     ? "; up to " + counted(s.protocol.episodes, "episode") +
                           ", a later window of the combination stopped on over the threshold "
                           "starting the next, trials counted over all of them"
                     : std::string()) +
                ")";
  return "# Learner benchmark: " + std::string(robot::to_string(b.dataset.robot)) + ", " +
         scenarios + " x " + counted(s.seeds, "seed") + "\n\n" +
         "Each learner replayed on the landscape dataset `" + s.dataset.string() + "` with " +
         protocol + ", windows " + std::string(learning::to_string(s.protocol.window_order)) +
         ", at most " + std::to_string(s.search.max_trials) + " trials, seed " +
         std::to_string(s.seed) +
         " (docs/learning.md \"Learner benchmark\"). A run is held when its answer holds every "
         "window the landscape measured (under " +
         shortest(s.search.threshold_deg) + "°), reached within " + budget +
         " trials. Trials to held: quartiles over the runs, a run that never held counting as "
         "more than any (\"" +
         kNever + "\": that share of runs never held). \"" + kNoneHolds +
         "\": the scenario has no combination that holds. " +
         (holding > 0
              ? "The pooled rows sum the " + counted(static_cast<long>(holding), "scenario") +
                    " where a combination holds (summary.json)."
              : "No scenario here has a combination that holds: nothing is pooled.") +
         "\n\n" + to_markdown(t);
}

void write_learner_benchmark(const LearnerBenchmark& b, const std::filesystem::path& out) {
  const Table table = benchmark_table(b);
  write_file_atomic(out / "benchmark.csv", to_csv(table));
  write_file_atomic(out / "benchmark.md", benchmark_markdown(b));
  write_file_atomic(out / "runs.csv", to_csv(benchmark_runs_table(b)));
  write_file_atomic(out / "summary.json", benchmark_summary(b).dump(kJsonIndent) + "\n");
}

}  // namespace multicpg::experiments
