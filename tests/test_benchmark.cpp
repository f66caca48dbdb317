// The replay benchmark: walked and drawn windows, seeds, its shares, the command and its figure.
#include "tests/synthetic_landscapes.h"

namespace multicpg::testing {
namespace {

// --told-nothing replays every learner told nothing beside told the failed legs: its own rows,
// the lost leg's period searched too, and the scenario replayed still withheld from the prior.
TEST_F(Dataset, TheBenchmarkReplaysEveryLearnerToldNothingBesideToldTheFailedLegs) {
  const std::string out = dir_ + "/blind";
  const CliResult r = run_cli("learner-benchmark --dataset " + stem() +
                              " --learners random,prior --seeds 4 --scenarios L2 --told-nothing"
                              " --out " +
                              out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("prior, told nothing"), std::string::npos) << r.out;
  const std::string table = read_file(out + "/benchmark.csv");
  EXPECT_EQ(count_lines(table), 1 + 4);
  EXPECT_NE(table.find("random, told nothing"), std::string::npos) << table;
  const auto summary = nlohmann::json::parse(read_file(out + "/summary.json"));
  ASSERT_EQ(summary.at("learners").size(), 4u);
  EXPECT_FALSE(summary.at("learners")[1].contains("told"));
  EXPECT_EQ(summary.at("learners")[3].at("told"), "nothing");
  EXPECT_EQ(summary.at("scenarios"), 1);

  const ScenarioLandscape& s = *data_.find({kL2});
  const LearnerChoice random = learning::resolve_learner(choice("random"));
  bool lost_leg_searched = false;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const ReplayRun blind = learning::replay_run(data_, s, random, {}, search(60), TrialProtocol{},
                                                 seed, std::nullopt, learning::Told::nothing);
    for (const learning::TrialRecord& t : blind.trace) {
      lost_leg_searched = lost_leg_searched || t.periods[kL2] != learning::kStartPeriod;
    }
  }
  EXPECT_TRUE(lost_leg_searched);
  // The prior told nothing never learns from the scenario it replays: naming it is refused.
  LearnerChoice seeing = choice("prior");
  seeing.options["scenarios"] = {"L2"};
  const LearnerChoice resolved = learning::resolve_learner(seeing);
  EXPECT_THROW(
      learning::replay_run(data_, s, resolved,
                           learning::learner_data(resolved, data_.robot, data_.criterion()),
                           search(60), TrialProtocol{}, 1, std::nullopt, learning::Told::nothing),
      BadInput);
}

// With windows walked in order a trial measures the landscape's first windows, the same at every
// visit, as the simulation does; drawn windows differ between visits and from that order.
TEST_F(Dataset, AWalkedReplayMeasuresTheLandscapesWindowsInTheirOrder) {
  const ScenarioLandscape& s = *data_.find({kL2});
  TrialProtocol walked;
  walked.window_order = learning::WindowOrder::walked;
  const auto in_order = [&](const learning::Periods& periods) {
    const LandscapePoint& p = s.points[*s.find(periods)];
    double e = 0.0;
    for (int w = 0; w < walked.hold_windows; ++w) {
      e = std::max(e,
                   learning::kPeriodsAloneCriterion.error(p.windows[static_cast<std::size_t>(w)]));
      if (!body::holds(e, learning::kDefaultThresholdDeg)) break;
    }
    return e;
  };
  int drawn_differs = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const learning::LearnerChoice random = learning::resolve_learner(choice("random"));
    const ReplayRun run = learning::replay_run(data_, s, random, {}, search(60), walked, seed);
    ASSERT_FALSE(run.trace.empty()) << seed;
    for (const learning::TrialRecord& t : run.trace) {
      EXPECT_EQ(t.deviation_deg, in_order(t.periods)) << "seed " << seed << " trial " << t.trial;
    }
    const ReplayRun drawn =
        learning::replay_run(data_, s, random, {}, search(60), TrialProtocol{}, seed);
    for (const learning::TrialRecord& t : drawn.trace) {
      drawn_differs += t.deviation_deg != in_order(t.periods) ? 1 : 0;
    }
  }
  EXPECT_GT(drawn_differs, 0) << "drawn windows must not be the walked order";
  EXPECT_EQ(learning::parse_window_order("walked"), learning::WindowOrder::walked);
  EXPECT_EQ(learning::to_string(learning::WindowOrder::drawn), "drawn");
}

