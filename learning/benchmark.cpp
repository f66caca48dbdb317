#include "learning/benchmark.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <string>

#include "body/deviation.h"
#include "common/enum_names.h"
#include "common/errors.h"
#include "common/random.h"
#include "common/user_text.h"

namespace multicpg::learning {
namespace {

constexpr auto kWindowOrderNames =
    enum_names<WindowOrder>({{WindowOrder::drawn, "drawn"}, {WindowOrder::walked, "walked"}});

// Keys of the two streams a run draws from.
constexpr std::uint64_t kLearnerStream = 1;
constexpr std::uint64_t kWindowStream = 2;

// The windows the `visit`-th measurement of `combination` walks, in order: a permutation of
// the landscape's windows drawn from (seed, combination, visit) alone.
std::vector<std::size_t> drawn_windows(std::uint64_t seed, std::size_t combination, int visit,
                                       std::size_t windows) {
  std::mt19937_64 rng(splitmix64(splitmix64(splitmix64(seed ^ kWindowStream) ^ combination) ^
                                 static_cast<std::uint64_t>(visit)));
  std::vector<std::size_t> order(windows);
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t i = 0; i + 1 < windows; ++i) {
    std::swap(order[i], order[i + draw_below(rng, windows - i)]);
  }
  return order;
}

}  // namespace

std::string_view to_string(WindowOrder order) {
  return kWindowOrderNames.name(order);
}

WindowOrder parse_window_order(std::string_view text) {
  if (const std::optional<WindowOrder> order = kWindowOrderNames.find(text)) return *order;
  throw BadInput(unknown_name("window order", text, kWindowOrderNames.names()));
}

void check_episodes(const TrialProtocol& protocol) {
  if (protocol.episodes < 1) throw BadInput("a run has at least one episode");
  if (protocol.episodes > 1 &&
      (protocol.yaw_only || protocol.window_order != WindowOrder::walked)) {
    throw BadInput(
        "more than one episode replays robust mode's monitoring, which walks a "
        "combination's windows on in the order walked (--window-order walked)");
  }
}

Criterion replay_criterion(const LandscapeDataset& dataset, const TrialProtocol& protocol) {
  if (protocol.yaw_only) return kPaperCriterion;
  Criterion c = dataset.criterion();
  c.trial_windows = protocol.hold_windows;
  return c;
}

