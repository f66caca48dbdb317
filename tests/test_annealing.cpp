// Simulated annealing over leg periods (paper Table 2 and the Fig. 8 walk-through; docs/learning.md
// "The search").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>

#include "common/errors.h"
#include "common/random.h"
#include "learning/annealing.h"

namespace multicpg::learning {
namespace {

constexpr std::size_t kHexLegs = 6;
constexpr std::size_t kR1 = 0;
constexpr std::size_t kR3 = 2;
constexpr std::size_t kL2 = 4;
const Periods kAllFour(kHexLegs, kStartPeriod);

std::size_t changed_legs(const Periods& a, const Periods& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i] ? 1 : 0;
  return n;
}

// Every combination that differs from `from` in exactly one of `legs`.
std::vector<Periods> one_leg_changes(const AnnealingParams& params, const Periods& from,
                                     const std::vector<std::size_t>& legs) {
  std::vector<Periods> out;
  for (std::size_t leg : legs) {
    for (int p : params.period_set) {
      if (p == from[leg]) continue;
      Periods c = from;
      c[leg] = p;
      out.push_back(c);
    }
  }
  return out;
}

// A deterministic stand-in for the robot: deviation from the periods alone.
double scripted_deviation(const Periods& periods) {
  double left = 0.0;
  double right = 0.0;
  for (std::size_t i = 1; i < 3; ++i) right += 1.0 / periods[i];
  for (std::size_t i = 3; i < 6; ++i) left += 1.0 / periods[i];
  return std::abs(150.0 * (left - right));
}

AnnealingState run_to_end(const AnnealingParams& params, std::uint64_t seed) {
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, scripted_deviation(kAllFour), seed);
  while (std::optional<Candidate> c = propose(params, s)) {
    if (decide(params, s, scripted_deviation(c->periods)).stop != StopReason::running) break;
  }
  return s;
}

TEST(Annealing, PaperFig8AcceptsBetterThenRejectsMuchWorse) {
  const AnnealingParams params;  // beta 0.5, threshold 8, 200 trials
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 37.86, 1);
  ASSERT_EQ(s.stop, StopReason::running);

  const Candidate first = *propose(params, s);
  const Decision better = decide_with_draw(params, s, 21.46, 0.999);
  EXPECT_TRUE(better.accepted);
  EXPECT_EQ(better.probability, 1.0);
  EXPECT_EQ(s.accepted, first.periods);
  EXPECT_EQ(s.e_ref, 21.46);

  propose(params, s);
  const Decision worse = decide_with_draw(params, s, 64.12, 1e-6);
  EXPECT_FALSE(worse.accepted);
  // Paper Eq. 7: exp(-0.5 (64.12 - 21.46)) = 5.45e-10.
  EXPECT_NEAR(worse.probability, 5.45e-10, 0.01e-10);
  EXPECT_EQ(s.accepted, first.periods);
  EXPECT_EQ(s.e_ref, 21.46);

  // Step 3 is derived from step 1, not from the rejected step 2.
  const Candidate third = *propose(params, s);
  EXPECT_EQ(changed_legs(third.periods, first.periods), 1u);
  ASSERT_EQ(s.trace.size(), 2u);
  EXPECT_EQ(s.trace[0].trial, 1);
  EXPECT_TRUE(s.trace[0].accepted);
  EXPECT_FALSE(s.trace[1].accepted);
}

TEST(Annealing, AcceptsWorseIffDrawBelowProbability) {
  const AnnealingParams params;
  const double e_ref = 20.0;
  const double e = 20.2;
  const double p = std::exp(-params.beta * (e - e_ref));
  for (const auto& [draw, accept] : {std::pair{p - 1e-9, true}, std::pair{p, false}}) {
    AnnealingState s = start_annealing(params, kAllFour, {kR1}, e_ref, 3);
    const Candidate c = *propose(params, s);
    const Decision d = decide_with_draw(params, s, e, draw);
    EXPECT_EQ(d.accepted, accept);
    EXPECT_DOUBLE_EQ(d.probability, p);
    EXPECT_EQ(s.accepted, accept ? c.periods : kAllFour);
    EXPECT_EQ(s.e_ref, accept ? e : e_ref);
  }
}

