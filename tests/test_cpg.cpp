// The chaotic CPG against its oracles (docs/controller.md "Converged values").
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "experiments/cpg_pair.h"
#include "neural/cpg.h"

namespace {

using multicpg::neural::CpgParams;
using multicpg::neural::CpgState;

constexpr long kConvergeSteps = 20000;

CpgState converged(int period, long steps = kConvergeSteps) {
  CpgParams params;
  CpgState s;
  multicpg::neural::cpg_reset(params, s, period);
  for (long t = 0; t < steps; ++t) multicpg::neural::cpg_step(params, s);
  return s;
}

struct Oracle {
  int period;
  double mu_plus_one;  // mu + 1, the authors' "cl"
};

class CpgOracle : public ::testing::TestWithParam<Oracle> {};

TEST_P(CpgOracle, ControlStrengthConvergesToReferenceValue) {
  const Oracle o = GetParam();
  EXPECT_NEAR(converged(o.period).mu + 1.0, o.mu_plus_one, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Periods, CpgOracle,
                         ::testing::Values(Oracle{4, 0.044497}, Oracle{5, 0.056449},
                                           Oracle{6, 0.012558}, Oracle{8, 0.017359},
                                           Oracle{9, 0.021984}));

TEST(Cpg, PeriodFourOrbitMatchesReference) {
  // docs/controller.md "Converged values": x1 orbit 0.6534, 0.0000, 0.2333, 0.0595 and x2 0.9679,
  // 0.3746, 0.9781, 0.9056.
  const std::vector<double> x1{0.6534, 0.0000, 0.2333, 0.0595};
  const std::vector<double> x2{0.9679, 0.3746, 0.9781, 0.9056};
  CpgParams params;
  CpgState s = converged(4);
  // Find the orbit phase that starts at the largest x1, then compare in order.
  for (int k = 0; k < 4 && std::abs(s.x1 - x1[0]) > 1e-3; ++k) {
    multicpg::neural::cpg_step(params, s);
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(s.x1, x1[k], 1e-4) << "phase " << k;
    EXPECT_NEAR(s.x2, x2[k], 1e-4) << "phase " << k;
    multicpg::neural::cpg_step(params, s);
  }
}

TEST(Cpg, OrbitHasExactlyThePeriodAsked) {
  CpgParams params;
  for (int p : {4, 5, 6, 8, 9}) {
    CpgState s = converged(p);
    std::vector<double> x1;
    for (int t = 0; t < 200; ++t) {
      multicpg::neural::cpg_step(params, s);
      x1.push_back(s.x1);
    }
    EXPECT_EQ(multicpg::experiments::orbit_period(x1, multicpg::neural::kMaxPeriod, 100), p);
  }
}

TEST(Cpg, PeriodsThreeAndSevenNeverSettle) {
  CpgParams params;
  for (int p : {3, 7}) {
    CpgState s;
    multicpg::neural::cpg_reset(params, s, p);
    std::vector<double> x1;
    for (long t = 0; t < kConvergeSteps; ++t) {
      multicpg::neural::cpg_step(params, s);
      x1.push_back(s.x1);
    }
    // Settled would mean p-periodic over some 2p consecutive steps; that never happens.
    long longest_settled_run = 0;
    long run = 0;
    for (std::size_t t = p; t < x1.size(); ++t) {
      run = std::abs(x1[t] - x1[t - p]) < 1e-6 ? run + 1 : 0;
      longest_settled_run = std::max(longest_settled_run, run);
    }
    EXPECT_LT(longest_settled_run, 2 * p) << "period " << p;
    EXPECT_GT(s.mu + 1.0, 5.0) << "control strength keeps growing for period " << p;
  }
}

// Largest Lyapunov exponent of the uncontrolled map by tangent-vector renormalisation.
double largest_lyapunov(long steps, long transient) {
  CpgParams q;
  double x1 = 0.1;
  double x2 = 0.1;
  double v1 = 1.0;
  double v2 = 0.0;
  double sum = 0.0;
  for (long t = 0; t < transient + steps; ++t) {
    const double s1 = 1.0 / (1.0 + std::exp(-(q.theta1 + q.w11 * x1 + q.w12 * x2)));
    const double s2 = 1.0 / (1.0 + std::exp(-(q.theta2 + q.w21 * x1)));
    // Jacobian of (x1, x2) -> (s1, s2): ds/da = s (1 - s).
    const double d1 = s1 * (1.0 - s1);
    const double d2 = s2 * (1.0 - s2);
    const double n1 = d1 * (q.w11 * v1 + q.w12 * v2);
    const double n2 = d2 * (q.w21 * v1);
    const double norm = std::hypot(n1, n2);
    v1 = n1 / norm;
    v2 = n2 / norm;
    x1 = s1;
    x2 = s2;
    if (t >= transient) sum += std::log(norm);
  }
  return sum / static_cast<double>(steps);
}

TEST(Cpg, UncontrolledIsChaotic) {
  const double lambda = largest_lyapunov(100000, 1000);
  EXPECT_GT(lambda, 0.2);
  EXPECT_LT(lambda, 0.4);  // about +0.30 per step (docs/controller.md "CPG")

  // The library's uncontrolled mode follows the same map: no orbit of period <= 9.
  CpgParams params;
  CpgState s;
  multicpg::neural::cpg_reset(params, s, 4);
  s.chaotic = true;
  std::vector<double> x1;
  for (int t = 0; t < 2000; ++t) {
    multicpg::neural::cpg_step(params, s);
    x1.push_back(s.x1);
  }
  EXPECT_EQ(multicpg::experiments::orbit_period(x1, multicpg::neural::kMaxPeriod, 500), 0);
  EXPECT_EQ(s.mu, params.mu0) << "no adaptation without control";
}

}  // namespace
