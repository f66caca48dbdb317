// The learners (learning/learner.h, learning/learners.h) on synthetic landscapes whose truth is
// known, the landscape files (learning/landscapes.h), and the CLI that chooses and benchmarks them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "common/errors.h"
#include "experiments/learner_benchmark.h"
#include "learning/additive_model.h"
#include "learning/ask_tell.h"
#include "learning/benchmark.h"
#include "learning/landscapes.h"
#include "learning/learners.h"
#include "learning/model_learner.h"
#include "learning/search_space.h"
#include "tests/cli_runner.h"

namespace multicpg::testing {
namespace {

namespace fs = std::filesystem;
using learning::LandscapeDataset;
using learning::LandscapePoint;
using learning::LearnerChoice;
using learning::Periods;
using learning::ReplayRun;
using learning::ScenarioLandscape;
using learning::SearchBounds;
using learning::StopReason;
using learning::TrialProtocol;

const std::vector<int> kPeriodSet{4, 5, 6, 8, 9};
// Each quadruped leg's (R1, R2, L1, L2) pull on the yaw per step up the period set: a landscape
// that is additive, as the model-based learners assume, and the same across scenarios, so the
// other scenarios predict the one under test.
const std::vector<double> kLegWeightDeg{3.0, 2.0, 1.0, 2.5};
constexpr double kPathPerYaw = 0.3;
const std::vector<double> kWindowNoiseDeg{-0.5, 0.0, 0.5};

int period_index(int period) {
  return static_cast<int>(std::find(kPeriodSet.begin(), kPeriodSet.end(), period) -
                          kPeriodSet.begin());
}

// A scenario of the quadruped whose yaw is `offset` minus each working leg's weight times its
// step up the period set; with `offset` = every working weight × 4 + 6 only the last few
// combinations up the set hold.
ScenarioLandscape synthetic_scenario(const std::vector<std::size_t>& failed, bool none_holds) {
  ScenarioLandscape s;
  s.failed = failed;
  std::vector<std::size_t> working;
  double top = 0.0;
  for (std::size_t leg = 0; leg < kLegWeightDeg.size(); ++leg) {
    if (std::find(failed.begin(), failed.end(), leg) != failed.end()) continue;
    working.push_back(leg);
    top += 4.0 * kLegWeightDeg[leg];
  }
  const double offset = none_holds ? 100.0 : top + 6.0;
  std::vector<int> index(working.size(), 0);
  while (true) {
    LandscapePoint p;
    p.periods.assign(kLegWeightDeg.size(), learning::kStartPeriod);
    double yaw = offset;
    for (std::size_t i = 0; i < working.size(); ++i) {
      p.periods[working[i]] = kPeriodSet[static_cast<std::size_t>(index[i])];
      yaw -= kLegWeightDeg[working[i]] * index[i];
    }
    p.holds = true;
    for (double noise : kWindowNoiseDeg) {
      body::WindowMeasure w;
      w.yaw_deg = yaw + noise;
      w.path_deg = kPathPerYaw * (yaw + noise);
      p.windows.push_back(w);
      const double worst = std::max(std::abs(yaw + noise), std::abs(kPathPerYaw * (yaw + noise)));
      p.worst_deg = std::max(p.worst_deg, worst);
      p.holds = p.holds && worst < learning::kDefaultThresholdDeg;
    }
    s.points.push_back(p);
    std::size_t i = 0;
    while (i < index.size() && ++index[i] == static_cast<int>(kPeriodSet.size())) index[i++] = 0;
    if (i == index.size()) break;
  }
  return s;
}

// Every one-leg loss of the quadruped (R1, R2, L1, L2), and R1+R2 where nothing holds.
LandscapeDataset synthetic_dataset() {
  LandscapeDataset d;
  d.robot = robot::RobotKind::quadruped;
  d.period_set = kPeriodSet;
  d.windows = static_cast<int>(kWindowNoiseDeg.size());
  d.window_steps = 400;
  d.threshold_deg = learning::kDefaultThresholdDeg;
  d.sim = nlohmann::json::object();
  for (std::size_t leg = 0; leg < kLegWeightDeg.size(); ++leg) {
    d.scenarios.push_back(synthetic_scenario({leg}, false));
  }
  d.scenarios.push_back(synthetic_scenario({0, 1}, true));
  return d;
}

constexpr std::size_t kL2 = 3;
constexpr std::size_t kR2 = 1;

SearchBounds search(int max_trials) {
  SearchBounds p;
  p.period_set = kPeriodSet;
  p.max_trials = max_trials;
  return p;
}

ReplayRun replay(const LandscapeDataset& d, const std::vector<std::size_t>& failed,
                 const LearnerChoice& choice, std::uint64_t seed, int max_trials = 60) {
  const ScenarioLandscape* s = d.find(failed);
  EXPECT_NE(s, nullptr);
  const LearnerChoice resolved = learning::resolve_learner(choice);
  return learning::replay_run(d, *s, resolved,
                              learning::learner_data(resolved, d.robot, d.criterion()),
                              search(max_trials), TrialProtocol{}, seed);
}

class Dataset : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = make_temp_dir("learners-");
    data_ = synthetic_dataset();
    learning::write_landscape_dataset(data_, fs::path(dir_) / "synthetic");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string stem() const { return dir_ + "/synthetic"; }
  LearnerChoice choice(const std::string& name) const {
    LearnerChoice c{name, nlohmann::json::object()};
    if (name == "prior") c.options["dataset"] = stem();
    return c;
  }
  std::string dir_;
  LandscapeDataset data_;
};

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

TEST_F(Dataset, AWrittenDatasetReadsBackAndAnEditedOneIsRefused) {
  const LandscapeDataset back = learning::read_landscape_dataset(stem());
  ASSERT_EQ(back.scenarios.size(), data_.scenarios.size());
  EXPECT_EQ(back.period_set, kPeriodSet);
  for (std::size_t i = 0; i < back.scenarios.size(); ++i) {
    EXPECT_EQ(back.scenarios[i].failed, data_.scenarios[i].failed);
    EXPECT_EQ(back.scenarios[i].holding(), data_.scenarios[i].holding());
    ASSERT_EQ(back.scenarios[i].points.size(), data_.scenarios[i].points.size());
    EXPECT_EQ(back.scenarios[i].points.back().periods, data_.scenarios[i].points.back().periods);
    EXPECT_NEAR(back.scenarios[i].points.back().windows[2].yaw_deg,
                data_.scenarios[i].points.back().windows[2].yaw_deg,
                learning::kLandscapeAngleResolutionDeg);
  }
  EXPECT_GT(data_.find({kL2})->holding(), 0u);
  EXPECT_EQ(data_.find({0, 1})->holding(), 0u);

  // One byte changed in the compressed table: the manifest's checksum no longer matches.
  const fs::path csv = stem() + ".csv.gz";
  std::string bytes = read_file(csv.string());
  ASSERT_GT(bytes.size(), 40u);
  {
    std::string cut = bytes.substr(0, bytes.size() / 2);
    std::ofstream(csv, std::ios::binary) << cut;
    EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
  }
  fs::remove(csv);
  EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
}

// A manifest whose checksum still matches its table but whose own fields are damaged is refused
// with one line naming the file and the field, never read as some other dataset.
TEST_F(Dataset, ADamagedManifestIsRefusedNamingTheFileAndTheField) {
  const fs::path manifest = stem() + ".json";
  const std::string good = read_file(manifest.string());
  const auto refused = [&](const std::string& what, const std::string& field,
                           const std::function<void(nlohmann::json&)>& damage) {
    nlohmann::json m = nlohmann::json::parse(good);
    damage(m);
    std::ofstream(manifest) << m.dump(2);
    try {
      learning::read_landscape_dataset(stem());
      ADD_FAILURE() << what << " was read";
    } catch (const BadInput& e) {
      const std::string line = e.what();
      EXPECT_NE(line.find("synthetic.json"), std::string::npos) << what << ": " << line;
      EXPECT_NE(line.find(field), std::string::npos) << what << ": " << line;
      EXPECT_EQ(line.find('\n'), std::string::npos) << what << ": " << line;
    }
  };
  refused("version 1.5", "version", [](nlohmann::json& m) { m["version"] = 1.5; });
  refused("threshold -1", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = -1; });
  refused("threshold 0", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = 0; });
  refused("threshold 1e308", "threshold", [](nlohmann::json& m) { m["threshold_deg"] = 1e308; });
  refused("count 125.5", "combinations",
          [](nlohmann::json& m) { m["scenarios"][0]["combinations"] = 125.5; });
  refused("no checksum", "checksum", [](nlohmann::json& m) { m.erase("checksum"); });
  refused("a numeric checksum", "checksum", [](nlohmann::json& m) { m["checksum"] = 7; });
  std::ofstream(manifest) << "";
  EXPECT_THROW(learning::read_landscape_dataset(stem()), BadInput);
  std::ofstream(manifest) << good;
  EXPECT_NO_THROW(learning::read_landscape_dataset(stem()));
}

