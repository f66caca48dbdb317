// A Gaussian-process model of a window's signed yaw change, path angle and (with the steering
// reflex) the reflex's effort in degrees of E (learning/criterion.h) over the combinations of a
// search space, for the model-based learners (learning/bayes.cpp, learning/prior.cpp).
//
// The kernel is a sum over working legs of a categorical kernel on each leg's period, plus a
// constant and, optionally, a sum over pairs of legs of the product of their categorical
// kernels: the turn a gait makes is close to a sum of what each leg's period contributes
// (docs/learning.md "Learners"). Such a GP is exactly Bayesian linear regression on one-hot
// features (a weight per leg and period, per pair of legs and periods, and a constant), so it is
// computed in weight space: a trial costs O(D^2) for D features, whatever the number of trials,
// and a prediction over every combination O(N k^2) for k features active per combination.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <vector>

#include "learning/forecast.h"
#include "learning/search_space.h"

namespace multicpg::learning {

struct AdditiveModelParams {
  double noise_deg = 0.0;      // sd of one window around its combination's mean
  double intercept_deg = 0.0;  // prior sd of the constant
  double effect_deg = 0.0;     // prior sd of each leg's contribution at each period
  double pair_deg = 0.0;       // prior sd of each pair's contribution; 0 = no pairs
};

// What the model predicts of a window: the three parts of E (learning/criterion.h).
enum Output : std::size_t { kYaw, kPath, kEffort, kOutputs };
// One window as the model sees it: yaw change and path angle in degrees, the reflex's effort in
// degrees of E (Criterion::effort_deg of its share; 0 without the reflex).
using WindowOutputs = std::array<double, kOutputs>;
// Every combination's prediction of each output.
using Predictions = std::array<std::vector<Prediction>, kOutputs>;

class AdditiveModel {
 public:
  // `prior_mean[output][combination]`: a mean the weights correct (empty: zero), for each of the
  // outputs.
  AdditiveModel(const SearchSpace& space, const AdditiveModelParams& params,
                std::vector<std::vector<double>> prior_mean = {});

  // One window of `combination`.
  void observe(std::size_t combination, const WindowOutputs& window);
  // Every output for every combination.
  void predict(Predictions& out) const;
  // Every output for one combination.
  std::array<Prediction, kOutputs> predict(std::size_t combination) const;
  double noise_deg() const { return params_.noise_deg; }

 private:
  std::vector<std::size_t> active(std::size_t combination) const;

  const SearchSpace& space_;
  AdditiveModelParams params_;
  std::vector<std::vector<double>> prior_mean_;
  std::size_t features_ = 0;
  // The weights' posterior, updated by each window (a Kalman, i.e. rank-one, update: O(D^2)
  // instead of refactoring the D x D precision matrix, O(D^3)).
  Eigen::MatrixXd covariance_;  // Sigma
  Eigen::MatrixXd mean_;        // of the weights, per output (of y - prior mean)
};

}  // namespace multicpg::learning
