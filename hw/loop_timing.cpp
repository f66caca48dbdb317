#include "hw/loop_timing.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>

namespace multicpg::hw {
namespace {

constexpr double kPercentile = 0.99;

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size()))) - 1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

LoopClock::LoopClock(double period_s) : period_s_(period_s) {}

Clock::time_point LoopClock::wait_for_slot() {
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s_));
  Clock::time_point now = Clock::now();
  if (period_s_ > 0.0) {
    if (!started_) {
      due_ = now;
    } else if (now > due_) {
      // The last step overran: start now and keep the rate from here, never a burst to catch up.
      ++overruns_;
      due_ = now;
    } else {
      std::this_thread::sleep_until(due_);
      now = Clock::now();
    }
  }
  started_ = true;
  last_start_ = now;
  starts_.push_back(monotonic_s(now));
  due_ += period;
  return now;
}

void LoopClock::exchanged() {
  exchanges_.push_back(std::chrono::duration<double>(Clock::now() - last_start_).count());
}

LoopTiming LoopClock::timing() const {
  LoopTiming t;
  t.steps = static_cast<long>(starts_.size());
  t.target_period_s = period_s_;
  t.overruns = overruns_;
  if (!exchanges_.empty()) {
    t.exchange_mean_s = std::accumulate(exchanges_.begin(), exchanges_.end(), 0.0) /
                        static_cast<double>(exchanges_.size());
    t.exchange_max_s = *std::max_element(exchanges_.begin(), exchanges_.end());
  }
  if (starts_.size() < 2) return t;
  std::vector<double> periods(starts_.size() - 1);
  for (std::size_t i = 1; i < starts_.size(); ++i) periods[i - 1] = starts_[i] - starts_[i - 1];
  t.period_mean_s = (starts_.back() - starts_.front()) / static_cast<double>(periods.size());
  t.period_max_s = *std::max_element(periods.begin(), periods.end());
  const double target = period_s_ > 0.0 ? period_s_ : t.period_mean_s;
  std::vector<double> jitter(periods.size());
  std::transform(periods.begin(), periods.end(), jitter.begin(),
                 [target](double p) { return std::abs(p - target); });
  t.jitter_max_s = *std::max_element(jitter.begin(), jitter.end());
  t.jitter_p99_s = percentile(std::move(jitter), kPercentile);
  return t;
}

}  // namespace multicpg::hw
