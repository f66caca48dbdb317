// The learners: the table, what every learner keeps, memory, the models, what a learner is told,
// the forecasts, and learners from the CLI and experiment files (ask/tell:
// tests/test_ask_tell.cpp; what the prior learns from: tests/test_prior_data.cpp).
#include "tests/synthetic_landscapes.h"

namespace multicpg::testing {
namespace {

TEST(Learners, TheTableNamesEveryLearnerAndRefusesUnknownOnes) {
  std::vector<std::string> names;
  for (const learning::LearnerInfo& l : learning::learner_list()) names.emplace_back(l.name);
  EXPECT_EQ(names, (std::vector<std::string>{"annealing", "random", "greedy", "bayes", "prior"}));
  try {
    learning::resolve_learner({"simplex", nlohmann::json::object()});
    FAIL() << "an unknown learner was accepted";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "name");
    EXPECT_NE(std::string(e.what()).find("annealing, random, greedy, bayes or prior"),
              std::string::npos);
  }
  EXPECT_THROW(learning::resolve_learner({"bayes", {{"kappa_typo", 1.0}}}), OptionError);
  EXPECT_THROW(learning::resolve_learner({"bayes", {{"kappa", "high"}}}), OptionError);
  EXPECT_THROW(learning::resolve_learner({"bayes", {{"noise_deg", -1.0}}}), OptionError);
  // Resolving fills every default in, so a run records every option that decides its result.
  const LearnerChoice bayes = learning::resolve_learner({"bayes", nlohmann::json::object()});
  EXPECT_TRUE(bayes.options.contains("kappa"));
  EXPECT_TRUE(bayes.options.contains("acquisition"));
  EXPECT_EQ(learning::resolve_learner(bayes), bayes);
}

TEST_F(Dataset, EveryLearnerKeepsTheFailedLegsAndTheSetAndRepeatsItself) {
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    SCOPED_TRACE(std::string(info.name));
    const LearnerChoice c = choice(std::string(info.name));
    const ReplayRun a = replay(data_, {kL2}, c, 7);
    ASSERT_TRUE(a.deviated);
    ASSERT_GT(a.trials, 0);
    for (const learning::TrialRecord& t : a.trace) {
      EXPECT_EQ(t.periods[kL2], learning::kStartPeriod);
      for (int p : t.periods) EXPECT_NE(period_index(p), static_cast<int>(kPeriodSet.size()));
      // Its details are the ones it declares, so trace tables have fixed columns.
      const std::vector<std::string> declared = learning::detail_columns(info.name, {});
      for (const auto& [key, value] : t.details.items()) {
        EXPECT_NE(std::find(declared.begin(), declared.end(), key), declared.end()) << key;
      }
    }
    // Same seed, same run, to the last detail.
    const ReplayRun b = replay(data_, {kL2}, c, 7);
    ASSERT_EQ(a.trace.size(), b.trace.size());
    for (std::size_t i = 0; i < a.trace.size(); ++i) {
      EXPECT_EQ(a.trace[i].periods, b.trace[i].periods);
      EXPECT_EQ(a.trace[i].deviation_deg, b.trace[i].deviation_deg);
      EXPECT_EQ(a.trace[i].details, b.trace[i].details);
    }
    EXPECT_EQ(a.answer, b.answer);
  }
}

TEST_F(Dataset, EveryLearnerTriesEachCombinationOnceWhenNoneHolds) {
  // R1+R2 lost: 25 combinations of L1 and L2, none holding; the start (4, 4) is walked already.
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    SCOPED_TRACE(std::string(info.name));
    const ReplayRun r = replay(data_, {0, 1}, choice(std::string(info.name)), 3, 100);
    EXPECT_EQ(r.reason, StopReason::space_exhausted);
    EXPECT_EQ(r.trials, 24);
    std::set<Periods> tried;
    for (const learning::TrialRecord& t : r.trace) tried.insert(t.periods);
    EXPECT_EQ(tried.size(), 24u);
    EXPECT_EQ(tried.count(Periods{4, 4, 4, 4}), 0u);
    EXPECT_FALSE(r.answer_holds);
    // The trial cap ends it first when it is lower (paper Table 2).
    const ReplayRun capped = replay(data_, {0, 1}, choice(std::string(info.name)), 3, 10);
    EXPECT_EQ(capped.reason, StopReason::trial_cap);
    EXPECT_EQ(capped.trials, 10);
  }
}

