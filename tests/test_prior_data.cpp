// What the prior learns from (docs/learning.md "Learners", "A learner's data"): never the
// scenario under test nor its mirror image, losses of another number of legs weighed as asked,
// its scales from the data without the scenario under test, and each combination's chance of
// holding on after its trial.
#include "tests/synthetic_landscapes.h"

namespace multicpg::testing {
namespace {

TEST_F(Dataset, APriorNeverSeesTheScenarioUnderTestNorItsMirrorImage) {
  for (const char* seen : {"L2", "R2"}) {
    LearnerChoice c = choice("prior");
    c.options["scenarios"] = {"R1", seen};
    EXPECT_THROW(
        learning::check_learner(learning::resolve_learner(c), robot::RobotKind::quadruped,
                                learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion),
        BadInput)
        << seen;
  }
  LearnerChoice fine = choice("prior");
  fine.options["scenarios"] = {"R1", "L1"};
  EXPECT_NO_THROW(
      learning::check_learner(learning::resolve_learner(fine), robot::RobotKind::quadruped,
                              learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion));
  // The run's period set is the dataset's, checked with the rest before anything walks.
  try {
    learning::check_learner(learning::resolve_learner(fine), robot::RobotKind::quadruped,
                            learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion,
                            {4, 5, 6, 8});
    ADD_FAILURE() << "a prior of another period set was accepted";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("has the period set 4,5,6,8,9, this run 4,5,6,8"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(learning::check_learner(
      learning::resolve_learner(fine), robot::RobotKind::quadruped,
      learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion, kPeriodSet));
  LearnerChoice missing = choice("prior");
  missing.options["dataset"] = dir_ + "/nothing-here";
  EXPECT_THROW(
      learning::check_learner(learning::resolve_learner(missing), robot::RobotKind::quadruped,
                              learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion),
      BadInput);
}

// The windows of losses of another number of legs count as much as the prior is told
// (docs/learning.md "The quadruped: a small dataset"): weighed 0, nothing, exactly as naming only
// the losses of as many legs; by default as much as any.
TEST_F(Dataset, APriorWeighsLossesOfAnotherNumberOfLegsAsAsked) {
  LearnerChoice alone = choice("prior");
  alone.options["other_size_weight"] = 0.0;
  LearnerChoice named = choice("prior");
  named.options["scenarios"] = {"R1", "L1"};  // L2 told: R2, its mirror image, is never seen
  const ReplayRun a = replay(data_, {kL2}, alone, 7);
  const ReplayRun b = replay(data_, {kL2}, named, 7);
  ASSERT_FALSE(a.trace.empty());
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    EXPECT_EQ(a.trace[i].periods, b.trace[i].periods) << i;
    // Each trial says what the other losses counted for: 0, and 1 (the default) beside a list
    // that has none.
    nlohmann::json details = a.trace[i].details;
    EXPECT_EQ(details.at(learning::kOtherSizeWeightKey), 0.0);
    EXPECT_EQ(b.trace[i].details.at(learning::kOtherSizeWeightKey), 1.0);
    details[learning::kOtherSizeWeightKey] = 1.0;
    EXPECT_EQ(details, b.trace[i].details) << i;
  }
  // R1+R2 (nothing holds there) is in the default prior's mean, so it forecasts otherwise.
  const ReplayRun every = replay(data_, {kL2}, choice("prior"), 7);
  EXPECT_NE(every.trace.front().details, a.trace.front().details);
  LearnerChoice negative = choice("prior");
  negative.options["other_size_weight"] = -1.0;
  EXPECT_THROW(learning::resolve_learner(negative), OptionError);
  // R1+R2 is the only loss of two legs: at 0 nothing is left to learn from, refused before a run.
  for (const nlohmann::json& zero : {nlohmann::json{{"other_size_weight", 0.0}},
                                     nlohmann::json{{"other_size_weights", {1.0, 0.0}}}}) {
    LearnerChoice c = choice("prior");
    c.options.update(zero);
    EXPECT_THROW(learning::check_learner(learning::resolve_learner(c), robot::RobotKind::quadruped,
                                         learning::ToldFault::legs({0, 1}),
                                         learning::kPeriodsAloneCriterion),
                 BadInput)
        << zero;
  }
  // Told nothing, it knows no number of lost legs to weigh the others against: the weight
  // changes nothing.
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.criterion = learning::kPeriodsAloneCriterion;
  setup.search = search(60);
  const auto first = [&](const LearnerChoice& c) {
    const LearnerChoice resolved = learning::resolve_learner(c);
    return learning::make_learner(resolved, setup,
                                  learning::learner_data(resolved, setup.robot, setup.criterion))
        ->best_forecasts(5);
  };
  const std::vector<learning::Forecast> plain = first(choice("prior"));
  const std::vector<learning::Forecast> zero = first(alone);
  ASSERT_EQ(plain.size(), zero.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].periods, zero[i].periods) << i;
    EXPECT_EQ(plain[i].hold, zero[i].hold) << i;
  }
}

// Several weights (docs/learning.md "Averaged by their evidence"): a prior for each, averaged
// by how likely each found the windows seen. Where the losses of another number of legs mislead,
// the trials turn to the prior without them, and the other way round; priors alike average to
// the one.
TEST_F(Dataset, APriorOfSeveralWeightsTrustsTheOneTheWindowsBearOut) {
  LearnerChoice both = choice("prior");
  both.options["other_size_weights"] = {1.0, 0.0};
  const nlohmann::json resolved = learning::resolve_learner(both).options;
  EXPECT_FALSE(resolved.contains("other_size_weight")) << resolved;
  EXPECT_EQ(resolved.at("other_size_weights"), nlohmann::json({1.0, 0.0}));
  EXPECT_FALSE(learning::resolve_learner(choice("prior")).options.contains("other_size_weights"));
  // L2 told, R2 never seen: R1+R2 (nothing holds there, every window at about 100 deg) misleads
  // the prior that counts it.
  const ReplayRun misled = replay(data_, {kL2}, both, 7);
  ASSERT_FALSE(misled.trace.empty());
  for (const learning::TrialRecord& t : misled.trace) {
    EXPECT_LT(t.details.at(learning::kOtherSizeWeightKey).get<double>(), 0.5) << t.trial;
  }
  // R1+R2 walking as every one-leg loss does, and R1 and L1 (the one-leg losses it may see)
  // turned by 30 deg: now the losses of as many legs mislead.
  LandscapeDataset turned = data_;
  for (ScenarioLandscape& s : turned.scenarios) {
    if (s.failed == std::vector<std::size_t>{0, 1}) s = synthetic_scenario({0, 1}, false);
    if (s.failed.size() != 1 || s.failed.front() == kL2 || s.failed.front() == kR2) continue;
    for (learning::LandscapePoint& p : s.points) {
      p.worst_deg = 0.0;
      for (body::WindowMeasure& w : p.windows) {
        w.yaw_deg += 30.0;
        p.worst_deg = std::max(p.worst_deg, turned.criterion().error(w));
      }
      p.holds = p.worst_deg < learning::kDefaultThresholdDeg;
    }
  }
  learning::write_landscape_dataset(turned, fs::path(dir_) / "turned");
  both.options["dataset"] = dir_ + "/turned";
  const ReplayRun other = replay(data_, {kL2}, both, 7);
  ASSERT_FALSE(other.trace.empty());
  for (const learning::TrialRecord& t : other.trace) {
    EXPECT_GT(t.details.at(learning::kOtherSizeWeightKey).get<double>(), 0.5) << t.trial;
  }
  // Two priors alike: the one prior's choices and chances.
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.told = learning::ToldFault::legs({kL2});
  setup.criterion = data_.criterion();
  setup.search = search(10);
  const learning::ModelLearnerParams params = learning::model_learner_params({});
  learning::ModelLearner one(setup, params);
  learning::ModelLearner two(setup, params,
                             {{params.model, {}, {}, {}}, {params.model, {}, {}, {}}});
  const ScenarioLandscape& truth = *data_.find({kL2});
  while (true) {
    const std::optional<Periods> a = one.propose();
    ASSERT_EQ(a, two.propose());
    if (!a) break;
    learning::Measurement m;
    m.windows = truth.points[*truth.find(*a)].windows;
    for (const body::WindowMeasure& w : m.windows) {
      m.deviation_deg = std::max(m.deviation_deg, setup.criterion.error(w));
    }
    const learning::TrialRecord ta = one.observe(m);
    const learning::TrialRecord tb = two.observe(m);
    EXPECT_EQ(ta.details.at(learning::kPredictedHoldKey),
              tb.details.at(learning::kPredictedHoldKey));
    EXPECT_NEAR(ta.details.at(learning::kPredictedYawSdKey).get<double>(),
                tb.details.at(learning::kPredictedYawSdKey).get<double>(), 1e-9);
    if (one.stop() != StopReason::running) break;
  }
  EXPECT_EQ(one.answer().periods, two.answer().periods);
  // Bad lists: one weight (that is other_size_weight), a weight twice, one out of range, one not
  // a number; both keys.
  for (const nlohmann::json& bad :
       {nlohmann::json({0.5}), nlohmann::json({1.0, 1.0}), nlohmann::json({1.0, -1.0}),
        nlohmann::json::array({1.0, "a"})}) {
    LearnerChoice c = choice("prior");
    c.options["other_size_weights"] = bad;
    EXPECT_THROW(learning::resolve_learner(c), OptionError) << bad;
  }
  LearnerChoice twice = choice("prior");
  twice.options["other_size_weights"] = {1.0, 0.1};
  twice.options["other_size_weight"] = 1.0;
  EXPECT_THROW(learning::resolve_learner(twice), OptionError);
}

// With scales = "data" the prior's GP scales come from what its regression misses on the
// scenarios it learns from (docs/learning.md "The prior's scales from its data"): never from the
// scenario under test nor its mirror image, but from every other one where a combination holds.
TEST_F(Dataset, APriorsScalesFromTheDataNeverSeeTheScenarioUnderTest) {
  const auto altered = [&](const std::vector<std::size_t>& legs, const std::string& name) {
    LandscapeDataset d = data_;
    for (ScenarioLandscape& s : d.scenarios) {
      if (s.failed != legs) continue;
      // Each window's yaw moved by -6, 0, +6 degrees: the combination's mean stays, its spread
      // grows. Its worst error and whether it holds follow.
      for (learning::LandscapePoint& p : s.points) {
        p.worst_deg = 0.0;
        for (std::size_t i = 0; i < p.windows.size(); ++i) {
          body::WindowMeasure& w = p.windows[i];
          w.yaw_deg +=
              6.0 * (static_cast<double>(i) - static_cast<double>(p.windows.size() - 1) / 2);
          p.worst_deg = std::max({p.worst_deg, std::abs(w.yaw_deg), std::abs(w.path_deg)});
        }
        p.holds = p.worst_deg < learning::kDefaultThresholdDeg;
      }
    }
    learning::write_landscape_dataset(d, fs::path(dir_) / name);
    LearnerChoice c = choice("prior");
    c.options["dataset"] = dir_ + "/" + name;
    c.options["scales"] = "data";
    return c;
  };
  LearnerChoice from_data = choice("prior");
  from_data.options["scales"] = "data";
  const ReplayRun a = replay(data_, {kL2}, from_data, 7);
  ASSERT_FALSE(a.trace.empty());
  // L2 is under test, R2 its mirror image: changing their windows changes nothing.
  for (const std::size_t leg : {kL2, kR2}) {
    const ReplayRun b = replay(data_, {kL2}, altered({leg}, "unseen" + std::to_string(leg)), 7);
    ASSERT_EQ(a.trace.size(), b.trace.size()) << leg;
    for (std::size_t i = 0; i < a.trace.size(); ++i) {
      EXPECT_EQ(a.trace[i].periods, b.trace[i].periods) << leg << " " << i;
      EXPECT_EQ(a.trace[i].details, b.trace[i].details) << leg << " " << i;
    }
  }
  // The same spread in a scenario it learns from (R1, the scenario's mean unchanged) widens the
  // window noise it takes from the data, and with it the forecast's band.
  const ReplayRun seen = replay(data_, {kL2}, altered({0}, "seen"), 7);
  ASSERT_FALSE(seen.trace.empty());
  EXPECT_GT(seen.trace.front().details["predicted_e_high_deg"].get<double>() -
                seen.trace.front().details["predicted_e_low_deg"].get<double>(),
            a.trace.front().details["predicted_e_high_deg"].get<double>() -
                a.trace.front().details["predicted_e_low_deg"].get<double>());
  // A scenario where no combination holds (R1+R2) is not one a learner can win: its misses and
  // spread are left out of the scales, so a wider spread there changes nothing.
  const ReplayRun hopeless = replay(data_, {kL2}, altered({0, 1}, "hopeless"), 7);
  ASSERT_EQ(hopeless.trace.size(), a.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    EXPECT_EQ(hopeless.trace[i].details, a.trace[i].details) << i;
  }
  // The options' scales are not the data's, which are the default.
  LearnerChoice given = choice("prior");
  given.options["scales"] = "options";
  EXPECT_NE(replay(data_, {kL2}, given, 7).trace.front().details, a.trace.front().details);
  const ReplayRun by_default = replay(data_, {kL2}, choice("prior"), 7);
  ASSERT_EQ(by_default.trace.size(), a.trace.size());
  EXPECT_EQ(by_default.trace.front().details, a.trace.front().details);
  // Written either way: a record without the key ran before the data's scales were the default.
  EXPECT_EQ(learning::resolve_learner(choice("prior")).options.at("scales"), "data");
  EXPECT_EQ(learning::resolve_learner(given).options.at("scales"), "options");
  LearnerChoice unknown = choice("prior");
  unknown.options["scales"] = "both";
  EXPECT_THROW(learning::resolve_learner(unknown), OptionError);
  // A given scale is used only with scales=options: with the data's it is refused, not ignored,
  // and the record does not list the scales the model did not use.
  EXPECT_FALSE(learning::resolve_learner(choice("prior")).options.contains("noise_deg"));
  EXPECT_EQ(learning::resolve_learner(given).options.at("noise_deg"), 3.0);
  LearnerChoice ignored = choice("prior");
  ignored.options["noise_deg"] = 5.0;
  EXPECT_THROW(learning::resolve_learner(ignored), OptionError);
  ignored.options["scales"] = "options";
  EXPECT_EQ(learning::resolve_learner(ignored).options.at("noise_deg"), 5.0);
  const LearnerChoice resolved = learning::resolve_learner(choice("prior"));
  EXPECT_EQ(learning::resolve_learner(resolved), resolved);
}

// The prior weighs each combination by the chance, from its data, that it holds on once its trial
// has held (docs/learning.md "Holding on after the trial"): learned from the scenarios it may see,
// never from the scenario under test nor its mirror image; every chance 1 with keeps=false.
TEST_F(Dataset, APriorWeighsACombinationByItsDatasChanceOfHoldingOn) {
  // Trials of one window: the dataset's later two are what a combination walks on after its trial.
  learning::Criterion judge = data_.criterion();
  judge.trial_windows = 1;
  // The dataset with the scenarios `straight` walking straight in every combination, then, in each
  // scenario of `lost` legs, every combination whose trial holds while `leg` is not at period 9
  // drifting after it (yaw 20 deg in its later windows).
  using Drift = std::pair<std::vector<std::size_t>, std::size_t>;
  const auto dataset = [&](const std::vector<std::vector<std::size_t>>& straight,
                           const std::vector<Drift>& drifts, const std::string& name) {
    LandscapeDataset d = data_;
    for (ScenarioLandscape& s : d.scenarios) {
      if (std::find(straight.begin(), straight.end(), s.failed) != straight.end()) {
        for (learning::LandscapePoint& p : s.points) {
          for (body::WindowMeasure& w : p.windows) w.yaw_deg = w.path_deg = 0.0;
          p.worst_deg = 0.0;
          p.holds = true;
        }
      }
      for (const auto& [lost, leg] : drifts) {
        if (s.failed != lost) continue;
        for (learning::LandscapePoint& p : s.points) {
          if (p.periods[leg] == 9 ||
              !body::holds(judge.error(p.windows.front()), learning::kDefaultThresholdDeg)) {
            continue;
          }
          for (std::size_t i = 1; i < p.windows.size(); ++i) p.windows[i].yaw_deg = 20.0;
          p.worst_deg = std::max(p.worst_deg, 20.0);
          p.holds = false;
        }
      }
    }
    learning::write_landscape_dataset(d, fs::path(dir_) / name);
    LearnerChoice c = choice("prior");
    c.options["dataset"] = dir_ + "/" + name;
    return c;
  };
  // Told L2, before any trial: every combination's forecast (the model's whole map).
  const auto map = [&](const LearnerChoice& c) {
    learning::LearnerSetup setup;
    setup.robot = robot::RobotKind::quadruped;
    setup.start.assign(4, learning::kStartPeriod);
    setup.told = learning::ToldFault::legs({kL2});
    setup.criterion = judge;
    const ScenarioLandscape& truth = *data_.find({kL2});
    setup.start_windows = {truth.points[*truth.find(setup.start)].windows.front()};
    setup.search = search(60);
    const LearnerChoice resolved = learning::resolve_learner(c);
    const auto learner = learning::make_learner(
        resolved, setup, learning::learner_data(resolved, setup.robot, judge));
    return learner->best_forecasts(truth.points.size());
  };
  const auto mean_keep = [](const std::vector<learning::Forecast>& m, bool r2_at_9) {
    double sum = 0.0;
    double n = 0.0;
    for (const learning::Forecast& f : m) {
      if ((f.periods[kR2] == 9) != r2_at_9) continue;
      sum += f.keep;
      n += 1.0;
    }
    return sum / n;
  };
  // R1 and its mirror image L1 walking straight: every combination holds on.
  const std::vector<learning::Forecast> straight = map(dataset({{0}, {2}}, {}, "straight"));
  ASSERT_EQ(straight.size(), 125u);
  EXPECT_GT(mean_keep(straight, true), 0.9);
  EXPECT_GT(mean_keep(straight, false), 0.9);
  // The same, but drifting after the trial wherever R2 (in L1's, the mirror image: L2) is not at
  // 9: R2 at 9 is the better bet.
  const std::vector<learning::Forecast> seen =
      map(dataset({{0}, {2}}, {{{0}, kR2}, {{2}, kL2}}, "drift-seen"));
  EXPECT_GT(mean_keep(seen, true), mean_keep(seen, false) + 0.3);
  // L2 is under test, R2 its mirror image: whatever they do changes nothing.
  const std::vector<learning::Forecast> plain = map(choice("prior"));
  const std::vector<learning::Forecast> unseen =
      map(dataset({{kL2}, {kR2}}, {{{kL2}, kR2}, {{kR2}, kL2}}, "drift-unseen"));
  ASSERT_EQ(unseen.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(unseen[i].periods, plain[i].periods) << i;
    EXPECT_EQ(unseen[i].keep, plain[i].keep) << i;
    EXPECT_EQ(unseen[i].hold, plain[i].hold) << i;
  }
  // keeps=false: a combination whose trial holds is taken to hold on.
  LearnerChoice off = dataset({{0}, {2}}, {{{0}, kR2}, {{2}, kL2}}, "drift-off");
  off.options["keeps"] = false;
  for (const learning::Forecast& f : map(off)) EXPECT_EQ(f.keep, 1.0);
  EXPECT_EQ(learning::resolve_learner(choice("prior")).options.at("keeps"), true);
  LearnerChoice wrong = choice("prior");
  wrong.options["keeps"] = "yes";
  EXPECT_THROW(learning::resolve_learner(wrong), OptionError);
}

}  // namespace
}  // namespace multicpg::testing
