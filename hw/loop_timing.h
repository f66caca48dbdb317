// How well a control loop kept its rate: the period between consecutive steps' commands, its
// jitter against the target period and the steps that overran (docs/hardware.md "Timing").
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "hw/serial_port.h"

namespace multicpg::hw {

struct LoopTiming {
  long steps = 0;
  double target_period_s = 0.0;  // 0: lock-step, no target
  double period_mean_s = 0.0;
  double period_max_s = 0.0;
  // The 99th percentile of |period - target| (lock-step: of |period - mean|).
  double jitter_p99_s = 0.0;
  double jitter_max_s = 0.0;
  // Steps that started late: the work of the step before ran past its slot.
  long overruns = 0;
  double exchange_mean_s = 0.0;  // command sent to last answer read
  double exchange_max_s = 0.0;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LoopTiming, steps, target_period_s, period_mean_s, period_max_s,
                                   jitter_p99_s, jitter_max_s, overruns, exchange_mean_s,
                                   exchange_max_s)

// Paces a loop at a fixed period on the monotonic clock (or not at all, lock-step) and records
// when each step's command went out and how long its exchange took.
class LoopClock {
 public:
  explicit LoopClock(double period_s);  // 0: lock-step
  // Waits until the next step is due (real time) and returns when it starts.
  Clock::time_point wait_for_slot();
  // The step's exchange ended now.
  void exchanged();
  LoopTiming timing() const;

 private:
  double period_s_;
  Clock::time_point due_{};
  bool started_ = false;
  std::vector<double> starts_;  // s
  std::vector<double> exchanges_;
  long overruns_ = 0;
  Clock::time_point last_start_{};
};

}  // namespace multicpg::hw