// What a run's earlier episodes walked (LearnerSetup::earlier) no learner walks again, and the
// models are told its windows (docs/learning.md "Memory across episodes").
TEST_F(Dataset, NoLearnerWalksAnEarlierEpisodesCombinationsAgain) {
  // R1+R2 lost: 25 combinations of L1 and L2, none holding; the start (4, 4) is walked already.
  const ScenarioLandscape& s = *data_.find({0, 1});
  const auto windows = [&](const Periods& p) { return s.points[*s.find(p)].windows; };
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.told = learning::ToldFault::legs({0, 1});
  setup.start_windows = {windows(setup.start).front()};
  setup.start_deviation_deg = setup.criterion.error(setup.start_windows.front());
  setup.search = search(100);
  setup.seed = 5;
  // Ten combinations an earlier episode walked.
  std::set<Periods> earlier;
  for (int l1 : {5, 6}) {
    for (int l2 : kPeriodSet) {
      const Periods p{4, 4, l1, l2};
      setup.earlier.push_back({p, windows(p)});
      earlier.insert(p);
    }
  }
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    SCOPED_TRACE(info.name);
    const LearnerChoice c = learning::resolve_learner(choice(std::string(info.name)));
    const std::unique_ptr<learning::Learner> learner =
        learning::make_learner(c, setup, learning::learner_data(c, setup.robot, setup.criterion));
    std::set<Periods> tried;
    while (learner->stop() == StopReason::running) {
      const std::optional<Periods> p = learner->propose();
      if (!p) break;
      EXPECT_EQ(earlier.count(*p), 0u) << "walked again";
      tried.insert(*p);
      double e = 0.0;
      for (const body::WindowMeasure& w : windows(*p)) e = std::max(e, setup.criterion.error(w));
      learner->observe({e, windows(*p)});
    }
    EXPECT_EQ(learner->stop(), StopReason::space_exhausted);
    EXPECT_EQ(tried.size(), 24u - earlier.size());
  }
  // The model is told the earlier windows: its first pick differs from a model without them.
  const LearnerChoice bayes = learning::resolve_learner(choice("bayes"));
  learning::LearnerSetup forgetful = setup;
  forgetful.earlier.clear();
  EXPECT_NE(learning::make_learner(bayes, setup, {})->propose(),
            learning::make_learner(bayes, forgetful, {})->propose());
}

TEST_F(Dataset, ModelsFindTheHoldingCombinationsSoonerThanChance) {
  // L2 lost: 2 of 125 combinations hold, so chance needs (N+1)/(K+1) = 41.7 trials on average.
  const ScenarioLandscape& s = *data_.find({kL2});
  ASSERT_EQ(s.holding(), 2u);
  ASSERT_NEAR(*learning::random_expected_trials(s), 125.0 / 3.0, 1e-9);
  constexpr int kSeeds = 20;
  const auto mean_trials = [&](const std::string& name) {
    double sum = 0.0;
    for (int seed = 0; seed < kSeeds; ++seed) {
      const ReplayRun r = replay(data_, {kL2}, choice(name), static_cast<std::uint64_t>(seed), 124);
      EXPECT_TRUE(r.answer_holds) << name << " seed " << seed;
      EXPECT_FALSE(r.false_stop) << name << " seed " << seed;
      sum += r.trials;
    }
    return sum / kSeeds;
  };
  const double random = mean_trials("random");
  const double bayes = mean_trials("bayes");
  const double prior = mean_trials("prior");
  EXPECT_GT(random, 20.0);
  EXPECT_LT(bayes, random / 2);
  // What the other scenarios teach (the same pull of every leg) leaves the prior little to try.
  EXPECT_LT(prior, bayes);
}

