// The paper's simulated annealing (learning/annealing.h) as a learner (learning/learner.h), in
// both modes.
#include <memory>
#include <optional>

#include "learning/annealing.h"
#include "learning/learner.h"
#include "learning/learners.h"

namespace multicpg::learning {
namespace {

// The annealing's one option: beta (paper §3, Fig. 14), the CLI's --beta and the experiment
// files' learning.annealing.beta.
struct AnnealingOptions {
  double beta = kDefaultBeta;
  bool operator==(const AnnealingOptions&) const = default;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(AnnealingOptions, beta)

void validate(const AnnealingOptions& o) {
  require_in("beta", o.beta, kBetaLimits);
}

class AnnealingLearner final : public Learner {
 public:
  AnnealingLearner(const LearnerSetup& setup, double beta)
      : params_(annealing_params(setup.search, beta)),
        state_(start_annealing(params_, setup.start, setup.told.failed(), setup.start_deviation_deg,
                               setup.seed)) {
    for (const EarlierTrial& t : setup.earlier) state_.tried.insert(t.periods);
  }

  std::optional<Periods> propose() override {
    const std::optional<Candidate> candidate = learning::propose(params_, state_);
    if (!candidate) return std::nullopt;
    return candidate->periods;
  }

  TrialRecord observe(const Measurement& measurement) override {
    decide(params_, state_, measurement.deviation_deg);
    const AnnealingTrial& t = state_.trace.back();
    return {t.trial,
            t.periods,
            t.deviation_deg,
            t.accepted,
            {{"acceptance_probability", t.acceptance_probability},
             {"legs_changed", t.legs_changed},
             {"redraws", t.redraws},
             {"tabu_redraw", t.redraws > 0}}};
  }

  StopReason stop() const override { return state_.stop; }
  Answer answer() const override { return {state_.accepted, state_.e_ref}; }

 private:
  AnnealingParams params_;
  AnnealingState state_;
};

}  // namespace

nlohmann::json annealing_options(const nlohmann::json& asked) {
  return read_learner_options<AnnealingOptions>(asked);
}

std::unique_ptr<Learner> make_annealing(const LearnerSetup& setup, const nlohmann::json& options,
                                        const LearnerData&) {
  return std::make_unique<AnnealingLearner>(setup, options.get<AnnealingOptions>().beta);
}

}  // namespace multicpg::learning
