// Random search without replacement: each trial a combination drawn uniformly from those not yet
// tried, in this episode or an earlier one of the run (the paper's beta = 0 draws from one-leg
// changes only; this draws from the whole space). The baseline every other learner must beat: its
// expected trials to the first holding combination are (N + 1) / (K + 1) for K holding among N
// (docs/learning.md "Learners").
#include <memory>
#include <random>
#include <vector>

#include "common/random.h"
#include "learning/learners.h"
#include "learning/search_space.h"

namespace multicpg::learning {
namespace {

class RandomSearch final : public Learner {
 public:
  explicit RandomSearch(const LearnerSetup& setup)
      : space_(setup), tried_(space_.size(), false), untried_(space_.size() - 1), best_(setup) {
    tried_[*space_.index(setup.start)] = true;
    // What earlier episodes of the run walked is not drawn again.
    for (const EarlierTrial& t : setup.earlier) {
      const std::optional<std::size_t> c = space_.index(t.periods);
      if (c && !tried_[*c]) {
        tried_[*c] = true;
        --untried_;
      }
    }
    rng_.seed(setup.seed);
  }

  std::optional<Periods> propose() override {
    if (untried_ == 0) {
      best_.exhausted();
      return std::nullopt;
    }
    std::uint64_t k = draw_below(rng_, untried_);
    std::size_t i = 0;
    for (;; ++i) {
      if (!tried_[i] && k-- == 0) break;
    }
    tried_[i] = true;
    --untried_;
    pending_ = space_.periods(i);
    return pending_;
  }

  TrialRecord observe(const Measurement& m) override {
    const bool accepted = best_.record(pending_, m.deviation_deg);
    return {best_.trials(), pending_, m.deviation_deg, accepted, nlohmann::json::object()};
  }

  StopReason stop() const override { return best_.stop(); }
  Answer answer() const override { return best_.answer(); }

 private:
  SearchSpace space_;
  std::vector<bool> tried_;
  std::uint64_t untried_;
  BestSoFar best_;
  std::mt19937_64 rng_;
  Periods pending_;
};

}  // namespace

nlohmann::json random_options(const nlohmann::json& asked) {
  return read_learner_options<NoLearnerOptions>(asked);
}

std::unique_ptr<Learner> make_random(const LearnerSetup& setup, const nlohmann::json&,
                                     const LearnerData&) {
  return std::make_unique<RandomSearch>(setup);
}

}  // namespace multicpg::learning
