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
  for (const body::WindowMeasure& w : setup.start_windows) model_.observe(start, outputs(w));
}

WindowOutputs ModelLearner::outputs(const body::WindowMeasure& w) const {
  return {w.yaw_deg, w.path_deg, setup_.criterion.effort_deg(w.steering_effort)};
}

double ModelLearner::window_holds(const Prediction& p) const {
  const double sd = std::sqrt(p.sd * p.sd + params_.model.noise_deg * params_.model.noise_deg);
  const double t = setup_.search.threshold_deg;
  const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  return cdf((t - p.mean) / sd) - cdf((-t - p.mean) / sd);
}

double ModelLearner::effort_holds(const Prediction& p) const {
  // The effort is never negative: only its upper side can fail.
  const double sd = std::sqrt(p.sd * p.sd + params_.model.noise_deg * params_.model.noise_deg);
  return 0.5 * std::erfc(-(setup_.search.threshold_deg - p.mean) / sd / std::sqrt(2.0));
}

std::optional<Periods> ModelLearner::propose() {
  Predictions predicted;
  model_.predict(predicted);
  const Criterion& judge = setup_.criterion;
  double best_score = -std::numeric_limits<double>::infinity();
  bool found = false;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    if (tried_[c]) continue;
    const Prediction& yaw = predicted[kYaw][c];
    const Prediction& path = predicted[kPath][c];
    const Prediction& effort = predicted[kEffort][c];
    double score = 0.0;
    if (params_.acquisition == Acquisition::pi) {
      score = window_holds(yaw) * (judge.path ? window_holds(path) : 1.0);
      if (judge.steers()) score *= effort_holds(effort);
    } else {
      double error = std::abs(yaw.mean);
      if (judge.path) error = std::max(error, std::abs(path.mean));
      if (judge.steers()) error = std::max(error, effort.mean);
      score = -(error - params_.kappa * yaw.sd);
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
  for (const body::WindowMeasure& w : m.windows) model_.observe(pending_, outputs(w));
  const Periods periods = space_.periods(pending_);
  const bool accepted = best_.record(periods, m.deviation_deg);
  return {best_.trials(), periods, m.deviation_deg, accepted, {{"acquisition", pending_score_}}};
}

}  // namespace multicpg::learning
