// Gaussian-process Bayesian optimisation over the period grid (docs/learning.md "Learners"): a GP
// of each window's yaw change and path angle (learning/additive_model.h) learned from the trials
// alone, each trial the untried combination the acquisition scores best: the probability that a
// window of it holds (pi, the default), or the lowest confidence bound of its error (ucb).
#include <memory>

#include "learning/learners.h"
#include "learning/model_learner.h"

namespace multicpg::learning {

nlohmann::json bayes_options(const nlohmann::json& asked) {
  return read_learner_options<ModelOptions>(asked);
}

std::unique_ptr<Learner> make_bayes(const LearnerSetup& setup, const nlohmann::json& options,
                                    const LearnerData&) {
  return std::make_unique<ModelLearner>(setup, model_learner_params(options.get<ModelOptions>()));
}

}  // namespace multicpg::learning