// More episodes replay robust mode's monitoring: a stop on a combination that drifts over the
// threshold in a later window starts another episode from it, as a live run does, its learner
// seeded as a live run's next episode and told what the first walked (random search walks none
// of it again); the run's first episode is the one-episode replay's.
TEST_F(Dataset, MoreEpisodesReplayRobustModesMonitoring) {
  const ScenarioLandscape& s = *data_.find({kL2});
  TrialProtocol one;
  one.window_order = learning::WindowOrder::walked;
  one.hold_windows = 1;  // a yaw of 8 deg holds its first window (7.5) and drifts in the next
  TrialProtocol monitored = one;
  monitored.episodes = 10;
  const LearnerChoice random = learning::resolve_learner(choice("random"));
  int false_stops = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const ReplayRun first = learning::replay_run(data_, s, random, {}, search(60), one, seed);
    const ReplayRun run = learning::replay_run(data_, s, random, {}, search(60), monitored, seed);
    ASSERT_LE(first.trace.size(), run.trace.size()) << seed;
    for (std::size_t t = 0; t < first.trace.size(); ++t) {
      EXPECT_EQ(run.trace[t].periods, first.trace[t].periods) << "seed " << seed << " trial " << t;
    }
    if (!first.false_stop) {
      EXPECT_EQ(run.trials, first.trials) << seed;
      EXPECT_EQ(run.episodes, first.episodes) << seed;
      continue;
    }
    ++false_stops;
    EXPECT_GE(run.episodes, 2) << seed;
    EXPECT_GT(run.trials, first.trials) << seed;
    std::set<Periods> walked;
    for (const learning::TrialRecord& t : run.trace) {
      EXPECT_TRUE(walked.insert(t.periods).second) << "seed " << seed << " walks again";
    }
    if (run.held_at) {
      EXPECT_TRUE(run.answer_holds) << seed;
      EXPECT_EQ(*run.held_at, run.trials) << seed;
    }
  }
  EXPECT_GT(false_stops, 0) << "no one-episode run stopped falsely: the test shows nothing";
  // Drawn windows have no order to walk on in: refused, by the replay and by the command.
  TrialProtocol drawn = monitored;
  drawn.window_order = learning::WindowOrder::drawn;
  EXPECT_THROW(learning::replay_run(data_, s, random, {}, search(60), drawn, 1), BadInput);
  const CliResult r = run_cli("learner-benchmark --dataset " + stem() +
                              " --learners random --seeds 2 --episodes 3 --out " + dir_ + "/e");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--episodes"), std::string::npos) << r.err;
  const CliResult walked = run_cli("learner-benchmark --dataset " + stem() +
                                   " --learners random --seeds 2 --episodes 3 --window-order "
                                   "walked --out " +
                                   dir_ + "/w");
  ASSERT_EQ(walked.exit_code, 0) << walked.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir_ + "/w/summary.json")).at("episodes"), 3);
}

// With windows walked in order the run seed draws nothing, so a learner seed given as a live run
// gives it (learn --seed) decides the replay alone, as it decides that live run.
TEST_F(Dataset, AWalkedReplayWithALearnerSeedIsThatSeedsRun) {
  const ScenarioLandscape& s = *data_.find({kL2});
  TrialProtocol walked;
  walked.window_order = learning::WindowOrder::walked;
  const learning::LearnerChoice random = learning::resolve_learner(choice("random"));
  const auto periods = [&](std::uint64_t run_seed, std::uint64_t learner_seed) {
    std::vector<Periods> out;
    for (const learning::TrialRecord& t :
         learning::replay_run(data_, s, random, {}, search(60), walked, run_seed, learner_seed)
             .trace) {
      out.push_back(t.periods);
    }
    return out;
  };
  const std::vector<Periods> seven = periods(1, 7);
  ASSERT_GT(seven.size(), 1u);
  EXPECT_EQ(periods(2, 7), seven);
  EXPECT_NE(periods(1, 8), seven);
}

TEST(Learners, AShareOfNoneOrAllLiesInsideItsInterval) {
  // Every run held (or none): the interval's bound is the share itself, not a rounding below it.
  for (int n = 1; n <= 5000; ++n) {
    const auto [low_all, high_all] = experiments::wilson_interval(n, n);
    EXPECT_EQ(high_all, 1.0) << n;
    EXPECT_LT(low_all, 1.0) << n;
    const auto [low_none, high_none] = experiments::wilson_interval(0, n);
    EXPECT_EQ(low_none, 0.0) << n;
    EXPECT_GT(high_none, 0.0) << n;
  }
  const auto [low, high] = experiments::wilson_interval(50, 100);
  EXPECT_NEAR(low, 0.4038, 1e-4);  // Wilson 1927, z = 1.96
  EXPECT_NEAR(high, 0.5962, 1e-4);
}