TEST(Annealing, BetaZeroAcceptsEveryWorseCandidate) {
  AnnealingParams params;
  params.beta = 0.0;  // random search (paper Fig. 14)
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 10.0, 4);
  propose(params, s);
  EXPECT_TRUE(decide(params, s, 170.0).accepted);
  EXPECT_EQ(s.e_ref, 170.0);
}

TEST(Annealing, TabuRedrawFindsTheOnlyUntriedNeighbour) {
  const AnnealingParams params;
  const std::vector<std::size_t> working{1, 2, 3, 4, 5};
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 30.0, 5);
  std::vector<Periods> neighbours = one_leg_changes(params, kAllFour, working);
  const Periods untried = neighbours.back();
  neighbours.pop_back();
  for (const Periods& n : neighbours) s.tried.insert(n);

  const Candidate c = *propose(params, s);
  EXPECT_EQ(c.periods, untried);
  EXPECT_EQ(c.legs_changed, 1);
  // 24 of the 25 (leg, period) draws are tabu; this seed needs several.
  EXPECT_GT(c.redraws, 0);
  decide_with_draw(params, s, 40.0, 0.9);
  EXPECT_GT(s.trace.back().redraws, 0);
}

TEST(Annealing, EscalatesToTwoThenThreeLegsWhenNeighboursAreTried) {
  const AnnealingParams params;
  const std::vector<std::size_t> working{1, 2, 3, 4, 5};
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 30.0, 6);
  std::vector<Periods> ones = one_leg_changes(params, kAllFour, working);
  for (const Periods& n : ones) s.tried.insert(n);

  const Candidate two = *propose(params, s);
  EXPECT_EQ(two.legs_changed, 2);
  EXPECT_EQ(changed_legs(two.periods, kAllFour), 2u);
  EXPECT_EQ(two.periods[kR1], kStartPeriod);
  decide_with_draw(params, s, 40.0, 0.9);  // rejected: the accepted combination stays C0

  for (const Periods& one : ones) {
    for (const Periods& n : one_leg_changes(params, one, working)) s.tried.insert(n);
  }
  const Candidate three = *propose(params, s);
  EXPECT_EQ(three.legs_changed, 3);
  EXPECT_EQ(changed_legs(three.periods, kAllFour), 3u);
}

TEST(Annealing, ExhaustedSpaceEndsTheRun) {
  const AnnealingParams params;
  // Quadruped with R1, R2, L1 disabled: only L2 may change, 5 combinations in all.
  const Periods start(4, kStartPeriod);
  AnnealingState s = start_annealing(params, start, {0, 1, 2}, 30.0, 7);
  int proposals = 0;
  while (std::optional<Candidate> c = propose(params, s)) {
    ++proposals;
    EXPECT_EQ(changed_legs(c->periods, start), 1u);
    decide(params, s, 30.0 + proposals);
  }
  EXPECT_EQ(proposals, 4);
  EXPECT_EQ(s.stop, StopReason::space_exhausted);
  EXPECT_EQ(s.trials, 4);
}

TEST(Annealing, StopsBelowThreshold) {
  const AnnealingParams params;
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 30.0, 8);
  propose(params, s);
  const Decision d = decide(params, s, 7.9);
  EXPECT_TRUE(d.accepted);
  EXPECT_EQ(d.stop, StopReason::below_threshold);
  EXPECT_THROW(propose(params, s), std::logic_error);
}

TEST(Annealing, StartBelowThresholdIsAlreadyDone) {
  const AnnealingParams params;
  const AnnealingState s = start_annealing(params, kAllFour, {kR1}, 3.0, 8);
  EXPECT_EQ(s.stop, StopReason::below_threshold);
  EXPECT_EQ(s.trials, 0);
}

TEST(Annealing, TrialCapEndsNotConverged) {
  AnnealingParams params;
  params.max_trials = 3;
  AnnealingState s = start_annealing(params, kAllFour, {kR1}, 30.0, 9);
  for (int i = 0; i < 3; ++i) {
    propose(params, s);
    decide(params, s, 50.0);
  }
  EXPECT_EQ(s.stop, StopReason::trial_cap);
  EXPECT_EQ(s.trials, 3);
  EXPECT_THROW(propose(params, s), std::logic_error);
}

