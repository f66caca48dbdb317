#include "learning/prior_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

#include "learning/model_learner.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {
namespace {

// The regression's features of one combination of one scenario: the constant, each lost leg,
// each working leg's period, and each (lost leg, working leg's period).
class Features {
 public:
  Features(std::size_t legs, std::size_t periods) : legs_(legs), periods_(periods) {}
  std::size_t size() const { return 1 + legs_ + legs_ * periods_ + legs_ * legs_ * periods_; }
  std::vector<std::size_t> active(const std::vector<std::size_t>& lost,
                                  const std::vector<std::size_t>& digit) const {
    // digit[leg]: the position of a working leg's period in the set; ignored for lost legs.
    std::vector<std::size_t> out{0};
    for (std::size_t l : lost) out.push_back(1 + l);
    for (std::size_t leg = 0; leg < legs_; ++leg) {
      if (std::binary_search(lost.begin(), lost.end(), leg)) continue;
      out.push_back(1 + legs_ + leg * periods_ + digit[leg]);
      for (std::size_t l : lost) {
        out.push_back(1 + legs_ + legs_ * periods_ + (l * legs_ + leg) * periods_ + digit[leg]);
      }
    }
    return out;
  }

 private:
  std::size_t legs_;
  std::size_t periods_;
};

std::vector<std::size_t> digits(const Periods& periods, const std::vector<int>& set) {
  std::vector<std::size_t> out;
  for (int p : periods) {
    out.push_back(static_cast<std::size_t>(std::find(set.begin(), set.end(), p) - set.begin()));
  }
  return out;
}

// A combination's mean window (yaw, path, effort in degrees of E), as the regression learns it.
WindowOutputs mean_window(const LandscapePoint& p, const Criterion& criterion) {
  WindowOutputs mean{};
  for (const body::WindowMeasure& w : p.windows) {
    const WindowOutputs y = window_outputs(w, criterion);
    for (std::size_t k = 0; k < kOutputs; ++k) mean[k] += y[k];
  }
  for (double& m : mean) m /= static_cast<double>(p.windows.size());
  return mean;
}

// Whether a combination walked in a landscape held its trial as `criterion` judges one (its first
// trial_windows windows each under `threshold_deg`), and if it did, whether it held on through
// every window of the dataset's walk; nothing when its trial did not hold.
std::optional<bool> held_on(const LandscapePoint& p, const Criterion& criterion,
                            double threshold_deg, int dataset_windows) {
  const auto trial = static_cast<std::size_t>(criterion.trial_windows);
  if (p.windows.size() < trial) return std::nullopt;
  const auto holds = [&](const body::WindowMeasure& w) {
    return body::holds(criterion.error(w), threshold_deg);
  };
  if (!std::all_of(p.windows.begin(), p.windows.begin() + static_cast<std::ptrdiff_t>(trial),
                   holds)) {
    return std::nullopt;
  }
  // A walk stops at its first window over the dataset's threshold: one that stopped short did not
  // hold on.
  return p.windows.size() == static_cast<std::size_t>(dataset_windows) &&
         std::all_of(p.windows.begin(), p.windows.end(), holds);
}

// The regression's normal equations X'WX and X'WY, of one scenario or summed over several.
struct NormalEquations {
  Eigen::MatrixXd xtx;
  Eigen::MatrixXd xty;
};

// The regression over the scenarios a prior learns from (their windows and their mirror images',
// weighed as `other_size_weight` says), its normal equations summed in the scenarios' order; for
// the scales from the data, each scenario's part kept apart too, so that they can leave one out.
// Beside it, on the same features and weights, the regression of whether a combination whose trial
// held held on (held_on: 1 or 0, a linear probability), over those whose trial held, about their
// share that held on: where the data say little, the ridge draws a chance to that share, not to 0.
class Regression {
 public:
  Regression(const LandscapeDataset& d, std::vector<const ScenarioLandscape*> scenarios,
             const LearnerSetup& setup, const PriorFit& fit)
      : d_(d),
        morph_(robot::morphology(d_.robot)),
        f_(morph_.size(), d_.period_set.size()),
        scenarios_(std::move(scenarios)) {
    const std::size_t lost = setup.told.failed().size();
    const auto n = static_cast<Eigen::Index>(f_.size());
    // The scales from the data leave scenarios out: each one's part is kept apart too.
    const Eigen::Index part_n = fit.scales ? n : 0;
    total_ = {Eigen::MatrixXd::Identity(n, n) * fit.ridge, Eigen::MatrixXd::Zero(n, kOutputs)};
    keep_ = {Eigen::MatrixXd::Identity(n, n) * fit.ridge, Eigen::MatrixXd::Zero(n, 1)};
    double held = 0.0;
    double passed = 0.0;
    for (const ScenarioLandscape* scenario : scenarios_) {
      const ScenarioLandscape& s = *scenario;
      // Told nothing, no scenario loses as many legs as it knows of (none): all weigh alike.
      const double w = s.failed.size() == lost ? 1.0 : fit.other_size_weight;
      weights_.push_back(w);
      NormalEquations part{Eigen::MatrixXd::Zero(part_n, part_n),
                           Eigen::MatrixXd::Zero(part_n, kOutputs)};
      const std::vector<std::size_t> image = robot::mirror(morph_, s.failed);
      for (const LandscapePoint& p : s.points) {
        const WindowOutputs mean = mean_window(p, setup.criterion);
        // Its mirror image turns the other way, with the same effort. It is never the scenario
        // the prior is told: that one's mirror is not among the scenarios.
        const WindowOutputs mirrored{-mean[kYaw], -mean[kPath], mean[kEffort]};
        const std::vector<std::size_t> a = f_.active(s.failed, digits(p.periods, d_.period_set));
        const std::vector<std::size_t> b =
            f_.active(image, digits(robot::mirror_periods(morph_, p.periods), d_.period_set));
        add(total_, a, mean, w);
        add(total_, b, mirrored, w);
        if (const std::optional<bool> kept =
                fit.keeps ? held_on(p, setup.criterion, setup.search.threshold_deg, d_.windows)
                          : std::nullopt) {
          const std::array<double, 1> y{*kept ? 1.0 : 0.0};
          for (const std::vector<std::size_t>* row : {&a, &b}) {
            add(keep_, *row, y, w);
            held += w * y[0];
            passed += w;
          }
        }
        if (!fit.scales) continue;
        add(part, a, mean, w);
        add(part, b, mirrored, w);
      }
      if (fit.scales) parts_.push_back(std::move(part));
    }
    // No combination's trial held in the data: nothing says one drifts after it.
    keep_share_ = passed > 0.0 ? held / passed : 1.0;
    // About that share: X'W(y - share) = X'Wy - share X'W1. The constant (feature 0) is in every
    // row, so X'W1, each feature's weight of rows, is X'WX's first column, its first entry
    // without the ridge (`passed`).
    Eigen::VectorXd rows = keep_.xtx.col(0);
    rows(0) = passed;
    keep_.xty.col(0) -= keep_share_ * rows;
  }

