// The prior-based learner, in the spirit of Intelligent Trial and Error (Cully, Clune, Tarapore,
// Mouret, Nature 2015: a map of gaits measured beforehand as the prior mean of a GP that the
// trials correct; docs/learning.md "Learners"). Here the map is what the landscapes of OTHER
// leg losses predict for this one (learning/prior_model.h): the scenario under test and its
// mirror image are never in it. The trials then correct that prediction through the same GP as
// the bayes learner (learning/model_learner.h), each combination weighed by its data's chance of
// holding on after its trial (docs/learning.md "Holding on after the trial"); with several
// weights of the losses of another number of legs, one prior for each, averaged by their
// evidence ("Averaged by their evidence"). This file: the prior's options, which scenarios it may
// learn from, its dataset's checks, and its models computed once per run setup.
#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <tuple>

#include "common/errors.h"
#include "learning/landscape_cache.h"
#include "learning/landscapes.h"
#include "learning/learners.h"
#include "learning/model_learner.h"
#include "learning/prior_model.h"
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
  // Instead of one such weight, several: a prior for each, averaged by their evidence (empty: the
  // one weight; docs/learning.md "Averaged by their evidence").
  std::vector<double> other_size_weights;
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
                                                scenarios, ridge, other_size_weight,
                                                other_size_weights, scales, keeps)
inline constexpr Limits<double> kRidgeLimits{1e-6, 1e6};
// 0: losses of as many legs alone; above 1 the others count for more.
inline constexpr Limits<double> kOtherSizeWeightLimits{0.0, 1e6};

void validate(const PriorOptions& o) {
  validate(static_cast<const ModelOptions&>(o));
  require_in("ridge", o.ridge, kRidgeLimits);
  require_in("other_size_weight", o.other_size_weight, kOtherSizeWeightLimits);
  for (double w : o.other_size_weights) require_in("other_size_weights", w, kOtherSizeWeightLimits);
  std::vector<double> sorted = o.other_size_weights;
  std::sort(sorted.begin(), sorted.end());
  if (o.other_size_weights.size() == 1 ||
      std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    throw OptionError("other_size_weights",
                      "must list at least two different weights to average over (one weight: "
                      "other_size_weight)");
  }
  if (o.scales != "options" && o.scales != "data") {
    throw OptionError("scales", "must be options or data, got '" + o.scales + "'");
  }
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
  const std::vector<std::size_t>& lost = told.failed();
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
  // A weight of 0 learns from the losses of as many legs alone: there must be one.
  const std::vector<double>& weights = o.other_size_weights;
  const bool zero = weights.empty()
                        ? o.other_size_weight == 0.0
                        : std::find(weights.begin(), weights.end(), 0.0) != weights.end();
  if (told.told() && zero && std::none_of(out.begin(), out.end(), [&](const ScenarioLandscape* s) {
        return s->failed.size() == lost.size();
      })) {
    throw BadInput("the prior's dataset has no loss of " + std::to_string(lost.size()) +
                   " legs it may learn from besides the one under test, so a weight of 0 for the "
                   "others (other_size_weight or other_size_weights) leaves it nothing");
  }
  return out;
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
  const std::vector<std::size_t>& lost = setup.told.failed();
  const Criterion& c = setup.criterion;
  return {setup.told.told(),          lost,     data.withheld,   o.scenarios,  o.ridge,
          o.other_size_weight,        c.path,   c.threshold_deg, c.max_effort, c.trial_windows,
          setup.search.threshold_deg, o.scales, o.keeps};
}

}  // namespace

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
    PriorModel model =
        fit_prior(*data.landscapes, prior_scenarios(*data.landscapes, o, setup.told, data.withheld),
                  setup, space, {o.ridge, o.other_size_weight, o.scales == "data", o.keeps});
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
  // The record names the weights the priors used: one, or the list (and a list given empty is
  // the one weight, as a run recorded before the list existed says).
  if (resolved.at("other_size_weights").empty()) {
    resolved.erase("other_size_weights");
  } else {
    if (asked.contains("other_size_weight")) {
      throw OptionError("other_size_weight",
                        "is unused beside other_size_weights (give one of them)");
    }
    resolved.erase("other_size_weight");
  }
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
  const ModelLearnerParams params = model_learner_params(o);
  std::vector<ModelPrior> priors;
  // Told nothing, every loss counts alike (learning/prior_model.h): one prior, of weight 1.
  std::vector<double> weights{1.0};
  if (setup.told.told()) {
    weights = o.other_size_weights.empty() ? std::vector<double>{o.other_size_weight}
                                           : o.other_size_weights;
  }
  for (double weight : weights) {
    PriorOptions one = o;
    one.other_size_weight = weight;
    PriorModel model = data.computed->get(data, setup, space, one);
    priors.push_back({model.scales.value_or(params.model), std::move(model.mean),
                      std::move(model.keep), weight});
  }
  return std::make_unique<ModelLearner>(setup, params, std::move(priors));
}

}  // namespace multicpg::learning
