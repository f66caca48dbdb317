// Greedy search over one-leg changes: each trial changes one working leg of the best combination
// so far (drawn uniformly among the untried one-leg changes) and moves there when it measures
// better. When every one-leg change of the best has been tried it changes two legs, then three,
// as the paper's annealing escalates (paper §3, docs/learning.md "The search"); the annealing at
// beta -> infinity, without its acceptance draws.
#include <memory>
#include <random>
#include <vector>

#include "common/random.h"
#include "learning/learners.h"
#include "learning/search_space.h"

namespace multicpg::learning {
namespace {

class Greedy final : public Learner {
 public:
  explicit Greedy(const LearnerSetup& setup)
      : space_(setup), tried_(space_.size(), false), best_(setup), at_(*space_.index(setup.start)) {
    tried_[at_] = true;
    for (const EarlierTrial& t : setup.earlier) {
      if (const std::optional<std::size_t> i = space_.index(t.periods)) tried_[*i] = true;
    }
    rng_.seed(setup.seed);
  }

  std::optional<Periods> propose() override {
    // The untried combinations at the smallest distance from the best that has any.
    std::vector<std::size_t> nearest;
    std::size_t level = space_.working().size() + 1;
    for (std::size_t i = 0; i < space_.size(); ++i) {
      if (tried_[i]) continue;
      const std::size_t d = space_.distance(i, at_);
      if (d < level) {
        level = d;
        nearest.clear();
      }
      if (d == level) nearest.push_back(i);
    }
    if (nearest.empty()) {
      best_.exhausted();
      return std::nullopt;
    }
    pending_ = nearest[draw_below(rng_, nearest.size())];
    tried_[pending_] = true;
    legs_changed_ = static_cast<int>(level);
    return space_.periods(pending_);
  }

  TrialRecord observe(const Measurement& m) override {
    const Periods periods = space_.periods(pending_);
    const bool accepted = best_.record(periods, m.deviation_deg);
    if (accepted) at_ = pending_;
    return {best_.trials(), periods, m.deviation_deg, accepted, {{"legs_changed", legs_changed_}}};
  }

  StopReason stop() const override { return best_.stop(); }
  Answer answer() const override { return best_.answer(); }

 private:
  SearchSpace space_;
  std::vector<bool> tried_;
  BestSoFar best_;
  std::size_t at_;  // the best combination's index
  std::mt19937_64 rng_;
  std::size_t pending_ = 0;
  int legs_changed_ = 1;
};

}  // namespace

nlohmann::json greedy_options(const nlohmann::json& asked) {
  return read_learner_options<NoLearnerOptions>(asked);
}

std::unique_ptr<Learner> make_greedy(const LearnerSetup& setup, const nlohmann::json&,
                                     const LearnerData&) {
  return std::make_unique<Greedy>(setup);
}

}  // namespace multicpg::learning