// Told nothing about the fault, a learner searches every leg's period, the lost leg's too
// (docs/learning.md "What a learner is told"); the prior then cannot leave a scenario out.
TEST_F(Dataset, ALearnerToldNothingSearchesEveryLegsPeriod) {
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.start_deviation_deg = 30.0;
  setup.search = search(60);
  setup.seed = 3;
  EXPECT_EQ(setup.working(), (std::vector<std::size_t>{0, 1, 2, 3}));
  for (const learning::LearnerInfo& info : learning::learner_list()) {
    const std::string name(info.name);
    const LearnerChoice resolved = learning::resolve_learner(choice(name));
    const auto learner = learning::make_learner(
        resolved, setup,
        learning::learner_data(resolved, setup.robot, learning::kPeriodsAloneCriterion));
    bool lost_leg_changed = false;
    // L2 is the lost leg of the truth walked here: its period changes nothing.
    const ScenarioLandscape& truth = *data_.find({kL2});
    while (learner->stop() == StopReason::running) {
      const std::optional<Periods> p = learner->propose();
      if (!p) break;
      lost_leg_changed = lost_leg_changed || (*p)[kL2] != learning::kStartPeriod;
      const LandscapePoint& point = truth.points[*truth.find(*p)];
      learning::Measurement m;
      m.windows = {point.windows.front()};
      m.deviation_deg = learning::kPeriodsAloneCriterion.error(m.windows.front());
      learner->observe(m);
    }
    EXPECT_TRUE(lost_leg_changed) << name;
  }
  LearnerChoice l2 = choice("prior");
  l2.options["scenarios"] = {"R1", "L2"};
  EXPECT_NO_THROW(
      learning::check_learner(learning::resolve_learner(l2), robot::RobotKind::quadruped,
                              learning::ToldFault::nothing(), learning::kPeriodsAloneCriterion));
  EXPECT_THROW(
      learning::check_learner(learning::resolve_learner(l2), robot::RobotKind::quadruped,
                              learning::ToldFault::legs({kL2}), learning::kPeriodsAloneCriterion),
      BadInput);
}

