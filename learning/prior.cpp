// The prior-based learner, in the spirit of Intelligent Trial and Error (Cully, Clune, Tarapore,
// Mouret, Nature 2015: a map of gaits measured beforehand as the prior mean of a GP that the
// trials correct; docs/learning.md "Learners"). Here the map is what the landscapes of OTHER
// leg losses predict for this one: a ridge regression over all of them of a window's mean yaw
// change and path angle on which legs are lost, each working leg's period, and each lost leg's
// effect on each working leg's period, mirrored scenarios included as data. The scenario under
// test and its mirror image are never in it. The trials then correct that prediction through
// the same GP as the bayes learner (learning/model_learner.h).
#include <Eigen/Dense>
#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "common/errors.h"
#include "learning/landscapes.h"
#include "learning/learners.h"
#include "learning/model_learner.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {
namespace {

namespace fs = std::filesystem;

// The residual around the prior is smaller than a landscape's own spread (the bayes learner's
// scales), so its GP starts tighter; the ridge keeps the 217 weights of a hexapod regression
// finite where a lost leg and a period never meet in the data.
struct PriorOptions : ModelOptions {
  std::string dataset;  // the landscape dataset (learning/landscapes.h); "" = the repository's
  // The scenarios it learns from ("R1+R3", ...); empty = every one but the scenario under test
  // and its mirror image, which it may never see.
  std::vector<std::string> scenarios;
  double ridge = 1.0;  // weight decay of the regression, in windows
  PriorOptions() {
    intercept_deg = 8.0;
    effect_deg = 4.0;
    pair_deg = 1.5;
  }
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(PriorOptions, acquisition, kappa, noise_deg,
                                                intercept_deg, effect_deg, pair_deg, dataset,
                                                scenarios, ridge)
inline constexpr Limits<double> kRidgeLimits{1e-6, 1e6};

void validate(const PriorOptions& o) {
  validate(static_cast<const ModelOptions&>(o));
  require_in("ridge", o.ridge, kRidgeLimits);
}

// Datasets read once per process: the benchmark makes thousands of learners from one.
std::shared_ptr<const LandscapeDataset> dataset_at(const fs::path& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const LandscapeDataset>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const LandscapeDataset>& d = cache[path.string()];
  if (!d) d = std::make_shared<const LandscapeDataset>(read_landscape_dataset(path));
  return d;
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

// What the other scenarios predict for every combination of `space` (yaw, path).
// The scenarios of `d` the prior of a run with legs `lost` learns from. Throws BadInput when the
// options name the scenario under test or its mirror, or a scenario the dataset lacks.
std::vector<const ScenarioLandscape*> prior_scenarios(const LandscapeDataset& d,
                                                      const PriorOptions& o,
                                                      std::vector<std::size_t> lost) {
  const robot::Morphology& morph = robot::morphology(d.robot);
  std::sort(lost.begin(), lost.end());
  const std::vector<std::size_t> mirrored = robot::mirror(morph, lost);
  std::vector<const ScenarioLandscape*> out;
  if (o.scenarios.empty()) {
    for (const ScenarioLandscape& s : d.scenarios) {
      if (s.failed != lost && s.failed != mirrored) out.push_back(&s);
    }
  }
  for (const std::string& name : o.scenarios) {
    const std::vector<std::size_t> legs = robot::parse_leg_set(morph, name);
    if (legs == lost || legs == mirrored) {
      throw OptionError("scenarios", "names " + name +
                                         ", so the prior would see the scenario under test (" +
                                         robot::leg_set_name(morph, lost) + ") or its mirror");
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

std::vector<std::vector<double>> prior_mean(const LandscapeDataset& d, const LearnerSetup& setup,
                                            const SearchSpace& space, const PriorOptions& o) {
  const robot::Morphology& morph = robot::morphology(d.robot);
  std::vector<std::size_t> lost = setup.fixed;
  std::sort(lost.begin(), lost.end());
  const double ridge = o.ridge;
  const Features f(morph.size(), d.period_set.size());
  const auto n = static_cast<Eigen::Index>(f.size());
  constexpr auto outputs = static_cast<Eigen::Index>(kOutputs);
  Eigen::MatrixXd xtx = Eigen::MatrixXd::Identity(n, n) * ridge;
  Eigen::MatrixXd xty = Eigen::MatrixXd::Zero(n, outputs);
  const auto add = [&](const std::vector<std::size_t>& failed, const Periods& periods,
                       const WindowOutputs& y) {
    const std::vector<std::size_t> a = f.active(failed, digits(periods, d.period_set));
    for (std::size_t i : a) {
      const auto ii = static_cast<Eigen::Index>(i);
      for (std::size_t j : a) xtx(ii, static_cast<Eigen::Index>(j)) += 1.0;
      for (Eigen::Index k = 0; k < outputs; ++k) xty(ii, k) += y[static_cast<std::size_t>(k)];
    }
  };
  for (const ScenarioLandscape* scenario : prior_scenarios(d, o, lost)) {
    const ScenarioLandscape& s = *scenario;
    const std::vector<std::size_t> image = robot::mirror(morph, s.failed);
    for (const LandscapePoint& p : s.points) {
      WindowOutputs mean{};
      for (const body::WindowMeasure& w : p.windows) {
        mean[kYaw] += w.yaw_deg;
        mean[kPath] += w.path_deg;
        mean[kEffort] += setup.criterion.effort_deg(w.steering_effort);
      }
      for (double& m : mean) m /= static_cast<double>(p.windows.size());
      add(s.failed, p.periods, mean);
      // Its mirror image turns the other way, with the same effort. It is never the scenario
      // under test: that one's mirror is not among the scenarios.
      add(image, robot::mirror_periods(morph, p.periods),
          {-mean[kYaw], -mean[kPath], mean[kEffort]});
    }
  }
  const Eigen::MatrixXd beta = xtx.ldlt().solve(xty);
  std::vector<std::vector<double>> out(kOutputs, std::vector<double>(space.size()));
  for (std::size_t c = 0; c < space.size(); ++c) {
    const std::vector<std::size_t> a = f.active(lost, digits(space.periods(c), d.period_set));
    for (std::size_t i : a) {
      for (std::size_t k = 0; k < kOutputs; ++k) {
        out[k][c] += beta(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
      }
    }
  }
  return out;
}

// The dataset a prior of `robot` learns from: the one its options name, or the repository's
// walked the way the run judges a trial (with the steering reflex or without). Throws BadInput
// (key "dataset") when the named one was walked the other way or is of another robot.
fs::path prior_dataset_path(const PriorOptions& o, robot::RobotKind robot,
                            const Criterion& criterion) {
  return o.dataset.empty() ? repository_dataset(robot, criterion.steers()) : fs::path(o.dataset);
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

// Prior means are computed once per dataset, scenario, scenario list and ridge (the benchmark's
// seeds share them); the key holds the ridge exactly.
std::vector<std::vector<double>> cached_prior_mean(const fs::path& path, const LearnerSetup& setup,
                                                   const SearchSpace& space,
                                                   const PriorOptions& o) {
  const std::shared_ptr<const LandscapeDataset> d = dataset_at(path);
  check_dataset(*d, path, setup.robot, setup.criterion);
  check_period_set(*d, path, setup.search.period_set);
  static std::mutex mutex;
  static std::map<std::string, std::vector<std::vector<double>>> cache;
  std::vector<std::size_t> lost = setup.fixed;
  std::sort(lost.begin(), lost.end());
  const std::string key =
      path.string() + "|" + robot::leg_set_name(robot::morphology(setup.robot), lost) + "|" +
      nlohmann::json(o.scenarios).dump() + "|" + nlohmann::json(o.ridge).dump() + "|" +
      nlohmann::json(setup.criterion.max_effort).dump() + "|" +
      nlohmann::json(setup.criterion.threshold_deg).dump();
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  std::vector<std::vector<double>> mean = prior_mean(*d, setup, space, o);
  const std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, std::move(mean)).first->second;
}

}  // namespace

nlohmann::json prior_options(const nlohmann::json& asked) {
  return read_learner_options<PriorOptions>(asked);
}

void check_prior(const nlohmann::json& options, robot::RobotKind robot,
                 const std::vector<std::size_t>& failed, const Criterion& criterion,
                 const std::vector<int>& period_set) {
  const PriorOptions o = options.get<PriorOptions>();
  const fs::path path = prior_dataset_path(o, robot, criterion);
  const std::shared_ptr<const LandscapeDataset> d = dataset_at(path);
  check_dataset(*d, path, robot, criterion);
  if (!period_set.empty()) check_period_set(*d, path, period_set);
  prior_scenarios(*d, o, failed);
}

std::unique_ptr<Learner> make_prior(const LearnerSetup& setup, const nlohmann::json& options) {
  const PriorOptions o = options.get<PriorOptions>();
  const fs::path path = prior_dataset_path(o, setup.robot, setup.criterion);
  const SearchSpace space(setup);
  return std::make_unique<ModelLearner>(setup, model_learner_params(o),
                                        cached_prior_mean(path, setup, space, o));
}

}  // namespace multicpg::learning
