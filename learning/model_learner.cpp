#include "learning/model_learner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/enum_names.h"
#include "common/errors.h"

namespace multicpg::learning {

namespace {

constexpr auto kAcquisitionNames =
    enum_names<Acquisition>({{Acquisition::pi, "pi"}, {Acquisition::ucb, "ucb"}});

}  // namespace

Acquisition parse_acquisition(std::string_view text) {
  if (const std::optional<Acquisition> a = kAcquisitionNames.find(text)) return *a;
  throw OptionError("acquisition", "must be " + kAcquisitionNames.list(" or ") + ", got \"" +
                                       std::string(text) + "\"");
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
                           std::vector<std::vector<double>> prior_mean, std::vector<double> keep)
    : ModelLearner(setup, params,
                   {ModelPrior{params.model, std::move(prior_mean), std::move(keep), {}}}) {}

ModelLearner::ModelLearner(const LearnerSetup& setup, const ModelLearnerParams& params,
                           std::vector<ModelPrior> priors)
    : setup_(setup), params_(params), space_(setup), tried_(space_.size(), false), best_(setup) {
  if (priors.empty()) throw std::invalid_argument("ModelLearner: no prior");
  components_.reserve(priors.size());
  for (ModelPrior& p : priors) {
    if (!p.keep.empty() && p.keep.size() != space_.size()) {
      throw std::invalid_argument("ModelLearner: keep has " + std::to_string(p.keep.size()) +
                                  " chances for " + std::to_string(space_.size()) +
                                  " combinations");
    }
    components_.push_back({AdditiveModel(space_, p.scales, std::move(p.mean)), std::move(p.keep),
                           p.other_size_weight});
  }
  const std::size_t start = *space_.index(setup.start);
  tried_[start] = true;
  for (const body::WindowMeasure& w : setup.start_windows)
    observe(start, window_outputs(w, setup_.criterion));
  for (const EarlierTrial& t : setup.earlier) {
    const std::optional<std::size_t> c = space_.index(t.periods);
    if (!c) continue;  // a combination outside this episode's space tells it nothing
    tried_[*c] = true;
    for (const body::WindowMeasure& w : t.windows) observe(*c, window_outputs(w, setup_.criterion));
  }
}

WindowOutputs window_outputs(const body::WindowMeasure& w, const Criterion& criterion) {
  return {w.yaw_deg, w.path_deg, criterion.effort_deg(w.steering_effort)};
}

std::optional<ForecastE> forecast_e(const nlohmann::json& details) {
  const auto number = [&](std::string_view key) -> std::optional<double> {
    const auto it = details.find(key);
    if (it == details.end() || !it->is_number()) return std::nullopt;
    return it->get<double>();
  };
  const std::optional<double> e = number(kPredictedEKey);
  const std::optional<double> low = number(kPredictedELowKey);
  const std::optional<double> high = number(kPredictedEHighKey);
  if (!e || !low || !high) return std::nullopt;
  return ForecastE{*e, *low, *high};
}

namespace {

// Halvings of the bracket of a quantile of E: 64 leave it within 2^-64 of its width, below a
// double's resolution of the bracket's end.
constexpr int kQuantileHalvings = 64;
// A window's E is below the largest |mean| of its parts plus this many sds with probability 1 to a
// double's resolution (a normal's tail beyond 10 sd is 8e-24).
constexpr double kQuantileBracketSds = 10.0;

double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

}  // namespace

double ModelLearner::window_under(const Prediction& p, double limit, double noise) {
  const double sd = std::sqrt(p.sd * p.sd + noise * noise);
  return normal_cdf((limit - p.mean) / sd) - normal_cdf((-limit - p.mean) / sd);
}

double ModelLearner::effort_under(const Prediction& p, double limit, double noise) {
  // The effort is never negative: only its upper side can fail.
  const double sd = std::sqrt(p.sd * p.sd + noise * noise);
  return normal_cdf((limit - p.mean) / sd);
}

double ModelLearner::e_under(std::size_t k, const Outputs& p, double limit) const {
  const Criterion& judge = setup_.criterion;
  const double noise = components_[k].model.noise_deg();
  double share = window_under(p[kYaw], limit, noise) *
                 (judge.path ? window_under(p[kPath], limit, noise) : 1.0);
  if (judge.steers()) share *= effort_under(p[kEffort], limit, noise);
  return share;
}

double ModelLearner::chance(std::size_t k, std::size_t c, const Outputs& p) const {
  return std::pow(e_under(k, p, setup_.search.threshold_deg), setup_.criterion.trial_windows) *
         keep(k, c);
}

std::vector<double> ModelLearner::weights() const {
  double top = -std::numeric_limits<double>::infinity();
  for (const Component& k : components_) top = std::max(top, k.log_evidence);
  std::vector<double> w;
  double sum = 0.0;
  for (const Component& k : components_) {
    w.push_back(std::exp(k.log_evidence - top));
    sum += w.back();
  }
  for (double& x : w) x /= sum;
  return w;
}

std::vector<Predictions> ModelLearner::predict() const {
  std::vector<Predictions> out(components_.size());
  for (std::size_t k = 0; k < components_.size(); ++k) components_[k].model.predict(out[k]);
  return out;
}

namespace {

std::array<Prediction, kOutputs> outputs(const Predictions& p, std::size_t c) {
  return {p[kYaw][c], p[kPath][c], p[kEffort][c]};
}

}  // namespace

ModelLearner::Outputs ModelLearner::mixed(const std::vector<double>& w,
                                          const std::vector<Predictions>& pk, std::size_t c) const {
  // One prior's own sd, not one through its square's rounding.
  if (components_.size() == 1) return outputs(pk[0], c);
  Outputs p;
  for (std::size_t o = 0; o < kOutputs; ++o) {
    double mean = 0.0;
    double second = 0.0;
    for (std::size_t k = 0; k < components_.size(); ++k) {
      const Prediction& x = pk[k][o][c];
      mean += w[k] * x.mean;
      second += w[k] * (x.sd * x.sd + x.mean * x.mean);
    }
    p[o] = {mean, std::sqrt(std::max(second - mean * mean, 0.0))};
  }
  return p;
}

double ModelLearner::chance(const std::vector<double>& w, const std::vector<Predictions>& p,
                            std::size_t c) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < components_.size(); ++k) sum += w[k] * chance(k, c, outputs(p[k], c));
  return sum;
}