TEST(Learners, TheAdditiveModelIsTheGaussianProcessOfItsKernel) {
  // Its weight-space update, window by window, against the function-space posterior of the
  // kernel it stands for: a constant, plus per working leg the same period, plus per pair of
  // legs the same two periods, each scaled by its prior variance.
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.told = learning::ToldFault::legs({kR2});
  setup.search = search(60);
  const learning::SearchSpace space(setup);
  const learning::AdditiveModelParams params{1.5, 8.0, 4.0, 2.0};
  std::vector<std::vector<double>> prior_mean(learning::kOutputs,
                                              std::vector<double>(space.size()));
  for (std::size_t c = 0; c < space.size(); ++c) {
    prior_mean[learning::kYaw][c] = 0.1 * static_cast<double>(c % 7);
    prior_mean[learning::kPath][c] = -0.2 * static_cast<double>(c % 5);
    prior_mean[learning::kEffort][c] = 0.3 * static_cast<double>(c % 3);
  }
  learning::AdditiveModel model(space, params, prior_mean);
  const auto kernel = [&](std::size_t a, std::size_t b) {
    const std::size_t legs = space.working().size();
    double k = params.intercept_deg * params.intercept_deg;
    for (std::size_t i = 0; i < legs; ++i) {
      if (space.digit(a, i) != space.digit(b, i)) continue;
      k += params.effect_deg * params.effect_deg;
      for (std::size_t j = i + 1; j < legs; ++j) {
        if (space.digit(a, j) == space.digit(b, j)) k += params.pair_deg * params.pair_deg;
      }
    }
    return k;
  };
  // Windows of a few combinations, one of them three times.
  const std::vector<std::size_t> seen{0, 7, 7, 7, 31, 64, 100, 124, 55};
  std::vector<learning::WindowOutputs> windows;
  for (std::size_t n = 0; n < seen.size(); ++n) {
    const double yaw = 3.0 * std::sin(static_cast<double>(n)) + static_cast<double>(seen[n] % 11);
    windows.push_back({yaw, 0.5 * yaw - 1.0, 2.0 + std::cos(static_cast<double>(n))});
    model.observe(seen[n], windows.back());
  }
  const auto n = static_cast<Eigen::Index>(seen.size());
  Eigen::MatrixXd gram(n, n);
  Eigen::MatrixXd residual(n, static_cast<Eigen::Index>(learning::kOutputs));
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t ci = seen[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < n; ++j) gram(i, j) = kernel(ci, seen[static_cast<std::size_t>(j)]);
    gram(i, i) += params.noise_deg * params.noise_deg;
    for (std::size_t o = 0; o < learning::kOutputs; ++o) {
      residual(i, static_cast<Eigen::Index>(o)) =
          windows[static_cast<std::size_t>(i)][o] - prior_mean[o][ci];
    }
  }
  const Eigen::LDLT<Eigen::MatrixXd> solve(gram);
  const Eigen::MatrixXd alpha = solve.solve(residual);
  learning::Predictions predicted;
  model.predict(predicted);
  ASSERT_EQ(predicted[learning::kYaw].size(), space.size());
  for (std::size_t c = 0; c < space.size(); ++c) {
    Eigen::VectorXd k(n);
    for (Eigen::Index i = 0; i < n; ++i) k(i) = kernel(c, seen[static_cast<std::size_t>(i)]);
    const double var = kernel(c, c) - k.dot(solve.solve(k));
    for (std::size_t o = 0; o < learning::kOutputs; ++o) {
      EXPECT_NEAR(predicted[o][c].mean,
                  prior_mean[o][c] + k.dot(alpha.col(static_cast<Eigen::Index>(o))), 1e-9)
          << c << " output " << o;
      EXPECT_NEAR(predicted[o][c].sd, std::sqrt(var), 1e-9) << c;
    }
  }
}

// What a window of `periods` measures on a made-up body: a turn each working leg's period moves,
// a path angle following it, the reflex's effort rising with the turn, two windows a trial.
std::vector<body::WindowMeasure> made_up_windows(const Periods& periods) {
  double yaw = 14.0;
  for (std::size_t leg = 0; leg < periods.size(); ++leg) {
    yaw -= kLegWeightDeg[leg] * period_index(periods[leg]);
  }
  std::vector<body::WindowMeasure> out;
  for (double noise : {-0.7, 0.4}) {
    body::WindowMeasure w;
    w.yaw_deg = yaw + noise;
    w.path_deg = kPathPerYaw * (yaw - noise);
    w.steering_effort = std::min(0.9, 0.02 * std::abs(yaw) + 0.1);
    out.push_back(w);
  }
  return out;
}