TEST(Annealing, DisabledLegsNeverChangeAndNoCombinationRepeats) {
  AnnealingParams params;
  params.beta = 0.1;
  const std::vector<std::size_t> disabled{kR1, kR3, kL2};
  AnnealingState s = start_annealing(params, kAllFour, disabled, 30.0, 10);
  std::set<Periods> seen{kAllFour};
  std::mt19937_64 noise(11);
  while (std::optional<Candidate> c = propose(params, s)) {
    for (std::size_t leg : disabled) EXPECT_EQ(c->periods[leg], kStartPeriod);
    EXPECT_TRUE(seen.insert(c->periods).second);
    // Deviations above the threshold, so the run only ends by the cap or by exhaustion.
    decide(params, s, 10.0 + 50.0 * draw_unit(noise));
  }
  // 3 working legs: 5^3 = 125 combinations, C0 plus 124 trials.
  EXPECT_EQ(s.stop, StopReason::space_exhausted);
  EXPECT_EQ(s.trials, 124);
}

TEST(Annealing, SameSeedSameTraceOtherSeedOtherTrace) {
  const AnnealingParams params;
  const AnnealingState a = run_to_end(params, 42);
  const AnnealingState b = run_to_end(params, 42);
  const AnnealingState c = run_to_end(params, 43);
  auto same = [](const AnnealingState& x, const AnnealingState& y) {
    if (x.trace.size() != y.trace.size()) return false;
    for (std::size_t i = 0; i < x.trace.size(); ++i) {
      if (x.trace[i].periods != y.trace[i].periods || x.trace[i].accepted != y.trace[i].accepted) {
        return false;
      }
    }
    return true;
  };
  EXPECT_EQ(a.stop, StopReason::below_threshold);
  EXPECT_TRUE(same(a, b));
  EXPECT_FALSE(same(a, c));
}

TEST(Annealing, RejectsBadInput) {
  auto with = [](const std::function<void(AnnealingParams&)>& change) {
    AnnealingParams p;
    change(p);
    return p;
  };
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.beta = -0.1; })), BadInput);
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.threshold_deg = 0.0; })), BadInput);
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.max_trials = 0; })), BadInput);
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.period_set = {}; })), BadInput);
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.period_set = {4, 4}; })), BadInput);
  EXPECT_THROW(validate(with([](AnnealingParams& p) { p.period_set = {4, 10}; })), BadInput);
  const AnnealingParams ok;
  EXPECT_NO_THROW(validate(ok));
  EXPECT_THROW(start_annealing(ok, kAllFour, {0, 1, 2, 3, 4, 5}, 30.0, 1), BadInput);
  EXPECT_THROW(start_annealing(ok, kAllFour, {6}, 30.0, 1), BadInput);
  EXPECT_THROW(start_annealing(ok, Periods(kHexLegs, 7), {kR1}, 30.0, 1), BadInput);
}

TEST(Annealing, DrawsAreInRangeAndUniform) {
  std::mt19937_64 rng(12);
  constexpr int kDraws = 50000;
  constexpr std::uint64_t kBins = 5;
  std::vector<int> counts(kBins, 0);
  for (int i = 0; i < kDraws; ++i) {
    const std::uint64_t k = draw_below(rng, kBins);
    ASSERT_LT(k, kBins);
    ++counts[k];
    const double u = draw_unit(rng);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  for (int c : counts) EXPECT_NEAR(c, kDraws / kBins, kDraws / kBins / 20);
  EXPECT_EQ(draw_below(rng, 1), 0u);
  // mt19937_64 is fixed by the standard, so these are the same with every library.
  std::mt19937_64 fixed(2015);
  const std::uint64_t raw = fixed();
  fixed.seed(2015);
  EXPECT_EQ(draw_unit(fixed), static_cast<double>(raw >> 11) * 0x1.0p-53);
}

}  // namespace
}  // namespace multicpg::learning