void ModelLearner::observe(std::size_t c, const WindowOutputs& window) {
  const Criterion& judge = setup_.criterion;
  for (Component& k : components_) {
    if (components_.size() > 1) {
      // The window's density under the model before it is told: the outputs the criterion
      // counts, independent as the model has them.
      const Outputs p = k.model.predict(c);
      const double noise = k.model.noise_deg();
      const auto log_density = [&](std::size_t o) {
        const double var = p[o].sd * p[o].sd + noise * noise;
        const double z = window[o] - p[o].mean;
        return -0.5 * (z * z / var + std::log(2.0 * std::numbers::pi * var));
      };
      k.log_evidence += log_density(kYaw);
      if (judge.path) k.log_evidence += log_density(kPath);
      if (judge.steers()) k.log_evidence += log_density(kEffort);
    }
    k.model.observe(c, window);
  }
}

Forecast ModelLearner::forecast(const std::vector<double>& w, const std::vector<Predictions>& pk,
                                std::size_t c) const {
  const std::size_t n = components_.size();
  const Outputs p = mixed(w, pk, c);
  Forecast f{space_.periods(c), tried_[c], p[kYaw], p[kPath], p[kEffort]};
  // One prior's weight is 1: these are its own numbers, exactly.
  f.keep = 0.0;
  for (std::size_t k = 0; k < n; ++k) f.keep += w[k] * keep(k, c);
  f.hold = chance(w, pk, c);
  const auto under = [&](double limit) {
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) sum += w[k] * e_under(k, outputs(pk[k], c), limit);
    return sum;
  };
  // The quantiles of E by bisection: its distribution is a product of normal CDFs (a mixture of
  // them over the priors), with no inverse in closed form.
  double top = 0.0;
  double sd = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Prediction& yaw = pk[k][kYaw][c];
    const double noise = components_[k].model.noise_deg();
    sd = std::max(sd, std::sqrt(yaw.sd * yaw.sd + noise * noise));
    top = std::max(top, std::abs(yaw.mean));
    if (setup_.criterion.path) top = std::max(top, std::abs(pk[k][kPath][c].mean));
    if (setup_.criterion.steers()) top = std::max(top, pk[k][kEffort][c].mean);
  }
  const auto quantile = [&](double q) {
    double lo = 0.0;
    double hi = top + kQuantileBracketSds * sd;
    for (int i = 0; i < kQuantileHalvings; ++i) {
      const double mid = 0.5 * (lo + hi);
      (under(mid) < q ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  f.e_deg = quantile(0.5);
  f.e_low_deg = quantile(kBandLowQuantile);
  f.e_high_deg = quantile(kBandHighQuantile);
  return f;
}

std::optional<Periods> ModelLearner::propose() {
  const std::vector<Predictions> predicted = predict();
  const std::vector<double> w = weights();
  const Criterion& judge = setup_.criterion;
  double best_score = -std::numeric_limits<double>::infinity();
  bool found = false;
  std::size_t untried = 0;
  std::size_t may_hold = 0;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    if (tried_[c]) continue;
    const double hold = chance(w, predicted, c);
    ++untried;
    if (hold >= kMayHoldLevel) ++may_hold;
    double score = hold;
    if (params_.acquisition == Acquisition::ucb) {
      const Outputs p = mixed(w, predicted, c);
      double error = std::abs(p[kYaw].mean);
      if (judge.path) error = std::max(error, std::abs(p[kPath].mean));
      if (judge.steers()) error = std::max(error, p[kEffort].mean);
      score = -(error - params_.kappa * p[kYaw].sd);
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
  const Forecast f = forecast(w, predicted, pending_);
  nlohmann::json& d = pending_details_;
  d = {{"acquisition", best_score}};
  d[kPredictedYawKey] = f.yaw.mean;
  d[kPredictedYawSdKey] = f.yaw.sd;
  d[kPredictedPathKey] = f.path.mean;
  d[kPredictedPathSdKey] = f.path.sd;
  if (judge.steers()) {
    d[kPredictedEffortKey] = f.effort.mean;
    d[kPredictedEffortSdKey] = f.effort.sd;
  }
  d[kPredictedHoldKey] = f.hold;
  d[kPredictedKeepKey] = f.keep;
  d[kPredictedEKey] = f.e_deg;
  d[kPredictedELowKey] = f.e_low_deg;
  d[kPredictedEHighKey] = f.e_high_deg;
  d[kMayHoldKey] = may_hold;
  d[kUntriedKey] = untried;
  if (components_.front().other_size_weight) {
    double other = 0.0;
    for (std::size_t k = 0; k < components_.size(); ++k) {
      other += w[k] * components_[k].other_size_weight.value();
    }
    d[kOtherSizeWeightKey] = other;
  }
  tried_[pending_] = true;
  return space_.periods(pending_);
}

TrialRecord ModelLearner::observe(const Measurement& m) {
  for (const body::WindowMeasure& w : m.windows)
    observe(pending_, window_outputs(w, setup_.criterion));
  const Periods periods = space_.periods(pending_);
  const bool accepted = best_.record(periods, m.deviation_deg);
  return {best_.trials(), periods, m.deviation_deg, accepted, pending_details_};
}

std::vector<Forecast> ModelLearner::best_forecasts(std::size_t count) const {
  const std::vector<Predictions> predicted = predict();
  const std::vector<double> w = weights();
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    order.emplace_back(-chance(w, predicted, c), c);
  }
  count = std::min(count, order.size());
  // Ties in the order of the grid, as propose() breaks them.
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end());
  std::vector<Forecast> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(forecast(w, predicted, order[i].second));
  return out;
}

}  // namespace multicpg::learning