// Each trial's forecast is the model's: rebuilt from the start's and the earlier trials' windows,
// the model predicts at the chosen combination the recorded means and sds, and the recorded
// chance to hold (each of the trial's windows, then holding on), E band and count of combinations
// that may hold follow from them (docs/learning.md "Inside the model"). Bayes by its name; the
// prior's path (a prior mean and chances of holding on) by the learner they share.
TEST(Learners, AModelLearnersTrialRecordsItsModelsForecastBeforeTheTrial) {
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.told = learning::ToldFault::legs({kR2});
  setup.criterion = learning::reflex_criterion(learning::kDefaultThresholdDeg, 0.75);
  setup.criterion.trial_windows = 2;  // made_up_windows' two
  setup.start_windows = made_up_windows(setup.start);
  setup.start_deviation_deg = setup.criterion.error(setup.start_windows.front());
  setup.search = search(15);
  setup.seed = 3;
  const learning::SearchSpace space(setup);
  const double t = setup.search.threshold_deg;
  const learning::ModelOptions options;
  const learning::ModelLearnerParams params = learning::model_learner_params(options);
  std::vector<std::vector<double>> prior_mean(learning::kOutputs,
                                              std::vector<double>(space.size(), 0.0));
  for (std::size_t c = 0; c < space.size(); ++c) {
    prior_mean[learning::kYaw][c] = 1.5 * static_cast<double>(c % 4);
  }
  std::vector<double> keep(space.size());
  for (std::size_t c = 0; c < space.size(); ++c) keep[c] = 1.0 - 0.2 * static_cast<double>(c % 5);
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  for (const bool with_prior : {false, true}) {
    SCOPED_TRACE(with_prior ? "a prior mean" : "bayes");
    const std::unique_ptr<learning::Learner> learner =
        with_prior
            ? std::make_unique<learning::ModelLearner>(setup, params, prior_mean, keep)
            : learning::make_learner(learning::resolve_learner({"bayes", nlohmann::json::object()}),
                                     setup, learning::LearnerData{});
    std::vector<std::pair<std::size_t, body::WindowMeasure>> told;
    for (const body::WindowMeasure& w : setup.start_windows) {
      told.emplace_back(*space.index(setup.start), w);
    }
    // The model as the trials told so far leave it, rebuilt from their windows.
    const auto rebuilt = [&] {
      auto model = std::make_unique<learning::AdditiveModel>(
          space, params.model, with_prior ? prior_mean : std::vector<std::vector<double>>{});
      for (const auto& [c, w] : told) {
        model->observe(c, {w.yaw_deg, w.path_deg, setup.criterion.effort_deg(w.steering_effort)});
      }
      return model;
    };
    const auto window_holds = [&](const std::array<learning::Prediction, learning::kOutputs>& p,
                                  double limit) {
      const double sd = std::hypot(p[0].sd, options.noise_deg);
      const auto within = [&](const learning::Prediction& x) {
        return cdf((limit - x.mean) / sd) - cdf((-limit - x.mean) / sd);
      };
      return within(p[learning::kYaw]) * within(p[learning::kPath]) *
             cdf((limit - p[learning::kEffort].mean) / sd);
    };
    // The chance the learner gives combination c: both windows of its trial, then holding on.
    const auto hold = [&](std::size_t c,
                          const std::array<learning::Prediction, learning::kOutputs>& p) {
      return std::pow(window_holds(p, t), 2) * (with_prior ? keep[c] : 1.0);
    };
    std::set<std::size_t> tried{*space.index(setup.start)};
    int trials = 0;
    while (learner->stop() == StopReason::running) {
      const std::optional<Periods> chosen = learner->propose();
      ASSERT_TRUE(chosen);
      const std::size_t c = *space.index(*chosen);
      const std::unique_ptr<learning::AdditiveModel> model = rebuilt();
      const std::array<learning::Prediction, learning::kOutputs> p = model->predict(c);
      std::size_t may_hold = 0;
      for (std::size_t other = 0; other < space.size(); ++other) {
        if (tried.count(other) == 0 &&
            hold(other, model->predict(other)) >= learning::kMayHoldLevel)
          ++may_hold;
      }
      const std::vector<body::WindowMeasure> windows = made_up_windows(*chosen);
      double e = 0.0;
      for (const body::WindowMeasure& w : windows) e = std::max(e, setup.criterion.error(w));
      const learning::TrialRecord r = learner->observe({e, windows});
      const nlohmann::json& d = r.details;
      SCOPED_TRACE("trial " + std::to_string(r.trial));
      EXPECT_EQ(d.at("predicted_yaw_deg").get<double>(), p[learning::kYaw].mean);
      EXPECT_EQ(d.at("predicted_yaw_sd_deg").get<double>(), p[learning::kYaw].sd);
      EXPECT_EQ(d.at("predicted_path_deg").get<double>(), p[learning::kPath].mean);
      EXPECT_EQ(d.at("predicted_path_sd_deg").get<double>(), p[learning::kPath].sd);
      EXPECT_EQ(d.at("predicted_effort_deg").get<double>(), p[learning::kEffort].mean);
      EXPECT_EQ(d.at("predicted_effort_sd_deg").get<double>(), p[learning::kEffort].sd);
      EXPECT_NEAR(d.at("predicted_hold").get<double>(), hold(c, p), 1e-12);
      EXPECT_EQ(d.at("predicted_keep").get<double>(), with_prior ? keep[c] : 1.0);
      // The pi acquisition scores by that chance.
      EXPECT_EQ(d.at("predicted_hold").get<double>(), d.at("acquisition").get<double>());
      const double median = d.at("predicted_e_deg").get<double>();
      const double low = d.at("predicted_e_low_deg").get<double>();
      const double high = d.at("predicted_e_high_deg").get<double>();
      EXPECT_LT(low, median);
      EXPECT_LT(median, high);
      // E's band is one window's.
      EXPECT_NEAR(window_holds(p, median), 0.5, 1e-9);
      EXPECT_NEAR(window_holds(p, low), learning::kBandLowQuantile, 1e-9);
      EXPECT_NEAR(window_holds(p, high), learning::kBandHighQuantile, 1e-9);
      EXPECT_EQ(d.at("untried").get<std::size_t>(), space.size() - tried.size());
      EXPECT_EQ(d.at("may_hold").get<std::size_t>(), may_hold);
      tried.insert(c);
      for (const body::WindowMeasure& w : windows) told.emplace_back(c, w);
      ++trials;
    }
    EXPECT_GT(trials, 1);
    // After the last trial: the map's best, in order, as the model told everything predicts.
    const std::vector<learning::Forecast> best = learner->best_forecasts(5);
    ASSERT_EQ(best.size(), 5u);
    const std::unique_ptr<learning::AdditiveModel> model = rebuilt();
    for (std::size_t i = 0; i < best.size(); ++i) {
      const std::size_t c = *space.index(best[i].periods);
      EXPECT_EQ(best[i].yaw.mean, model->predict(c)[learning::kYaw].mean);
      EXPECT_EQ(best[i].tried, tried.count(c) == 1);
      EXPECT_NEAR(best[i].hold, hold(c, model->predict(c)), 1e-12);
      EXPECT_EQ(best[i].keep, with_prior ? keep[c] : 1.0);
      if (i > 0) {
        EXPECT_GE(best[i - 1].hold, best[i].hold);
      }
    }
    for (std::size_t c = 0; c < space.size(); ++c) {
      EXPECT_LE(hold(c, model->predict(c)), best.front().hold + 1e-12);
    }
  }
  // A learner without a model has no forecast.
  const std::unique_ptr<learning::Learner> random =
      learning::make_learner(learning::resolve_learner({"random", nlohmann::json::object()}), setup,
                             learning::LearnerData{});
  EXPECT_TRUE(random->best_forecasts(5).empty());
  EXPECT_TRUE(learning::forecasts("prior"));
  EXPECT_FALSE(learning::forecasts("annealing"));
}

