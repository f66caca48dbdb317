// Post-processed CPG output: a sawtooth of period p(2p+1) rising for 1/p of it (docs/controller.md
// "Post-processing").
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "neural/controller.h"

namespace {

using namespace multicpg;

// Long enough for every period to lock exactly (p = 4 is slowest, step 737: docs/controller.md
// "Steps to lock, from reset").
constexpr long kLockSteps = 3000;

std::vector<double> ramp(int period, long steps) {
  const auto model = neural::make_controller_model(robot::RobotKind::hexapod);
  auto state = neural::make_controller_state(model, period);
  for (long t = 0; t < kLockSteps; ++t) neural::controller_step(model, state);
  std::vector<double> y1;
  for (long t = 0; t < steps; ++t) {
    neural::controller_step(model, state);
    y1.push_back(state.legs[0].post.y1);
  }
  return y1;
}

// Smallest exact (bit for bit) period of the sequence.
long smallest_period(const std::vector<double>& y) {
  for (std::size_t p = 1; p < y.size() / 2; ++p) {
    bool ok = true;
    for (std::size_t i = p; i < y.size() && ok; ++i) ok = y[i] == y[i - p];
    if (ok) return static_cast<long>(p);
  }
  return 0;
}

class PostProcessing : public ::testing::TestWithParam<int> {};

TEST_P(PostProcessing, SawtoothPeriodAndSwingFraction) {
  const int p = GetParam();
  const long cycle = static_cast<long>(p) * (2 * p + 1);
  const std::vector<double> y1 = ramp(p, 4 * cycle);
  EXPECT_EQ(smallest_period(y1), cycle);

  long rising = 0;
  for (long t = 1; t <= cycle; ++t) rising += y1[t] > y1[t - 1] ? 1 : 0;
  EXPECT_EQ(rising * p, cycle) << "swing (rising) fraction must be exactly 1/p";
  EXPECT_EQ(rising, 2 * p + 1) << "the rise lasts one window N = 2p+1";
}

INSTANTIATE_TEST_SUITE_P(GaitPeriods, PostProcessing, ::testing::Values(4, 5, 6, 8, 9));

TEST(PostProcessing, LocksAtTheReferenceSteps) {
  // docs/controller.md "Steps to lock, from reset": from reset (x = 0) the post-processed output is
  // exactly periodic from these steps on (counted from 0, step t = the output after t + 1 updates).
  for (const int p : {4, 5, 6, 8, 9}) {
    const long expected = neural::lock_steps(p);
    const auto model = neural::make_controller_model(robot::RobotKind::hexapod);
    auto state = neural::make_controller_state(model, p);
    std::vector<double> y1;
    for (long t = 0; t < kLockSteps; ++t) {
      neural::controller_step(model, state);
      y1.push_back(state.legs[0].post.y1);
    }
    const long cycle = static_cast<long>(p) * (2 * p + 1);
    long first_repeat = 0;  // first t with y1[t'] == y1[t' - cycle] for every t' >= t
    for (long t = static_cast<long>(y1.size()) - 1; t >= cycle; --t) {
      if (y1[t] != y1[t - cycle]) {
        first_repeat = t + 1;
        break;
      }
    }
    EXPECT_EQ(first_repeat - cycle, expected) << "period " << p;
  }
}

TEST(PostProcessing, PeriodOneHoldsConstant) {
  const std::vector<double> y1 = ramp(1, 100);
  for (double y : y1) EXPECT_EQ(y, 1.0);  // docs/controller.md "Period 1: stop"
}

}  // namespace
