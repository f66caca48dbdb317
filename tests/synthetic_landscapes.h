// The synthetic landscapes the learner, dataset and benchmark tests share: a quadruped whose
// windows each working leg's period turns by a known weight, and a fixture that writes them as a
// dataset the prior can read.
#pragma once

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

inline const std::vector<int> kPeriodSet{4, 5, 6, 8, 9};
// Each quadruped leg's (R1, R2, L1, L2) pull on the yaw per step up the period set: a landscape
// that is additive, as the model-based learners assume, and the same across scenarios, so the
// other scenarios predict the one under test.
inline const std::vector<double> kLegWeightDeg{3.0, 2.0, 1.0, 2.5};
inline constexpr double kPathPerYaw = 0.3;
inline const std::vector<double> kWindowNoiseDeg{-0.5, 0.0, 0.5};

inline int period_index(int period) {
  return static_cast<int>(std::find(kPeriodSet.begin(), kPeriodSet.end(), period) -
                          kPeriodSet.begin());
}

// A scenario of the quadruped whose yaw is `offset` minus each working leg's weight times its
// step up the period set; with `offset` = every working weight × 4 + 6 only the last few
// combinations up the set hold.
inline ScenarioLandscape synthetic_scenario(const std::vector<std::size_t>& failed,
                                            bool none_holds) {
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
inline LandscapeDataset synthetic_dataset() {
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

inline constexpr std::size_t kL2 = 3;
inline constexpr std::size_t kR2 = 1;

inline SearchBounds search(int max_trials) {
  SearchBounds p;
  p.period_set = kPeriodSet;
  p.max_trials = max_trials;
  return p;
}

inline ReplayRun replay(const LandscapeDataset& d, const std::vector<std::size_t>& failed,
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

}  // namespace multicpg::testing