TEST_F(Dataset, TheBenchmarkCommandScoresLearnersTheSameOnAnyThreadCount) {
  const std::string common = "learner-benchmark --dataset " + stem() +
                             " --learners random,greedy,bayes --seeds 12 --scenarios L2,R1+R2";
  const CliResult one = run_cli(common + " --jobs 1 --out " + dir_ + "/one");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const CliResult two = run_cli(common + " --jobs 2 --out " + dir_ + "/two");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  for (const char* name : {"benchmark.csv", "runs.csv"}) {
    const std::string a = read_file(dir_ + "/one/" + name);
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, read_file(dir_ + "/two/" + name)) << name;
  }
  // One row per scenario and learner, 12 runs each.
  const std::string table = read_file(dir_ + "/one/benchmark.csv");
  EXPECT_EQ(count_lines(table), 1 + 2 * 3);
  EXPECT_EQ(count_lines(read_file(dir_ + "/one/runs.csv")), 1 + 2 * 3 * 12);
  EXPECT_GT(fs::file_size(dir_ + "/one/benchmark-figure.png"), 1000u);
  EXPECT_GT(fs::file_size(dir_ + "/one/benchmark-figure.svg"), 1000u);
  const auto summary = nlohmann::json::parse(read_file(dir_ + "/one/summary.json"));
  EXPECT_EQ(summary.at("seeds"), 12);
  EXPECT_EQ(summary.at("window_order"), "drawn");
  EXPECT_EQ(summary.at("live_seeds"), false);

  for (const auto& [args, mention] : std::vector<std::pair<std::string, std::string>>{
           {"--learners simplex", "unknown learner 'simplex'"},
           {"--learners random --scenarios R1+R2+L1+L2", "R1+R2+L1+L2"},
           {"--learners random --seeds 0", "--seeds"},
           {"--learners random --budget -1", "--budget"},
           {"--learners random --window-order sorted", "window order 'sorted'"},
       }) {
    const CliResult bad =
        run_cli("learner-benchmark --dataset " + stem() + " " + args + " --out " + dir_ + "/bad");
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find(mention), std::string::npos) << bad.err;
  }
  const CliResult none = run_cli("learner-benchmark --dataset " + dir_ +
                                 "/nothing-here --learners random --out " + dir_ + "/bad");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ + "/bad/benchmark.csv"));
}

// Every selection of the dataset's scenarios gets its figure, or none and the reason: the
// figure pools the scenarios where a combination holds (R1+R2 has none). Small and odd benchmarks
// too: one seed, a budget and cap of one trial, one learner that never holds.
TEST_F(Dataset, TheBenchmarkFigureIsDrawnOrLeftOutSayingWhyForEverySelection) {
  const std::vector<std::string> holding{"R1", "R2", "L1", "L2"};
  std::vector<std::string> selections{"R1+R2", "R1,R2,L1,L2,R1+R2"};
  for (const std::string& s : holding) {
    selections.push_back(s);
    selections.push_back(s + ",R1+R2");
  }
  int n = 0;
  for (const std::string& scenarios : selections) {
    for (const std::string args :
         {"--learners random --seeds 3", "--seeds 1 --budget 1 --max-trials 1",
          "--learners annealing --seeds 1 --max-trials 1", "--learners prior,greedy --seeds 2"}) {
      SCOPED_TRACE(scenarios + " " + args);
      const std::string out = dir_ + "/sel" + std::to_string(n++);
      const CliResult r = run_cli("learner-benchmark --dataset " + stem() + " --scenarios " +
                                  scenarios + " " + args + " --out " + out);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(r.err, "");
      const bool holds = scenarios != "R1+R2";
      EXPECT_EQ(is_png(out + "/benchmark-figure.png"), holds);
      EXPECT_EQ(fs::exists(out + "/benchmark-figure.svg"), holds);
      EXPECT_EQ(r.out.find("no figure: nothing pooled") != std::string::npos, !holds) << r.out;
      if (!holds) {
        EXPECT_NE(r.out.find("none of the 1 scenario has a combination that holds"),
                  std::string::npos)
            << r.out;
      }
      const std::string md = read_file(out + "/benchmark.md");
      EXPECT_EQ(md.rfind("# Learner benchmark: quadruped, ", 0), 0u) << md;
      EXPECT_EQ(md.find("| scenario | learner | combinations | holding | runs | held within "),
                md.find("| scenario"))
          << md;
      EXPECT_EQ(md.find("| pooled (") != std::string::npos, holds) << md;
      EXPECT_EQ(md.find(" - "), std::string::npos) << md;
    }
  }
  // The committed hexapod dataset's R1+R2, where no combination holds.
  const CliResult r = run_cli(
      "learner-benchmark --steering off --scenarios R1+R2 --learners random --seeds 3 --out " +
      dir_ + "/hexapod");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("no figure: nothing pooled"), std::string::npos) << r.out;
}

// The terminal and benchmark.md say what the bracketed numbers are; the pooled row holds the
// summary's numbers.
TEST_F(Dataset, TheBenchmarkLabelsItsIntervalAndPoolsItsScenarios) {
  const CliResult r = run_cli("learner-benchmark --dataset " + stem() +
                              " --learners random --seeds 4 --out " + dir_ + "/b");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // It names the dataset it replayed and how that was walked.
  EXPECT_NE(r.out.find("5 scenarios x 4 seeds of " + stem() + " (walked with periods alone)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("pooled over the 4 scenarios where a combination holds"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("% (95% interval "), std::string::npos) << r.out;
  const std::string md = read_file(dir_ + "/b/benchmark.md");
  EXPECT_NE(md.find("| share held | 95 % interval | trials to held: median (quartiles) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| pooled (4 scenarios) | random |  |  | 16 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| R1+R2 | random | "), std::string::npos) << md;
  EXPECT_NE(md.find("| none holds | none holds |"), std::string::npos) << md;
  const auto summary = nlohmann::json::parse(read_file(dir_ + "/b/summary.json"));
  EXPECT_EQ(summary.at("holding_scenarios"), 4);
}

}  // namespace
}  // namespace multicpg::testing
