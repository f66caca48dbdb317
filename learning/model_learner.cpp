#include "learning/model_learner.h"

#include <cmath>
#include <limits>
#include <string>

#include "common/errors.h"

namespace multicpg::learning {

std::string_view to_string(Acquisition a) {
  return a == Acquisition::pi ? "pi" : "ucb";
}

Acquisition parse_acquisition(std::string_view text) {
  if (text == "pi") return Acquisition::pi;
  if (text == "ucb") return Acquisition::ucb;
  throw OptionError("acquisition", "must be \"pi\" or \"ucb\", got \"" + std::string(text) + "\"");
}

void validate(const ModelOptions& o) {
  parse_acquisition(o.acquisition);
  require_in("kappa", o.kappa, kKappaLimits);
  require_in("noise_deg", o.noise_deg, kModelScaleLimits);
  require_in("intercept_deg", o.intercept_deg, kModelScaleLimits);
  require_in("effect_deg", o.effect_deg, kModelScaleLimits);
  require_in("pair_deg", o.pair_deg, kPairScaleLimits);
}

ModelLearnerParams model_learner_params(const ModelOptions& o) {
  return {{o.noise_deg, o.intercept_deg, o.effect_deg, o.pair_deg},
          parse_acquisition(o.acquisition),
          o.kappa};
}

ModelLearner::ModelLearner(const LearnerSetup& setup, const ModelLearnerParams& params,
                           std::vector<std::vector<double>> prior_mean)
    : setup_(setup),
      params_(params),
      space_(setup),
      model_(space_, params.model, std::move(prior_mean)),
      tried_(space_.size(), false),
      best_(setup) {
  const std::size_t start = *space_.index(setup.start);
  tried_[start] = true;
  for (const sim::WindowMeasure& w : setup.start_windows)
    model_.observe(start, w.yaw_deg, w.path_deg);
}

double ModelLearner::window_holds(const Prediction& p) const {
  const double sd = std::sqrt(p.sd * p.sd + params_.model.noise_deg * params_.model.noise_deg);
  const double t = setup_.search.threshold_deg;
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  return cdf((t - p.mean) / sd) - cdf((-t - p.mean) / sd);
}

std::optional<Periods> ModelLearner::propose() {
  std::vector<Prediction> yaw;
  std::vector<Prediction> path;
  model_.predict(yaw, path);
  double best_score = -std::numeric_limits<double>::infinity();
  bool found = false;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    if (tried_[c]) continue;
    double score = 0.0;
    if (params_.acquisition == Acquisition::pi) {
      score = window_holds(yaw[c]) * (setup_.yaw_only ? 1.0 : window_holds(path[c]));
    } else {
      double error = std::abs(yaw[c].mean);
      if (!setup_.yaw_only) error = std::max(error, std::abs(path[c].mean));
      score = -(error - params_.kappa * yaw[c].sd);
    }
    // Ties go to the first combination in order: deterministic without a draw.
    if (score > best_score) {
      best_score = score;
      pending_ = c;
      found = true;
    }
  }
  if (!found) {
    best_.exhausted();
    return std::nullopt;
  }
  pending_score_ = best_score;
  tried_[pending_] = true;
  return space_.periods(pending_);
}

TrialRecord ModelLearner::observe(const Measurement& m) {
  for (const sim::WindowMeasure& w : m.windows) model_.observe(pending_, w.yaw_deg, w.path_deg);
  const Periods periods = space_.periods(pending_);
  const bool accepted = best_.record(periods, m.deviation_deg);
  return {best_.trials(), periods, m.deviation_deg, accepted, {{"acquisition", pending_score_}}};
}

}  // namespace multicpg::learning
