// The prior-based learner, in the spirit of Intelligent Trial and Error (Cully, Clune, Tarapore,
// Mouret, Nature 2015: a map of gaits measured beforehand as the prior mean of a GP that the
// trials correct; docs/learning.md "Learners"). Here the map is what the landscapes of OTHER
// leg losses predict for this one: a ridge regression over all of them of a window's mean yaw
// change and path angle on which legs are lost, each working leg's period, and each lost leg's
// effect on each working leg's period, mirrored scenarios included as data. The scenario under
// test and its mirror image are never in it. The trials then correct that prediction through
// the same GP as the bayes learner (learning/model_learner.h). Beside the mean, the same regression
// learns from those landscapes which combinations, once their trial's windows held, held on
// through every later window, and weighs each combination by that chance: a combination that holds
// its trial and then drifts is a false stop, which robust mode's monitoring catches only after it
// has walked on (docs/learning.md "Holding on after the trial").
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

#include "common/errors.h"
#include "learning/landscape_cache.h"
#include "learning/landscapes.h"
#include "learning/learners.h"
#include "learning/model_learner.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {
namespace {

namespace fs = std::filesystem;

// The residual around the prior is smaller than a landscape's own spread (the bayes learner's
// scales), so its given scales (scales = "options") start its GP tighter; by default it takes them
// from the data. The ridge keeps the 217 weights of a hexapod regression finite where a lost leg
// and a period never meet in the data.
struct PriorOptions : ModelOptions {
  std::string dataset;  // the landscape dataset (learning/landscapes.h); "" = the repository's
  // The scenarios it learns from ("R1+R3", ...); empty = every one but the scenario under test
  // and its mirror image, which it may never see.
  std::vector<std::string> scenarios;
  double ridge = 1.0;  // weight decay of the regression, in windows
  // What a window of a loss of another number of legs than the one told counts for against one
  // of as many (1: every window alike; docs/learning.md "The quadruped: a small dataset").
  double other_size_weight = 1.0;
  // Where the GP's scales (noise_deg, intercept_deg, effect_deg, pair_deg) come from: "data"
  // (what the regression misses on the scenarios it learns from, each left out in turn) or
  // "options" (as given); docs/learning.md "The prior's scales from its data".
  std::string scales = "data";
  // Whether it weighs each combination by its data's chance that the combination keeps holding
  // once its trial has held; false: every combination whose trial holds is taken to hold on.
  bool keeps = true;
  PriorOptions() {
    intercept_deg = 8.0;
    effect_deg = 4.0;
    pair_deg = 1.5;
  }
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PriorOptions, acquisition, kappa, noise_deg,
                                                intercept_deg, effect_deg, pair_deg, dataset,
                                                scenarios, ridge, other_size_weight, scales, keeps)
inline constexpr Limits<double> kRidgeLimits{1e-6, 1e6};
// 0: losses of as many legs alone; above 1 the others count for more.
inline constexpr Limits<double> kOtherSizeWeightLimits{0.0, 1e6};

void validate(const PriorOptions& o) {
  validate(static_cast<const ModelOptions&>(o));
  require_in("ridge", o.ridge, kRidgeLimits);
  require_in("other_size_weight", o.other_size_weight, kOtherSizeWeightLimits);
  if (o.scales != "options" && o.scales != "data") {
    throw OptionError("scales", "must be options or data, got '" + o.scales + "'");
  }
}

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

// The scenarios of `d` a prior learns from: every one but the scenario it is told it is in, the
// scenarios its data withhold, and their mirror images; or the ones its options name. Told
// nothing, it cannot leave its own scenario out (docs/learning.md "What a learner is told").
// Throws OptionError when the options name a scenario it may not see or one the dataset lacks;
// BadInput when no scenario is left.
std::vector<const ScenarioLandscape*> prior_scenarios(
    const LandscapeDataset& d, const PriorOptions& o, const ToldFault& told,
    const std::vector<std::vector<std::size_t>>& withheld) {
  const robot::Morphology& morph = robot::morphology(d.robot);
  std::vector<std::size_t> lost = told.failed();
  std::sort(lost.begin(), lost.end());
  std::vector<std::vector<std::size_t>> unseen;
  if (told.told()) unseen = {lost, robot::mirror(morph, lost)};
  for (const std::vector<std::size_t>& legs : withheld) {
    unseen.push_back(legs);
    unseen.push_back(robot::mirror(morph, legs));
  }
  const auto is_unseen = [&](const std::vector<std::size_t>& legs) {
    return std::find(unseen.begin(), unseen.end(), legs) != unseen.end();
  };
  std::vector<const ScenarioLandscape*> out;
  if (o.scenarios.empty()) {
    for (const ScenarioLandscape& s : d.scenarios) {
      if (!is_unseen(s.failed)) out.push_back(&s);
    }
  }
  for (const std::string& name : o.scenarios) {
    const std::vector<std::size_t> legs = robot::parse_leg_set(morph, name);
    if (is_unseen(legs)) {
      throw OptionError("scenarios",
                        "names " + name + ", so the prior would see the scenario under test (" +
                            robot::leg_set_name(morph, told.told() ? lost : withheld.front()) +
                            ") or its mirror");
    }
    const ScenarioLandscape* s = d.find(legs);
    if (s == nullptr) throw OptionError("scenarios", "names " + name + ", which the dataset lacks");
    out.push_back(s);
  }
  if (out.empty()) {
    throw BadInput("the prior's dataset has no scenario other than the one under test");
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
// weighed as `other_size_weight` says), its normal equations summed in the scenarios' order; with
// `keep_parts`, each scenario's part kept apart too, so that the scales from the data can leave
// one out. Beside it, on the same features and weights, the regression of whether a combination
// whose trial held held on (held_on: 1 or 0, a linear probability), over those whose trial held,
// about their share that held on: where the data say little, the ridge draws a chance to that
// share, not to 0.
class Regression {
 public:
  Regression(const LearnerData& data, const LearnerSetup& setup, const PriorOptions& o,
             bool keep_parts)
      : d_(*data.landscapes),
        morph_(robot::morphology(d_.robot)),
        f_(morph_.size(), d_.period_set.size()),
        scenarios_(prior_scenarios(d_, o, setup.told, data.withheld)) {
    const std::size_t lost = setup.told.failed().size();
    const auto n = static_cast<Eigen::Index>(f_.size());
    total_ = {Eigen::MatrixXd::Identity(n, n) * o.ridge, Eigen::MatrixXd::Zero(n, kOutputs)};
    keep_ = {Eigen::MatrixXd::Identity(n, n) * o.ridge, Eigen::MatrixXd::Zero(n, 1)};
    Eigen::VectorXd keep_rows = Eigen::VectorXd::Zero(n);  // each feature's weight of rows
    double held = 0.0;
    double passed = 0.0;
    for (const ScenarioLandscape* scenario : scenarios_) {
      const ScenarioLandscape& s = *scenario;
      // Told nothing, no scenario loses as many legs as it knows of (none): all weigh alike.
      const double w = s.failed.size() == lost ? 1.0 : o.other_size_weight;
      weights_.push_back(w);
      NormalEquations part{Eigen::MatrixXd::Zero(keep_parts ? n : 0, keep_parts ? n : 0),
                           Eigen::MatrixXd::Zero(keep_parts ? n : 0, kOutputs)};
      const std::vector<std::size_t> image = robot::mirror(morph_, s.failed);
      for (const LandscapePoint& p : s.points) {
        const WindowOutputs mean = mean_window(p, setup.criterion);
        // Its mirror image turns the other way, with the same effort. It is never the scenario
        // the prior is told: that one's mirror is not among the scenarios.
        const WindowOutputs mirrored{-mean[kYaw], -mean[kPath], mean[kEffort]};
        const Periods mirrored_periods = robot::mirror_periods(morph_, p.periods);
        add(total_, s.failed, p.periods, mean, w);
        add(total_, image, mirrored_periods, mirrored, w);
        if (const std::optional<bool> kept =
                o.keeps ? held_on(p, setup.criterion, setup.search.threshold_deg, d_.windows)
                        : std::nullopt) {
          const std::array<double, 1> y{*kept ? 1.0 : 0.0};
          for (const auto& [legs, periods] :
               {std::pair{&s.failed, &p.periods}, std::pair{&image, &mirrored_periods}}) {
            add(keep_, *legs, *periods, y, w);
            for (std::size_t i : f_.active(*legs, digits(*periods, d_.period_set)))
              keep_rows(static_cast<Eigen::Index>(i)) += w;
            held += w * y[0];
            passed += w;
          }
        }
        if (!keep_parts) continue;
        add(part, s.failed, p.periods, mean, w);
        add(part, image, mirrored_periods, mirrored, w);
      }
      if (keep_parts) parts_.push_back(std::move(part));
    }
    // No combination's trial held in the data: nothing says one drifts after it.
    keep_share_ = passed > 0.0 ? held / passed : 1.0;
    keep_.xty.col(0) -= keep_share_ * keep_rows;
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
  template <std::size_t N>
  void add(NormalEquations& e, const std::vector<std::size_t>& failed, const Periods& periods,
           const std::array<double, N>& y, double w) const {
    const std::vector<std::size_t> a = f_.active(failed, digits(periods, d_.period_set));
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
  std::vector<std::size_t> lost = setup.told.failed();
  std::sort(lost.begin(), lost.end());
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
  std::vector<std::size_t> lost = setup.told.failed();
  std::sort(lost.begin(), lost.end());
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

void check_dataset(const LandscapeDataset& d, const fs::path& path, robot::RobotKind robot,
                   const Criterion& criterion) {
  if (d.robot != robot) {
    throw OptionError("dataset", "'" + path.string() + "' is of the " +
                                     std::string(robot::to_string(d.robot)) + ", not the " +
                                     std::string(robot::to_string(robot)));
  }
  if (d.reflex.has_value() != criterion.steers()) {
    throw OptionError(
        "dataset",
        "'" + path.string() + "' was walked with " + d.walked() +
            ", but this run judges its trials " +
            (criterion.steers() ? "with the steering reflex (--steering off, or a dataset "
                                  "walked with --steering reflex)"
                                : "without the steering reflex (a dataset walked with "
                                  "--steering off)"));
  }
}

// The run's period set must be the dataset's: its cells are combinations of that set.
void check_period_set(const LandscapeDataset& d, const fs::path& path,
                      const std::vector<int>& period_set) {
  if (d.period_set == period_set) return;
  const auto text = [](const std::vector<int>& set) {
    std::string t;
    for (int p : set) t += (t.empty() ? "" : ",") + std::to_string(p);
    return t;
  };
  throw BadInput("the prior's dataset '" + path.string() + "' has the period set " +
                 text(d.period_set) + ", this run " + text(period_set) +
                 " (learning.annealing.period_set; or a dataset walked with the run's)");
}

// What decides a prior mean besides its data, compared exactly.
using PriorKey = std::tuple<bool, std::vector<std::size_t>, std::vector<std::vector<std::size_t>>,
                            std::vector<std::string>, double, double, bool, double, double, int,
                            double, std::string, bool>;

PriorKey prior_key(const LearnerData& data, const LearnerSetup& setup, const PriorOptions& o) {
  std::vector<std::size_t> lost = setup.told.failed();
  std::sort(lost.begin(), lost.end());
  const Criterion& c = setup.criterion;
  return {setup.told.told(),          lost,     data.withheld,   o.scenarios,  o.ridge,
          o.other_size_weight,        c.path,   c.threshold_deg, c.max_effort, c.trial_windows,
          setup.search.threshold_deg, o.scales, o.keeps};
}

}  // namespace

// A prior's model before any trial: its mean, its scales where they come from the data, and each
// combination's chance of holding on after its trial where it weighs by it.
struct PriorModel {
  std::vector<std::vector<double>> mean;
  std::optional<AdditiveModelParams> scales;
  std::vector<double> keep;
};

// Prior models computed once per scenario told, withheld scenarios, options and criterion (the
// benchmark's seeds share them), for the data they belong to.
class PriorMeans {
 public:
  PriorModel get(const LearnerData& data, const LearnerSetup& setup, const SearchSpace& space,
                 const PriorOptions& o) {
    const PriorKey key = prior_key(data, setup, o);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      const auto it = models_.find(key);
      if (it != models_.end()) return it->second;
    }
    const Regression r(data, setup, o, o.scales == "data");
    PriorModel model{prior_mean(r, setup, space), std::nullopt, {}};
    if (o.scales == "data") model.scales = data_scales(r, setup.criterion);
    if (o.keeps) model.keep = keep_chances(r, setup, space);
    const std::lock_guard<std::mutex> lock(mutex_);
    return models_.emplace(key, std::move(model)).first->second;
  }

 private:
  std::mutex mutex_;
  std::map<PriorKey, PriorModel> models_;
};

namespace {

// The data a prior of `robot` learns from: the dataset its options name, or the repository's
// walked the way the run judges a trial (with the steering reflex or without).
fs::path prior_dataset_path(const PriorOptions& o, robot::RobotKind robot,
                            const Criterion& criterion) {
  return o.dataset.empty() ? repository_dataset(robot, criterion.steers()) : fs::path(o.dataset);
}

}  // namespace

nlohmann::json prior_options(const nlohmann::json& asked) {
  nlohmann::json resolved = read_learner_options<PriorOptions>(asked);
  if (resolved.at("scales") == "data") {
    // The scales come from the data: a scale given beside them would be silently unused, and a
    // record that listed them would say what the model did not use.
    for (const char* key : {"noise_deg", "intercept_deg", "effect_deg", "pair_deg"}) {
      if (asked.contains(key)) {
        throw OptionError(key,
                          "is one of the prior's given scales, unused while it takes its "
                          "scales from its data (scales=data, the default); add "
                          "scales=options to give them");
      }
      resolved.erase(key);
    }
  }
  return resolved;
}

LearnerData prior_data(const nlohmann::json& options, robot::RobotKind robot,
                       const Criterion& criterion) {
  const fs::path path = prior_dataset_path(options.get<PriorOptions>(), robot, criterion);
  LearnerData data;
  data.landscapes = read_landscape_dataset_once(path);
  data.source = path;
  data.computed = std::make_shared<PriorMeans>();
  return data;
}

void check_prior(const nlohmann::json& options, const LearnerData& data, robot::RobotKind robot,
                 const ToldFault& told, const Criterion& criterion,
                 const std::vector<int>& period_set) {
  const PriorOptions o = options.get<PriorOptions>();
  if (!data.landscapes) throw std::invalid_argument("check_prior: no data (learner_data)");
  check_dataset(*data.landscapes, data.source, robot, criterion);
  if (!period_set.empty()) check_period_set(*data.landscapes, data.source, period_set);
  prior_scenarios(*data.landscapes, o, told, data.withheld);
}

std::unique_ptr<Learner> make_prior(const LearnerSetup& setup, const nlohmann::json& options,
                                    const LearnerData& data) {
  if (!data.landscapes || !data.computed) {
    throw std::invalid_argument("make_prior: no data (learner_data)");
  }
  const PriorOptions o = options.get<PriorOptions>();
  check_dataset(*data.landscapes, data.source, setup.robot, setup.criterion);
  check_period_set(*data.landscapes, data.source, setup.search.period_set);
  const SearchSpace space(setup);
  PriorModel model = data.computed->get(data, setup, space, o);
  ModelLearnerParams params = model_learner_params(o);
  if (model.scales) params.model = *model.scales;
  return std::make_unique<ModelLearner>(setup, params, std::move(model.mean),
                                        std::move(model.keep));
}

}  // namespace multicpg::learning
