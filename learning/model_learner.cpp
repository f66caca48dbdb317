#include "learning/model_learner.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
    : setup_(setup),
      params_(params),
      space_(setup),
      model_(space_, params.model, std::move(prior_mean)),
      keep_(std::move(keep)),
      tried_(space_.size(), false),
      best_(setup) {
  if (!keep_.empty() && keep_.size() != space_.size()) {
    throw std::invalid_argument("ModelLearner: keep has " + std::to_string(keep_.size()) +
                                " chances for " + std::to_string(space_.size()) + " combinations");
  }
  const std::size_t start = *space_.index(setup.start);
  tried_[start] = true;
  for (const body::WindowMeasure& w : setup.start_windows)
    model_.observe(start, window_outputs(w, setup_.criterion));
  for (const EarlierTrial& t : setup.earlier) {
    const std::optional<std::size_t> c = space_.index(t.periods);
    if (!c) continue;  // a combination outside this episode's space tells it nothing
    tried_[*c] = true;
    for (const body::WindowMeasure& w : t.windows)
      model_.observe(*c, window_outputs(w, setup_.criterion));
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

double ModelLearner::window_under(const Prediction& p, double limit) const {
  const double sd = std::sqrt(p.sd * p.sd + params_.model.noise_deg * params_.model.noise_deg);
  return normal_cdf((limit - p.mean) / sd) - normal_cdf((-limit - p.mean) / sd);
}

double ModelLearner::effort_under(const Prediction& p, double limit) const {
  // The effort is never negative: only its upper side can fail.
  const double sd = std::sqrt(p.sd * p.sd + params_.model.noise_deg * params_.model.noise_deg);
  return normal_cdf((limit - p.mean) / sd);
}

double ModelLearner::e_under(const std::array<Prediction, kOutputs>& p, double limit) const {
  const Criterion& judge = setup_.criterion;
  double share = window_under(p[kYaw], limit) * (judge.path ? window_under(p[kPath], limit) : 1.0);
  if (judge.steers()) share *= effort_under(p[kEffort], limit);
  return share;
}

double ModelLearner::chance(std::size_t c, const std::array<Prediction, kOutputs>& p) const {
  return std::pow(e_under(p, setup_.search.threshold_deg), setup_.criterion.trial_windows) *
         keep(c);
}

Forecast ModelLearner::forecast(std::size_t c, const std::array<Prediction, kOutputs>& p) const {
  Forecast f{space_.periods(c), tried_[c], p[kYaw], p[kPath], p[kEffort]};
  f.keep = keep(c);
  f.hold = chance(c, p);
  // The quantiles of E by bisection: its distribution is a product of normal CDFs, with no
  // inverse in closed form.
  const double sd = std::sqrt(p[kYaw].sd * p[kYaw].sd + model_.noise_deg() * model_.noise_deg());
  double top = std::abs(p[kYaw].mean);
  if (setup_.criterion.path) top = std::max(top, std::abs(p[kPath].mean));
  if (setup_.criterion.steers()) top = std::max(top, p[kEffort].mean);
  const auto quantile = [&](double q) {
    double lo = 0.0;
    double hi = top + kQuantileBracketSds * sd;
    for (int i = 0; i < kQuantileHalvings; ++i) {
      const double mid = 0.5 * (lo + hi);
      (e_under(p, mid) < q ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  f.e_deg = quantile(0.5);
  f.e_low_deg = quantile(kBandLowQuantile);
  f.e_high_deg = quantile(kBandHighQuantile);
  return f;
}

std::optional<Periods> ModelLearner::propose() {
  Predictions predicted;
  model_.predict(predicted);
  const Criterion& judge = setup_.criterion;
  double best_score = -std::numeric_limits<double>::infinity();
  bool found = false;
  std::size_t untried = 0;
  std::size_t may_hold = 0;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    if (tried_[c]) continue;
    const Prediction& yaw = predicted[kYaw][c];
    const Prediction& path = predicted[kPath][c];
    const Prediction& effort = predicted[kEffort][c];
    const double hold = chance(c, {yaw, path, effort});
    ++untried;
    if (hold >= kMayHoldLevel) ++may_hold;
    double score = hold;
    if (params_.acquisition == Acquisition::ucb) {
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
  const Forecast f = forecast(pending_, {predicted[kYaw][pending_], predicted[kPath][pending_],
                                         predicted[kEffort][pending_]});
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
  tried_[pending_] = true;
  return space_.periods(pending_);
}

TrialRecord ModelLearner::observe(const Measurement& m) {
  for (const body::WindowMeasure& w : m.windows)
    model_.observe(pending_, window_outputs(w, setup_.criterion));
  const Periods periods = space_.periods(pending_);
  const bool accepted = best_.record(periods, m.deviation_deg);
  return {best_.trials(), periods, m.deviation_deg, accepted, pending_details_};
}

std::vector<Forecast> ModelLearner::best_forecasts(std::size_t count) const {
  Predictions predicted;
  model_.predict(predicted);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t c = 0; c < space_.size(); ++c) {
    order.emplace_back(-chance(c, {predicted[kYaw][c], predicted[kPath][c], predicted[kEffort][c]}),
                       c);
  }
  count = std::min(count, order.size());
  // Ties in the order of the grid, as propose() breaks them.
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end());
  std::vector<Forecast> out;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t c = order[i].second;
    out.push_back(forecast(c, {predicted[kYaw][c], predicted[kPath][c], predicted[kEffort][c]}));
  }
  return out;
}

}  // namespace multicpg::learning
