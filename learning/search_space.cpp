#include "learning/search_space.h"

#include <algorithm>
#include <string>

#include "body/deviation.h"
#include "common/errors.h"

namespace multicpg::learning {

SearchSpace::SearchSpace(const LearnerSetup& setup)
    : start_(setup.start), working_(setup.working()), period_set_(setup.search.period_set) {
  if (working_.empty()) throw BadInput("every leg is disabled: there is nothing to learn");
  for (std::size_t i = 0; i < working_.size(); ++i) size_ *= period_set_.size();
  if (!index(start_)) {
    throw BadInput("a working leg starts at a period that is not in the period set");
  }
}

Periods SearchSpace::periods(std::size_t index) const {
  Periods out = start_;
  const std::size_t q = period_set_.size();
  for (std::size_t i = working_.size(); i-- > 0;) {
    out[working_[i]] = period_set_[index % q];
    index /= q;
  }
  return out;
}

std::optional<std::size_t> SearchSpace::index(const Periods& periods) const {
  std::size_t out = 0;
  for (std::size_t leg : working_) {
    const auto it = std::find(period_set_.begin(), period_set_.end(), periods.at(leg));
    if (it == period_set_.end()) return std::nullopt;
    out = out * period_set_.size() + static_cast<std::size_t>(it - period_set_.begin());
  }
  return out;
}

std::size_t SearchSpace::digit(std::size_t index, std::size_t i) const {
  const std::size_t q = period_set_.size();
  for (std::size_t k = working_.size() - 1; k > i; --k) index /= q;
  return index % q;
}

std::size_t SearchSpace::distance(std::size_t a, std::size_t b) const {
  std::size_t d = 0;
  const std::size_t q = period_set_.size();
  for (std::size_t i = 0; i < working_.size(); ++i) {
    d += (a % q) != (b % q) ? 1 : 0;
    a /= q;
    b /= q;
  }
  return d;
}

BestSoFar::BestSoFar(const LearnerSetup& setup)
    : threshold_deg_(setup.search.threshold_deg),
      max_trials_(setup.search.max_trials),
      answer_{setup.start, setup.start_deviation_deg} {
  if (body::holds(setup.start_deviation_deg, threshold_deg_)) stop_ = StopReason::below_threshold;
}

bool BestSoFar::record(const Periods& periods, double deviation_deg) {
  ++trials_;
  const bool better = deviation_deg < answer_.deviation_deg;
  if (better) answer_ = {periods, deviation_deg};
  if (body::holds(deviation_deg, threshold_deg_)) {
    stop_ = StopReason::below_threshold;
  } else if (trials_ >= max_trials_) {
    stop_ = StopReason::trial_cap;
  }
  return better;
}

}  // namespace multicpg::learning