TEST(CliLearner, LearnTakesALearnerAndItsOptionsAndRecordsThem) {
  const CliResult r = run_cli(
      "learn --robot quadruped --disable L2 --learner bayes --learner-option kappa=1.5 --seed 1 "
      "--json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json learner = nlohmann::json::parse(r.out).at("options").at("learner");
  EXPECT_EQ(learner.at("name"), "bayes");
  EXPECT_EQ(learner.at("options").at("kappa"), 1.5);
  EXPECT_TRUE(learner.at("options").contains("noise_deg"));  // every default, recorded
  EXPECT_EQ(run_cli("learn --robot quadruped --disable L2 --learner bayes --learner-option "
                    "kappa=1.5 --seed 1 --json")
                .out,
            r.out);
  for (const auto& [args, mention] : std::vector<std::pair<std::string, std::string>>{
           {"--learner simplex", "unknown learner 'simplex'"},
           {"--learner bayes --learner-option kappa", "KEY=VALUE"},
           {"--learner bayes --learner-option nope=1", "nope"},
           {"--learner random --learner-option kappa=1", "kappa"},
       }) {
    const CliResult bad = run_cli("learn --robot quadruped --disable L2 " + args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find(mention), std::string::npos) << bad.err;
  }
}

TEST(CliLearner, AnExperimentFileTakesALearnerOrAGridOfThem) {
  const std::string dir = make_temp_dir("learner-experiment-");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + "/" + name) << text;
    return dir + "/" + name;
  };
  const std::string head = "robot = \"quadruped\"\nscenarios = [\"L2\"]\nruns = 1\n";
  const std::string one = write("one.toml", head + "[learning.learner]\nname = \"greedy\"\n");
  EXPECT_EQ(run_cli("run " + one + " --check").exit_code, 0);
  const std::string grid =
      write("grid.toml", head +
                             "[learning]\nlearner = [{ name = \"random\" }, { name = \"bayes\", "
                             "options = { kappa = 1.5 } }]\n");
  const CliResult r = run_cli("run " + grid + " --jobs 2 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string runs = read_file(dir + "/out/runs.csv");
  EXPECT_EQ(count_lines(runs), 3) << runs;  // header + one run per learner
  EXPECT_NE(runs.find("random"), std::string::npos);
  EXPECT_NE(runs.find("bayes"), std::string::npos);
  const auto experiment = nlohmann::json::parse(read_file(dir + "/out/experiment.json"));
  const nlohmann::json learners = experiment.at("arguments").at("learning").at("learner");
  ASSERT_EQ(learners.size(), 2u);
  EXPECT_EQ(learners[1].at("options").at("kappa"), 1.5);
  EXPECT_TRUE(learners[1].at("options").contains("noise_deg"));  // resolved, every default

  for (const auto& [text, mention] : std::vector<std::pair<std::string, std::string>>{
           {"[learning.learner]\nname = \"simplex\"\n", "learning.learner.name"},
           {"[learning.learner]\nname = \"bayes\"\noptions = { kappa = -1 }\n",
            "learning.learner.options.kappa"},
           {"[learning]\nlearner = [{ name = \"bayes\" }, { name = \"bayes\" }]\n",
            "names learner 'bayes' again"},
           {"[learning]\nlearner = \"bayes\"\n", "must be a table"},
       }) {
    const CliResult bad = run_cli("run " + write("bad.toml", head + text) + " --check");
    EXPECT_EQ(bad.exit_code, 2) << text;
    EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
    EXPECT_NE(bad.err.find(mention), std::string::npos) << bad.err;
  }
  fs::remove_all(dir);
}

