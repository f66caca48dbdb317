// A learner that picks each trial by a model of every combination's windows
// (learning/additive_model.h): the combination most likely to hold, or the one with the lowest
// optimistic error; the model-based learners (bayes: a GP alone; prior: a GP around what other
// scenarios predict) differ only in the model's prior mean.
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

class ModelLearner final : public Learner {
 public:
  // `prior_mean`: as AdditiveModel's (empty: zero). `keep[combination]`: the chance, from data
  // beside the trials (the prior's), that the combination keeps holding once its trial has held
  // (empty: 1). Throws BadInput for a start outside the space.
  ModelLearner(const LearnerSetup& setup, const ModelLearnerParams& params,
               std::vector<std::vector<double>> prior_mean = {}, std::vector<double> keep = {});

  std::optional<Periods> propose() override;
  TrialRecord observe(const Measurement& measurement) override;
  StopReason stop() const override { return best_.stop(); }
  Answer answer() const override { return best_.answer(); }
  std::vector<Forecast> best_forecasts(std::size_t count) const override;

 private:
  // P(|x| < limit) for x ~ N(mean, sd^2 + noise^2): one window of the output is under `limit`.
  double window_under(const Prediction& p, double limit) const;
  // P(x < limit): the reflex's effort, never negative, is under `limit`.
  double effort_under(const Prediction& p, double limit) const;
  // The probability that one window's E is under `limit`: each part the criterion counts under
  // it, the parts independent as the model has them.
  double e_under(const std::array<Prediction, kOutputs>& p, double limit) const;
  // The chance that combination `c`, whose outputs the model predicts `p`, holds: every window of
  // its trial under the threshold (as independent windows around its mean), then holding on
  // (keep_).
  double chance(std::size_t c, const std::array<Prediction, kOutputs>& p) const;
  double keep(std::size_t c) const { return keep_.empty() ? 1.0 : keep_[c]; }
  // The forecast of combination `c` whose outputs the model predicts `p`.
  Forecast forecast(std::size_t c, const std::array<Prediction, kOutputs>& p) const;
  LearnerSetup setup_;
  ModelLearnerParams params_;
  SearchSpace space_;
  AdditiveModel model_;
  std::vector<double> keep_;
  std::vector<bool> tried_;
  BestSoFar best_;
  std::size_t pending_ = 0;
  // What the trial of pending_ records: its acquisition score and forecast, made by propose().
  nlohmann::json pending_details_;
};

}  // namespace multicpg::learning