ReplayRun replay_run(const LandscapeDataset& dataset, const ScenarioLandscape& scenario,
                     const LearnerChoice& choice, const LearnerData& data,
                     const SearchBounds& search, const TrialProtocol& protocol, std::uint64_t seed,
                     std::optional<std::uint64_t> learner_seed, Told told) {
  if (search.period_set != dataset.period_set) {
    throw BadInput("the search's period set is not the landscape's");
  }
  if (search.threshold_deg != dataset.threshold_deg) {
    throw BadInput("the search's threshold is not the landscape's (" +
                   std::to_string(dataset.threshold_deg) + " deg)");
  }
  if (protocol.hold_windows < 1 || protocol.hold_windows > dataset.windows) {
    throw BadInput("hold windows must be in 1.." + std::to_string(dataset.windows));
  }
  if (dataset.reflex && protocol.yaw_only) {
    throw BadInput("the dataset was walked with " + dataset.walked() +
                   ", which paper mode does not use: replay paper mode on a dataset of periods "
                   "alone");
  }
  check_episodes(protocol);
  if (dataset.reflex && protocol.window_order == WindowOrder::drawn) {
    throw BadInput("the dataset was walked with " + dataset.walked() +
                   " up to each combination's first window over the threshold, so its windows "
                   "replay only in the order walked (--window-order walked)");
  }
  const Criterion criterion = replay_criterion(dataset, protocol);
  const robot::Morphology& morph = robot::morphology(dataset.robot);
  const Periods start(morph.size(), kStartPeriod);
  const std::optional<std::size_t> c0 = scenario.find(start);
  if (!c0) throw BadInput("the landscape lacks the start combination (every leg at 4)");

  std::map<std::size_t, int> visits;
  std::vector<std::size_t> walked(static_cast<std::size_t>(dataset.windows));
  std::iota(walked.begin(), walked.end(), 0);
  const auto windows_of = [&](std::size_t point) {
    return protocol.window_order == WindowOrder::walked
               ? walked
               : drawn_windows(seed, point, visits[point]++, walked.size());
  };
  const auto measure = [&](std::size_t point) {
    const std::vector<std::size_t> order = windows_of(point);
    const LandscapePoint& p = scenario.points[point];
    Measurement m;
    const int windows = protocol.yaw_only ? 1 : protocol.hold_windows;
    for (int w = 0; w < windows; ++w) {
      // A window not walked follows one over the threshold, where the trial has stopped.
      const body::WindowMeasure& window = p.windows.at(order[w]);
      m.windows.push_back(window);
      m.deviation_deg = std::max(m.deviation_deg, criterion.error(window));
      if (!body::holds(m.deviation_deg, search.threshold_deg)) break;
    }
    return m;
  };

  ReplayRun run;
  const auto finish = [&](const Answer& answer) {
    run.answer = answer.periods;
    const LandscapePoint& p = scenario.points[*scenario.find(answer.periods)];
    run.answer_holds = p.holds;
    run.answer_worst_deg = p.worst_deg;
    return run;
  };
  // Detection: one window (paper §3 step 2; robust mode judges its windows one at a time): with
  // the reflex the window its start walk ended with, else one of the start combination's.
  const body::WindowMeasure detecting =
      dataset.reflex ? scenario.start_windows.back()
                     : scenario.points[*c0].windows.at(windows_of(*c0).front());
  const double e0 = criterion.error(detecting);
  if (body::holds(e0, search.threshold_deg)) {
    finish({start, e0});
    if (dataset.reflex) {
      // The start walk itself is the truth: every one of its windows held, so the live run
      // walks on as it was, learning nothing.
      run.answer_holds = true;
      run.answer_worst_deg = 0.0;
      for (const body::WindowMeasure& w : scenario.start_windows) {
        run.answer_worst_deg = std::max(run.answer_worst_deg, criterion.error(w));
      }
    }
    return run;
  }
  run.deviated = true;

  LearnerSetup setup;
  setup.robot = dataset.robot;
  setup.start = start;
  setup.told = told == Told::failed_legs ? ToldFault::legs(scenario.failed) : ToldFault::nothing();
  setup.start_deviation_deg = e0;
  setup.start_windows = {detecting};
  setup.criterion = criterion;
  setup.search = search;
  const std::uint64_t first_seed = learner_seed.value_or(splitmix64(seed ^ kLearnerStream));
  LearnerData unseen = data;
  unseen.withheld = {scenario.failed};
  for (int episode = 1;; ++episode) {
    // Episode k + 1 draws from its own stream, as a live run's (learning/compensation.cpp).
    setup.seed = first_seed + static_cast<std::uint64_t>(episode - 1);
    const std::unique_ptr<Learner> learner = make_learner(choice, setup, unseen);
    std::vector<EarlierTrial> walked;
    EpisodeHooks hooks;
    hooks.measure = [&](int trial, const Periods& periods) {
      const std::optional<std::size_t> point = scenario.find(periods);
      if (!point) throw std::logic_error("a learner proposed a combination outside its space");
      if (!run.first_holding_tried && scenario.points[*point].holds) {
        run.first_holding_tried = run.trials + trial;
      }
      Measurement m = measure(*point);
      walked.push_back({periods, m.windows});
      return m;
    };
    EpisodeEnd end = run_episode(*learner, hooks);
    run.episodes = episode;
    run.trials += end.trials;
    run.reason = end.reason;
    for (TrialRecord& t : end.trace) run.trace.push_back(std::move(t));
    finish(end.answer);
    if (end.reason != StopReason::below_threshold) break;
    if (run.answer_holds) {
      run.held_at = run.trials;
      break;
    }
    if (episode == protocol.episodes) {
      run.false_stop = true;
      break;
    }
    // Monitoring: the combination walks on after the trial's windows; the first later window
    // over the threshold (one is, as it does not hold) starts the next episode from it.
    const LandscapePoint& p = scenario.points[*scenario.find(end.answer.periods)];
    std::optional<body::WindowMeasure> drift;
    for (std::size_t w = static_cast<std::size_t>(protocol.hold_windows);
         w < p.windows.size() && !drift; ++w) {
      if (!body::holds(criterion.error(p.windows[w]), search.threshold_deg)) drift = p.windows[w];
    }
    if (!drift) throw std::logic_error("a combination that does not hold has no window over");
    setup.earlier.insert(setup.earlier.end(), walked.begin(), walked.end());
    setup.start = end.answer.periods;
    setup.start_windows = {*drift};
    setup.start_deviation_deg = criterion.error(*drift);
  }
  return run;
}

std::optional<double> random_expected_trials(const ScenarioLandscape& scenario) {
  const std::size_t holding = scenario.holding();
  if (holding == 0) return std::nullopt;
  // The start is not drawn again; it deviated, so it is not among the holding ones.
  const double others = static_cast<double>(scenario.points.size() - 1);
  return (others + 1.0) / (static_cast<double>(holding) + 1.0);
}

}  // namespace multicpg::learning