  const std::vector<const ScenarioLandscape*>& scenarios() const { return scenarios_; }
  // What a window of scenario `i` counts for in the regression.
  double weight(std::size_t i) const { return weights_.at(i); }

  // The weights learned from every scenario but those in `left_out`, each named once (which
  // needs the parts).
  Eigen::MatrixXd solve(const std::vector<std::size_t>& left_out = {}) const {
    if (left_out.empty()) return total_.xtx.ldlt().solve(total_.xty);
    NormalEquations e = total_;
    for (std::size_t i : left_out) {
      e.xtx -= parts_.at(i).xtx;
      e.xty -= parts_.at(i).xty;
    }
    return e.xtx.ldlt().solve(e.xty);
  }

  // The weights of the chance of holding on after a trial that held, about keep_share().
  Eigen::VectorXd solve_keep() const { return keep_.xtx.ldlt().solve(keep_.xty); }
  double keep_share() const { return keep_share_; }

  // What weights `beta` (a column per output) predict for `periods` with `lost` legs lost.
  template <std::size_t N = kOutputs>
  std::array<double, N> predict(const Eigen::MatrixXd& beta, const std::vector<std::size_t>& lost,
                                const Periods& periods) const {
    std::array<double, N> out{};
    for (std::size_t i : f_.active(lost, digits(periods, d_.period_set))) {
      for (std::size_t k = 0; k < N; ++k) {
        out[k] += beta(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
      }
    }
    return out;
  }

  // The position of scenario `i`'s mirror image among the scenarios (none: itself).
  std::size_t mirror_of(std::size_t i) const {
    const std::vector<std::size_t> image = robot::mirror(morph_, scenarios_[i]->failed);
    for (std::size_t j = 0; j < scenarios_.size(); ++j) {
      if (scenarios_[j]->failed == image) return j;
    }
    return i;
  }

  const std::vector<int>& period_set() const { return d_.period_set; }

 private:
  // One row, its active features `a`, of targets `y` and weight `w`.
  template <std::size_t N>
  static void add(NormalEquations& e, const std::vector<std::size_t>& a,
                  const std::array<double, N>& y, double w) {
    for (std::size_t i : a) {
      const auto ii = static_cast<Eigen::Index>(i);
      for (std::size_t j : a) e.xtx(ii, static_cast<Eigen::Index>(j)) += w;
      for (std::size_t k = 0; k < N; ++k) e.xty(ii, static_cast<Eigen::Index>(k)) += w * y[k];
    }
  }

  const LandscapeDataset& d_;
  const robot::Morphology& morph_;
  Features f_;
  std::vector<const ScenarioLandscape*> scenarios_;
  std::vector<double> weights_;
  NormalEquations total_;
  NormalEquations keep_;     // of held_on less keep_share_, one column
  double keep_share_ = 1.0;  // the share of the combinations whose trial held that held on
  std::vector<NormalEquations> parts_;
};

// What the scenarios it learns from predict for every combination of `space` (yaw, path,
// effort): for the legs it is told failed, or, told nothing, for the features every scenario
// shares (each leg's period), no leg lost.
std::vector<std::vector<double>> prior_mean(const Regression& r, const LearnerSetup& setup,
                                            const SearchSpace& space) {
  const std::vector<std::size_t>& lost = setup.told.failed();
  const Eigen::MatrixXd beta = r.solve();
  std::vector<std::vector<double>> out(kOutputs, std::vector<double>(space.size()));
  for (std::size_t c = 0; c < space.size(); ++c) {
    const WindowOutputs y = r.predict(beta, lost, space.periods(c));
    for (std::size_t k = 0; k < kOutputs; ++k) out[k][c] = y[k];
  }
  return out;
}

// A chance of holding on is a linear probability, which may fall below 0 where the data see none
// hold on: floored here, such combinations stay in the order of their chance of holding their
// trial, behind every one the data give a real chance (the replays of docs/learning.md "Holding on
// after the trial" are the same with a floor of 0.01, 0.05 or 0.1).
inline constexpr double kKeepFloor = 0.01;

// The chance that each combination of `space` keeps holding once its trial has held, as the
// scenarios the prior learns from say (for the legs it is told failed, as prior_mean), within
// [kKeepFloor, 1].
std::vector<double> keep_chances(const Regression& r, const LearnerSetup& setup,
                                 const SearchSpace& space) {
  const std::vector<std::size_t>& lost = setup.told.failed();
  const Eigen::MatrixXd beta = r.solve_keep();
  std::vector<double> out(space.size());
  for (std::size_t c = 0; c < space.size(); ++c) {
    out[c] =
        std::clamp(r.keep_share() + r.predict<1>(beta, lost, space.periods(c))[0], kKeepFloor, 1.0);
  }
  return out;
}

// The GP's scales from the data (scales = "data"): how far the regression misses each scenario it
// learns from when that scenario and its mirror image are left out of it, as the scenario under
// test is left out of the prior. A combination's miss is split as the GP splits a function (the
// scenario's mean miss: the constant; each working leg's period's mean miss about it: an effect;
// what each pair of legs' periods leaves: a pair), and a scale is the root mean square of its
// part, over the scenarios and the parts of E the run judges (yaw; the path angle in robust mode;
// the reflex's effort with the reflex). The noise: the windows' spread around their combination's
// mean, where a combination walked two or more (in a dataset walked in order, those that held
// their first window). Moments rather than a likelihood fit, as the
// ANOVA of a balanced grid gives them in closed form.
AdditiveModelParams data_scales(const Regression& r, const Criterion& criterion) {
  std::vector<std::size_t> outputs{kYaw};
  if (criterion.path) outputs.push_back(kPath);
  if (criterion.steers()) outputs.push_back(kEffort);
  const std::size_t q = r.period_set().size();
  struct Moment {
    double sum = 0.0;
    double count = 0.0;
    void add(double x, double weight = 1.0) {
      sum += weight * x * x;
      count += weight;
    }
    double rms() const { return count > 0.0 ? std::sqrt(sum / count) : 0.0; }
  };
  // Over the scenarios where some combination holds, each counting once (as much as its windows
  // count in the regression): a scale describes the scenario a prior is asked about, one drawn
  // from among those it can win, whatever its number of combinations. Where nothing holds (a
  // whole side lost) the robot's turn is tens of degrees off any model, and a few such scenarios
  // would set every scale (the quadruped's six of fourteen: docs/learning.md).
  Moment intercept, effect, pair, noise;
  for (std::size_t i = 0; i < r.scenarios().size(); ++i) {
    const ScenarioLandscape& s = *r.scenarios()[i];
    const bool holds = std::any_of(s.points.begin(), s.points.end(),
                                   [](const LandscapePoint& p) { return p.holds; });
    if (!holds || r.weight(i) == 0.0) continue;
    Moment s_intercept, s_effect, s_pair, s_noise;
    const std::size_t image = r.mirror_of(i);
    const Eigen::MatrixXd beta =
        r.solve(image == i ? std::vector<std::size_t>{i} : std::vector<std::size_t>{i, image});
    std::vector<std::size_t> working;
    for (std::size_t leg = 0; leg < s.points.front().periods.size(); ++leg) {
      if (!std::binary_search(s.failed.begin(), s.failed.end(), leg)) working.push_back(leg);
    }
    std::vector<WindowOutputs> miss;
    std::vector<std::vector<std::size_t>> digit;
    for (const LandscapePoint& p : s.points) {
      const WindowOutputs mean = mean_window(p, criterion);
      const WindowOutputs predicted = r.predict(beta, s.failed, p.periods);
      WindowOutputs m{};
      for (std::size_t k : outputs) m[k] = mean[k] - predicted[k];
      miss.push_back(m);
      digit.push_back(digits(p.periods, r.period_set()));
      if (p.windows.size() < 2) continue;
      WindowOutputs sum{};
      WindowOutputs sq{};
      for (const body::WindowMeasure& w : p.windows) {
        const WindowOutputs y = window_outputs(w, criterion);
        for (std::size_t k : outputs) {
          sum[k] += y[k];
          sq[k] += y[k] * y[k];
        }
      }
      const auto n = static_cast<double>(p.windows.size());
      for (std::size_t k : outputs) {
        s_noise.sum += (sq[k] - sum[k] * sum[k] / n) / (n - 1.0);
        s_noise.count += 1.0;
      }
    }
    // The mean miss of a cell: every combination, those with one working leg at one period, or
    // two working legs at two periods; each cell summed in one pass in the combinations' order.
    struct Cell {
      double sum = 0.0;
      double n = 0.0;
      std::optional<double> mean() const {
        if (n == 0.0) return std::nullopt;
        return sum / n;
      }
    };
    const std::size_t legs = working.size();
    const auto two = [&](std::size_t a, std::size_t b, std::size_t j, std::size_t l) {
      return ((a * legs + b) * q + j) * q + l;
    };
    for (std::size_t k : outputs) {
      Cell all;
      std::vector<Cell> one(legs * q);
      std::vector<Cell> both(legs * legs * q * q);
      for (std::size_t c = 0; c < miss.size(); ++c) {
        const double x = miss[c][k];
        const auto add = [x](Cell& cell) {
          cell.sum += x;
          cell.n += 1.0;
        };
        add(all);
        for (std::size_t a = 0; a < legs; ++a) {
          add(one[a * q + digit[c][working[a]]]);
          for (std::size_t b = a + 1; b < legs; ++b) {
            add(both[two(a, b, digit[c][working[a]], digit[c][working[b]])]);
          }
        }
      }
      const double constant = *all.mean();
      s_intercept.add(constant);
      std::vector<std::optional<double>> main(legs * q);
      for (std::size_t a = 0; a < legs; ++a) {
        for (std::size_t j = 0; j < q; ++j) {
          main[a * q + j] = one[a * q + j].mean();
          if (main[a * q + j]) {
            *main[a * q + j] -= constant;
            s_effect.add(*main[a * q + j]);
          }
        }
      }
      for (std::size_t a = 0; a < legs; ++a) {
        for (std::size_t b = a + 1; b < legs; ++b) {
          for (std::size_t j = 0; j < q; ++j) {
            for (std::size_t l = 0; l < q; ++l) {
              if (const std::optional<double> m = both[two(a, b, j, l)].mean()) {
                s_pair.add(*m - constant - *main[a * q + j] - *main[b * q + l]);
              }
            }
          }
        }
      }
    }
    for (auto [all, one] : {std::pair{&intercept, &s_intercept}, std::pair{&effect, &s_effect},
                            std::pair{&pair, &s_pair}, std::pair{&noise, &s_noise}}) {
      if (one->count > 0.0) all->add(one->rms(), r.weight(i));
    }
  }
  const auto scale = [](const Moment& m, const Limits<double>& limits) {
    return std::clamp(m.rms(), limits.lo, limits.hi);
  };
  return {scale(noise, kModelScaleLimits), scale(intercept, kModelScaleLimits),
          scale(effect, kModelScaleLimits), scale(pair, kPairScaleLimits)};
}

}  // namespace

PriorModel fit_prior(const LandscapeDataset& dataset,
                     std::vector<const ScenarioLandscape*> scenarios, const LearnerSetup& setup,
                     const SearchSpace& space, const PriorFit& fit) {
  const Regression r(dataset, std::move(scenarios), setup, fit);
  PriorModel model{prior_mean(r, setup, space), std::nullopt, {}};
  if (fit.scales) model.scales = data_scales(r, setup.criterion);
  if (fit.keeps) model.keep = keep_chances(r, setup, space);
  return model;
}

}  // namespace multicpg::learning