TEST(Learners, TheRepositoryDatasetsReadWhole) {
  const LandscapeDataset q = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::quadruped, false));
  EXPECT_EQ(q.scenarios.size(), 14u);  // every loss of one, two or three legs
  EXPECT_EQ(q.windows, 6);
  EXPECT_EQ(q.find({3})->points.size(), 125u);  // L2
  EXPECT_EQ(q.find({3})->holding(), 2u);        // docs/learning.md "The landscape"
  const LandscapeDataset h = learning::read_landscape_dataset(
      learning::repository_dataset(robot::RobotKind::hexapod, false));
  EXPECT_GE(h.scenarios.size(), 35u);  // the two- and three-leg losses at least
  for (const ScenarioLandscape& s : h.scenarios) {
    const std::size_t working = 6 - s.failed.size();
    std::size_t expected = 1;
    for (std::size_t i = 0; i < working; ++i) expected *= kPeriodSet.size();
    EXPECT_EQ(s.points.size(), expected);
  }
}

// The search path (learning/landscapes.h): $MULTICPG_DATA before the source tree (nothing is
// installed beside this test program), a dataset it lacks found further on, and one that no
// place holds refused on one line naming every place looked, by the CLI too (exit 2).
TEST_F(Dataset, MulticpgDataComesFirstAndAMissingDatasetNamesEveryPlaceLooked) {
  const fs::path source = learning::repository_dataset(robot::RobotKind::quadruped, false);
  const fs::path given = fs::path(dir_) / "landscapes";
  fs::create_directories(given);
  learning::write_landscape_dataset(data_, given / "quadruped");
  const auto missing = [] {
    try {
      learning::repository_dataset(robot::RobotKind::octopod, false);
    } catch (const BadInput& e) {
      return std::string(e.what());
    }
    return std::string("found");
  };
  struct DataEnv {
    explicit DataEnv(const std::string& dir) { setenv(learning::kDataEnv, dir.c_str(), 1); }
    ~DataEnv() { unsetenv(learning::kDataEnv); }
  };
  {
    const DataEnv env(dir_);
    EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, false),
              given / "quadruped");
    EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, true),
              source.parent_path() / "quadruped-reflex");
    const std::string named = missing();
    EXPECT_NE(named.find("no landscape dataset octopod"), std::string::npos) << named;
    EXPECT_NE(named.find(given.string() + ", "), std::string::npos) << named;
    EXPECT_NE(named.find(source.parent_path().string()), std::string::npos) << named;
    EXPECT_EQ(named.find('\n'), std::string::npos) << named;
  }
  EXPECT_EQ(learning::repository_dataset(robot::RobotKind::quadruped, false), source);
  EXPECT_NE(missing().find("$MULTICPG_DATA unset"), std::string::npos) << missing();
  expect_bad_input("learn --robot octopod --disable R1 --learner prior --steering off",
                   "no landscape dataset octopod");
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