// docs/learning.md's own grid, the paper's annealing beside the prior, runs (and the annealing
// alone or in any list is accepted: the default learner reads back as the default). Periods
// alone (steering off): the prior learns from the committed dataset of that walk.
TEST(CliLearner, TheDocumentedLearnerGridRuns) {
  const std::string dir = make_temp_dir("learner-grid-");
  const std::string head =
      "robot = \"quadruped\"\nscenarios = [\"L2\"]\nruns = 1\n[learning]\nsteering = \"off\"\n";
  const std::string documented =
      "learner = [{ name = \"annealing\" }, { name = \"prior\" }]\n[learning.annealing]\n"
      "max_trials = 3\n";
  std::ofstream(dir + "/grid.toml") << head + documented;
  const CliResult r = run_cli("run " + dir + "/grid.toml --jobs 2 --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string runs = read_file(dir + "/out/runs.csv");
  EXPECT_EQ(count_lines(runs), 3) << runs;
  EXPECT_NE(runs.find("annealing"), std::string::npos) << runs;
  EXPECT_NE(runs.find("prior"), std::string::npos) << runs;
  for (const std::string learner :
       {"learner = { name = \"annealing\" }\n", "learner = [{ name = \"annealing\" }]\n",
        "learner = [{ name = \"random\" }, { name = \"annealing\", options = {} }]\n"}) {
    std::ofstream(dir + "/check.toml") << head + learner;
    const CliResult check = run_cli("run " + dir + "/check.toml --check");
    EXPECT_EQ(check.exit_code, 0) << learner << check.err;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace multicpg::testing
