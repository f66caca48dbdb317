// Physics fidelity: cheaper MuJoCo settings must walk the same robot. The baselines
// are what the hexapod did before the contact rework changed the physics (explicit ground contact
// pairs, sparse constraint Jacobians), measured with exactly the specs below:
//   multicpg walk --robot hexapod --periods P [--disable R1|L1] --warmup 1000 --settle 400
//                 --steps 1200 --json
// at commit 1a31546 (MuJoCo 2.2.2, Euler, physics step 0.004625 s; docs/robots.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <utility>

#include "sim/walk.h"

namespace {

using namespace multicpg;

// Speed (cm/s) of the intact hexapod per gait before the contact rework.
constexpr std::pair<int, double> kBaselineSpeedCmS[] = {
    {4, 7.8552}, {5, 4.6902}, {6, 3.0821}, {8, 1.5984}, {9, 1.2520}};
// Mean deviation per 400-step window (deg, + = left) with R1 / L1 disabled, others p = 4, before
// the contact rework (windows -41.56, -41.07, -41.22 and +43.80, +44.11, +42.11).
constexpr double kBaselineR1TurnDeg = -41.28;
constexpr double kBaselineL1TurnDeg = 43.34;
// Tolerances of the contact rework (docs/robots.md).
constexpr double kSpeedTolerance = 0.05;  // relative
constexpr double kTurnToleranceDeg = 2.0;
constexpr double kStraightDeg = 8.0;  // paper §4.1 threshold

constexpr long kSettle = 400;
constexpr long kSteps = 1200;

const sim::SimModel& hexapod() {
  static const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  return model;
}

sim::WalkResult walk(int period, std::vector<std::size_t> disabled = {}) {
  sim::WalkSpec spec;
  spec.start.periods.assign(hexapod().legs.size(), period);
  spec.faults = body::fail_at(disabled, 0);
  spec.settle = kSettle;
  spec.steps = kSteps;
  spec.record = false;
  return sim::walk(hexapod(), spec);
}

double mean_turn(const sim::WalkResult& r) {
  const std::vector<double>& w = r.window_deviations_deg;
  return std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(w.size());
}

TEST(Fidelity, GaitSpeedsMatchTheBaseline) {
  for (const auto& [period, baseline] : kBaselineSpeedCmS) {
    const sim::WalkResult r = walk(period);
    EXPECT_NEAR(100.0 * r.speed_m_s, baseline, kSpeedTolerance * baseline) << "p = " << period;
    RecordProperty("speed_cm_s_p" + std::to_string(period), std::to_string(100.0 * r.speed_m_s));
  }
}

TEST(Fidelity, IntactTripodWalksStraight) {
  const sim::WalkResult r = walk(4);
  ASSERT_EQ(r.window_deviations_deg.size(), 3u);
  for (double d : r.window_deviations_deg) EXPECT_LT(std::abs(d), kStraightDeg);
}

TEST(Fidelity, DisabledFrontLegTurnsMatchTheBaseline) {
  const sim::WalkResult right = walk(4, {0});  // R1
  const sim::WalkResult left = walk(4, {3});   // L1
  ASSERT_EQ(right.window_deviations_deg.size(), 3u);
  ASSERT_EQ(left.window_deviations_deg.size(), 3u);
  EXPECT_NEAR(mean_turn(right), kBaselineR1TurnDeg, kTurnToleranceDeg);
  EXPECT_NEAR(mean_turn(left), kBaselineL1TurnDeg, kTurnToleranceDeg);
  RecordProperty("R1_turn_deg", std::to_string(mean_turn(right)));
  RecordProperty("L1_turn_deg", std::to_string(mean_turn(left)));
}

}  // namespace
