// Ask/tell (learning/ask_tell.h): a learner driven from outside retraces the replay a run of
// the same learner walks, one episode and ten.
#include "tests/synthetic_landscapes.h"

namespace multicpg::testing {
namespace {

// Ask/tell (learning/ask_tell.h) walking the windows a replay walks, in the order walked, gives
// the replay's trials for every learner: the same learner made the same way, E judged from the
// windows by the run's criterion.
TEST_F(Dataset, AskTellRetracesAReplayForEveryLearner) {
  const ScenarioLandscape& s = *data_.find({kL2});
  TrialProtocol walked;
  walked.window_order = learning::WindowOrder::walked;
  const Periods start(4, learning::kStartPeriod);
  const auto windows_of = [&](const Periods& periods) {
    const LandscapePoint& p = s.points[*s.find(periods)];
    std::vector<body::WindowMeasure> out;
    for (int w = 0; w < walked.hold_windows; ++w) {
      out.push_back(p.windows.at(static_cast<std::size_t>(w)));
      if (!body::holds(data_.criterion().error(out), learning::kDefaultThresholdDeg)) break;
    }
    return out;
  };
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    const std::string name(info.name);
    const LearnerChoice resolved = learning::resolve_learner(choice(name));
    constexpr std::uint64_t kSeed = 11;
    const ReplayRun replayed = learning::replay_run(
        data_, s, resolved, learning::learner_data(resolved, data_.robot, data_.criterion()),
        search(30), walked, 1, kSeed);
    ASSERT_TRUE(replayed.deviated) << name;
    learning::AskTellSetup setup;
    setup.learner = choice(name);
    setup.robot = data_.robot;
    setup.told = learning::ToldFault::legs({kL2});
    setup.search = search(30);
    setup.criterion = data_.criterion();
    setup.start_windows = {s.points[*s.find(start)].windows.front()};
    setup.seed = kSeed;
    learning::AskTell learner(setup);
    std::vector<learning::TrialRecord> trace;
    while (const std::optional<Periods> p = learner.ask())
      trace.push_back(learner.tell(windows_of(*p)));
    ASSERT_EQ(trace.size(), replayed.trace.size()) << name;
    ASSERT_FALSE(trace.empty()) << name;
    for (std::size_t i = 0; i < trace.size(); ++i) {
      EXPECT_EQ(trace[i].trial, replayed.trace[i].trial) << name;
      EXPECT_EQ(trace[i].periods, replayed.trace[i].periods) << name << " trial " << i + 1;
      EXPECT_EQ(trace[i].deviation_deg, replayed.trace[i].deviation_deg) << name;
      EXPECT_EQ(trace[i].accepted, replayed.trace[i].accepted) << name;
      EXPECT_EQ(trace[i].details, replayed.trace[i].details) << name;
    }
    EXPECT_EQ(learner.reason(), replayed.reason) << name;
    EXPECT_EQ(learner.answer().periods, replayed.answer) << name;
    EXPECT_TRUE(learner.done()) << name;
    EXPECT_THROW(learner.tell(1.0), std::logic_error) << name;
  }
  // C0 needs what it measured: its windows or its E.
  learning::AskTellSetup bare;
  EXPECT_THROW(learning::AskTell{bare}, OptionError);
}

// Ask/tell over episodes: the loop walks a stop on a combination on in its later windows, and the
// first over the threshold starts the next episode (next_episode), as robust mode's monitoring
// and the replay with more episodes do; every learner retraces the replay's trials across them.
TEST_F(Dataset, AskTellRetracesAReplayOverEpisodesForEveryLearner) {
  const ScenarioLandscape& s = *data_.find({kL2});
  TrialProtocol monitored;
  monitored.window_order = learning::WindowOrder::walked;
  monitored.hold_windows = 1;  // some combinations hold their first window and drift later
  monitored.episodes = 10;
  // The replay's judge, its trials of one window (as a run of --hold-windows 1 judges them).
  const learning::Criterion judge = learning::replay_criterion(data_, monitored);
  const auto over = [&](const body::WindowMeasure& w) {
    return !body::holds(judge.error(w), learning::kDefaultThresholdDeg);
  };
  const Periods start(4, learning::kStartPeriod);
  int later_episodes = 0;
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    const std::string name(info.name);
    const LearnerChoice resolved = learning::resolve_learner(choice(name));
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const ReplayRun replayed = learning::replay_run(
          data_, s, resolved, learning::learner_data(resolved, data_.robot, judge), search(60),
          monitored, 1, seed);
      learning::AskTellSetup setup;
      setup.learner = choice(name);
      setup.robot = data_.robot;
      setup.told = learning::ToldFault::legs({kL2});
      setup.search = search(60);
      setup.criterion = judge;
      setup.start_windows = {s.points[*s.find(start)].windows.front()};
      setup.seed = seed;
      learning::AskTell learner(setup);
      std::vector<learning::TrialRecord> trace;
      for (;;) {
        while (const std::optional<Periods> p = learner.ask()) {
          const LandscapePoint& point = s.points[*s.find(*p)];
          trace.push_back(learner.tell(std::vector{point.windows.front()}));
        }
        const LandscapePoint& stop = s.points[*s.find(learner.answer().periods)];
        if (learner.reason() != StopReason::below_threshold || stop.holds ||
            learner.episode() == monitored.episodes) {
          break;
        }
        const auto drift = std::find_if(stop.windows.begin() + 1, stop.windows.end(), over);
        ASSERT_NE(drift, stop.windows.end()) << name;
        learner.next_episode(stop.periods, std::vector{*drift});
      }
      ASSERT_EQ(learner.episode(), replayed.episodes) << name << " seed " << seed;
      later_episodes += learner.episode() - 1;
      ASSERT_EQ(trace.size(), replayed.trace.size()) << name << " seed " << seed;
      for (std::size_t i = 0; i < trace.size(); ++i) {
        EXPECT_EQ(trace[i].trial, replayed.trace[i].trial) << name;
        EXPECT_EQ(trace[i].periods, replayed.trace[i].periods) << name << " trial " << i + 1;
        EXPECT_EQ(trace[i].details, replayed.trace[i].details) << name;
      }
      EXPECT_EQ(learner.answer().periods, replayed.answer) << name;
    }
  }
  EXPECT_GT(later_episodes, 0) << "no run needed a second episode: the test shows nothing";
  // Between ask and tell no episode starts.
  learning::AskTellSetup setup;
  setup.learner = choice("random");
  setup.robot = data_.robot;
  setup.told = learning::ToldFault::legs({kL2});
  setup.search = search(60);
  setup.start_deviation_deg = 20.0;
  learning::AskTell learner(setup);
  ASSERT_TRUE(learner.ask());
  EXPECT_THROW(learner.next_episode(start, 20.0), std::logic_error);
}

}  // namespace
}  // namespace multicpg::testing
