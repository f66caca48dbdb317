// A learner that picks each trial by a model of every combination's windows
// (learning/additive_model.h): the combination most likely to hold, or the one with the lowest
// optimistic error; the model-based learners (bayes: a GP alone; prior: a GP around what other
// scenarios predict) differ only in the model's prior mean. Given several priors, it averages
// them by their evidence.
#pragma once

#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "common/limits.h"
#include "learning/additive_model.h"
#include "learning/learner.h"
#include "learning/search_space.h"

namespace multicpg::learning {

enum class Acquisition {
  pi,   // probability of improvement past the threshold: that it holds (ModelLearner::chance)
  ucb,  // lowest confidence bound of the error (upper confidence bound of its negative)
};
Acquisition parse_acquisition(std::string_view text);  // throws OptionError("acquisition")

struct ModelLearnerParams {
  AdditiveModelParams model;
  Acquisition acquisition = Acquisition::pi;
  double kappa = 2.0;  // ucb: how many sds below its predicted error a combination is scored
};

// The options of a model-based learner, as a learner's options table (learning/learners.h).
// Defaults, in degrees: a window's yaw change scatters by about 3 deg around its combination's
// mean (the landscapes' windows), one leg's period moves the mean by up to ~10 deg, the start
// turns up to ~40 deg per window (paper Fig. 8: 37.86), pairs of legs add little.
struct ModelOptions {
  std::string acquisition = "pi";
  double kappa = 2.0;
  double noise_deg = 3.0;
  double intercept_deg = 30.0;
  double effect_deg = 8.0;
  double pair_deg = 2.0;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(ModelOptions, acquisition, kappa, noise_deg,
                                                intercept_deg, effect_deg, pair_deg)
// Scales from a hundredth of a degree to a U-turn (pairs may be off: 0); kappa up to 10 sds.
inline constexpr Limits<double> kModelScaleLimits{0.01, 180.0};
inline constexpr Limits<double> kPairScaleLimits{0.0, 180.0};
inline constexpr Limits<double> kKappaLimits{0.0, 10.0};
// Throws OptionError naming the key of a value outside its range.
void validate(const ModelOptions& options);
ModelLearnerParams model_learner_params(const ModelOptions& options);

// What a model sees of a window: its yaw change, path angle and the reflex's effort scaled as
// `criterion` scales it into degrees of E.
WindowOutputs window_outputs(const body::WindowMeasure& w, const Criterion& criterion);

// A trial's forecast E as its details (TrialRecord::details) record it (learning/forecast.h): the
// median of a window's E and its band; nothing for a trial of a learner without a model.
struct ForecastE {
  double deg = 0.0;
  double low_deg = 0.0;
  double high_deg = 0.0;
};
std::optional<ForecastE> forecast_e(const nlohmann::json& details);

// One prior of a model-based learner: its GP's scales, its prior mean (as AdditiveModel's; empty:
// zero), each combination's chance, from data beside the trials, of holding on once its trial has
// held (empty: 1), and, for the prior learner's, what a loss of another number of legs counted
// for in its data (learning/prior_model.h).
struct ModelPrior {
  AdditiveModelParams scales;
  std::vector<std::vector<double>> mean;
  std::vector<double> keep;
  std::optional<double> other_size_weight;
};

// The detail of a trial of priors that say what a loss of another number of legs counted for
// (ModelPrior::other_size_weight): theirs, averaged by the priors' weights before the trial.
inline constexpr std::string_view kOtherSizeWeightKey = "other_size_weight";

class ModelLearner final : public Learner {
 public:
  // `prior_mean`: as AdditiveModel's (empty: zero). `keep[combination]`: the chance, from data
  // beside the trials (the prior's), that the combination keeps holding once its trial has held
  // (empty: 1). Throws BadInput for a start outside the space.
  ModelLearner(const LearnerSetup& setup, const ModelLearnerParams& params,
               std::vector<std::vector<double>> prior_mean = {}, std::vector<double> keep = {});
  // Several priors, averaged (Bayesian model averaging, equal odds before the first window): each
  // weighed by its evidence, the probability its model gave the windows seen so far, each window
  // before it was told (docs/learning.md "Averaged by their evidence"). `params.model` is
  // unused: each prior has its scales. Throws std::invalid_argument without a prior.
  ModelLearner(const LearnerSetup& setup, const ModelLearnerParams& params,
               std::vector<ModelPrior> priors);

  std::optional<Periods> propose() override;
  TrialRecord observe(const Measurement& measurement) override;
  StopReason stop() const override { return best_.stop(); }
  Answer answer() const override { return best_.answer(); }
  std::vector<Forecast> best_forecasts(std::size_t count) const override;

 private:
  // A prior and what the trials made of it.
  struct Component {
    AdditiveModel model;
    std::vector<double> keep;
    std::optional<double> other_size_weight;
    double log_evidence = 0.0;  // ln of the probability density it gave the windows told
  };
  using Outputs = std::array<Prediction, kOutputs>;
  // P(|x| < limit) for x ~ N(mean, sd^2 + noise^2): one window of the output is under `limit`.
  static double window_under(const Prediction& p, double limit, double noise);
  // P(x < limit): the reflex's effort, never negative, is under `limit`.
  static double effort_under(const Prediction& p, double limit, double noise);
  // The probability that one window's E is under `limit`, prior `k`'s model predicting `p`: each
  // part the criterion counts under it, the parts independent as the model has them.
  double e_under(std::size_t k, const Outputs& p, double limit) const;
  // The chance that combination `c`, whose outputs prior `k`'s model predicts `p`, holds: every
  // window of its trial under the threshold (as independent windows around its mean), then
  // holding on (its keep).
  double chance(std::size_t k, std::size_t c, const Outputs& p) const;
  double keep(std::size_t k, std::size_t c) const {
    return components_[k].keep.empty() ? 1.0 : components_[k].keep[c];
  }
  // Each prior's weight: its evidence, normalised.
  std::vector<double> weights() const;
  // Each prior's predictions of every combination.
  std::vector<Predictions> predict() const;
  // Combination `c`'s outputs over the priors by their weights `w`: their mixture's mean and sd.
  Outputs mixed(const std::vector<double>& w, const std::vector<Predictions>& p,
                std::size_t c) const;
  // The chance that combination `c` holds, over the priors by their weights `w`.
  double chance(const std::vector<double>& w, const std::vector<Predictions>& p,
                std::size_t c) const;
  // Tells every prior one window of combination `c`, after it said how likely it found it.
  void observe(std::size_t c, const WindowOutputs& window);
  // The forecast of combination `c`: over the priors by their weights `w`.
  Forecast forecast(const std::vector<double>& w, const std::vector<Predictions>& p,
                    std::size_t c) const;
  LearnerSetup setup_;
  ModelLearnerParams params_;
  SearchSpace space_;
  std::vector<Component> components_;
  std::vector<bool> tried_;
  BestSoFar best_;
  std::size_t pending_ = 0;
  // What the trial of pending_ records: its acquisition score and forecast, made by propose().
  nlohmann::json pending_details_;
};

}  // namespace multicpg::learning
