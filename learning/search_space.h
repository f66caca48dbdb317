// The combinations a learner searches (paper Table 2 step 2): every period of the set on every
// working leg, the failed legs keeping their start period. Numbered 0..size()-1 as an odometer
// whose first working leg varies slowest, the order of a landscape (experiments/landscape.h).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "learning/learner.h"

namespace multicpg::learning {

class SearchSpace {
 public:
  // Throws BadInput when the setup's start is not in the space (a working leg's period outside
  // the period set) or no leg works.
  explicit SearchSpace(const LearnerSetup& setup);

  std::size_t size() const { return size_; }
  const std::vector<std::size_t>& working() const { return working_; }
  const std::vector<int>& period_set() const { return period_set_; }
  Periods periods(std::size_t index) const;
  // Nothing when a working leg's period is not in the set.
  std::optional<std::size_t> index(const Periods& periods) const;
  // The position in the period set of working leg `i`'s period in combination `index`.
  std::size_t digit(std::size_t index, std::size_t i) const;
  // Working legs whose periods differ between two combinations.
  std::size_t distance(std::size_t a, std::size_t b) const;

 private:
  Periods start_;
  std::vector<std::size_t> working_;
  std::vector<int> period_set_;
  std::size_t size_ = 1;
};

// The bookkeeping of a learner whose answer is the best combination it measured: trials, the
// answer, and the stop every learner shares (held under the threshold, or the trial cap).
class BestSoFar {
 public:
  explicit BestSoFar(const LearnerSetup& setup);
  // Counts a trial; returns whether it became the answer (E below the answer's).
  bool record(const Periods& periods, double deviation_deg);
  int trials() const { return trials_; }
  StopReason stop() const { return stop_; }
  void exhausted() { stop_ = StopReason::space_exhausted; }
  const Answer& answer() const { return answer_; }

 private:
  double threshold_deg_;
  int max_trials_;
  int trials_ = 0;
  StopReason stop_ = StopReason::running;
  Answer answer_;
};

}  // namespace multicpg::learning