// What a run's earlier episodes walked (LearnerSetup::earlier) the learners that remember do not
// walk again, and the models are told its windows (docs/learning.md "Memory across episodes").
TEST_F(Dataset, TheLearnersThatRememberDoNotWalkAnEarlierEpisodesCombinationsAgain) {
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
  for (const std::string name : {"random", "bayes", "prior"}) {
    SCOPED_TRACE(name);
    const LearnerChoice c = learning::resolve_learner(choice(name));
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
// chance to hold, E band and count of combinations that may hold follow from them
// (docs/learning.md "Inside the model"). Bayes by its name; the prior's path (a prior mean) by
// the learner they share.
TEST(Learners, AModelLearnersTrialRecordsItsModelsForecastBeforeTheTrial) {
  learning::LearnerSetup setup;
  setup.robot = robot::RobotKind::quadruped;
  setup.start.assign(4, learning::kStartPeriod);
  setup.told = learning::ToldFault::legs({kR2});
  setup.criterion = learning::reflex_criterion(learning::kDefaultThresholdDeg, 0.75);
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
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  for (const bool with_prior : {false, true}) {
    SCOPED_TRACE(with_prior ? "a prior mean" : "bayes");
    const std::unique_ptr<learning::Learner> learner =
        with_prior
            ? std::make_unique<learning::ModelLearner>(setup, params, prior_mean)
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
    const auto hold = [&](const std::array<learning::Prediction, learning::kOutputs>& p,
                          double limit) {
      const double sd = std::hypot(p[0].sd, options.noise_deg);
      const auto within = [&](const learning::Prediction& x) {
        return cdf((limit - x.mean) / sd) - cdf((-limit - x.mean) / sd);
      };
      return within(p[learning::kYaw]) * within(p[learning::kPath]) *
             cdf((limit - p[learning::kEffort].mean) / sd);
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
        if (tried.count(other) == 0 && hold(model->predict(other), t) >= learning::kMayHoldLevel)
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
      EXPECT_NEAR(d.at("predicted_hold").get<double>(), hold(p, t), 1e-12);
      // The pi acquisition scores by that chance.
      EXPECT_EQ(d.at("predicted_hold").get<double>(), d.at("acquisition").get<double>());
      const double median = d.at("predicted_e_deg").get<double>();
      const double low = d.at("predicted_e_low_deg").get<double>();
      const double high = d.at("predicted_e_high_deg").get<double>();
      EXPECT_LT(low, median);
      EXPECT_LT(median, high);
      EXPECT_NEAR(hold(p, median), 0.5, 1e-9);
      EXPECT_NEAR(hold(p, low), learning::kBandLowQuantile, 1e-9);
      EXPECT_NEAR(hold(p, high), learning::kBandHighQuantile, 1e-9);
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
      EXPECT_NEAR(best[i].hold, hold(model->predict(c), t), 1e-12);
      if (i > 0) {
        EXPECT_GE(best[i - 1].hold, best[i].hold);
      }
    }
    for (std::size_t c = 0; c < space.size(); ++c) {
      EXPECT_LE(hold(model->predict(c), t), best.front().hold + 1e-12);
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
  EXPECT_NE(r.out.find("5 scenarios x 4 seeds"), std::string::npos) << r.out;
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
