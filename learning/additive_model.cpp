#include "learning/additive_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace multicpg::learning {

AdditiveModel::AdditiveModel(const SearchSpace& space, const AdditiveModelParams& params,
                             std::vector<std::vector<double>> prior_mean)
    : space_(space), params_(params), prior_mean_(std::move(prior_mean)) {
  const std::size_t legs = space.working().size();
  const std::size_t q = space.period_set().size();
  const std::size_t pairs = params.pair_deg > 0.0 ? legs * (legs - 1) / 2 : 0;
  features_ = 1 + legs * q + pairs * q * q;
  if (prior_mean_.empty()) prior_mean_.assign(kOutputs, std::vector<double>(space.size(), 0.0));
  if (prior_mean_.size() != kOutputs ||
      std::any_of(prior_mean_.begin(), prior_mean_.end(),
                  [&](const std::vector<double>& m) { return m.size() != space.size(); })) {
    throw std::logic_error("AdditiveModel: a prior mean per output and combination");
  }
  const auto d = static_cast<Eigen::Index>(features_);
  covariance_ = Eigen::MatrixXd::Zero(d, d);
  mean_ = Eigen::MatrixXd::Zero(d, kOutputs);
  const auto var = [](double sd) { return sd * sd; };
  covariance_(0, 0) = var(params.intercept_deg);
  for (std::size_t f = 1; f < 1 + legs * q; ++f) {
    covariance_(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(f)) =
        var(params.effect_deg);
  }
  for (std::size_t f = 1 + legs * q; f < features_; ++f) {
    covariance_(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(f)) = var(params.pair_deg);
  }
}

std::vector<std::size_t> AdditiveModel::active(std::size_t combination) const {
  const std::size_t legs = space_.working().size();
  const std::size_t q = space_.period_set().size();
  std::vector<std::size_t> digit(legs);
  for (std::size_t i = 0; i < legs; ++i) digit[i] = space_.digit(combination, i);
  std::vector<std::size_t> out{0};
  for (std::size_t i = 0; i < legs; ++i) out.push_back(1 + i * q + digit[i]);
  if (params_.pair_deg > 0.0) {
    std::size_t pair = 0;
    for (std::size_t i = 0; i < legs; ++i) {
      for (std::size_t j = i + 1; j < legs; ++j, ++pair) {
        out.push_back(1 + legs * q + pair * q * q + digit[i] * q + digit[j]);
      }
    }
  }
  return out;
}

void AdditiveModel::observe(std::size_t combination, const WindowOutputs& window) {
  // The window is y = x^T weights + noise with x the combination's active features (0/1):
  // u = Sigma x, gain k = u / (noise^2 + x^T u), mean += k (y - x^T mean), Sigma -= k u^T.
  const std::vector<std::size_t> a = active(combination);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(covariance_.rows());
  for (std::size_t i : a) u += covariance_.col(static_cast<Eigen::Index>(i));
  double xu = 0.0;
  for (std::size_t i : a) xu += u(static_cast<Eigen::Index>(i));
  const Eigen::VectorXd gain = u / (params_.noise_deg * params_.noise_deg + xu);
  for (std::size_t o = 0; o < kOutputs; ++o) {
    const auto oo = static_cast<Eigen::Index>(o);
    const double y = window[o] - prior_mean_[o][combination];
    double predicted = 0.0;
    for (std::size_t i : a) predicted += mean_(static_cast<Eigen::Index>(i), oo);
    mean_.col(oo) += gain * (y - predicted);
  }
  covariance_.noalias() -= gain * u.transpose();
}

std::array<Prediction, kOutputs> AdditiveModel::predict(std::size_t c) const {
  const std::vector<std::size_t> a = active(c);
  std::array<double, kOutputs> m{};
  for (std::size_t o = 0; o < kOutputs; ++o) m[o] = prior_mean_[o][c];
  double var = 0.0;
  for (std::size_t i : a) {
    const auto ii = static_cast<Eigen::Index>(i);
    for (std::size_t o = 0; o < kOutputs; ++o) m[o] += mean_(ii, static_cast<Eigen::Index>(o));
    for (std::size_t j : a) var += covariance_(ii, static_cast<Eigen::Index>(j));
  }
  const double sd = std::sqrt(std::max(var, 0.0));
  std::array<Prediction, kOutputs> out;
  for (std::size_t o = 0; o < kOutputs; ++o) out[o] = {m[o], sd};
  return out;
}

void AdditiveModel::predict(Predictions& out) const {
  for (std::vector<Prediction>& v : out) v.resize(space_.size());
  for (std::size_t c = 0; c < space_.size(); ++c) {
    const std::array<Prediction, kOutputs> p = predict(c);
    for (std::size_t o = 0; o < kOutputs; ++o) out[o][c] = p[o];
  }
}

}  // namespace multicpg::learning
