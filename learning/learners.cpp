#include "learning/learners.h"

#include <algorithm>
#include <set>

#include "common/user_text.h"
#include "learning/annealing.h"
#include "learning/forecast.h"
#include "learning/model_learner.h"

namespace multicpg::learning {

// Each learner's file defines these two functions (learning/learner.h "To add a learner").
nlohmann::json annealing_options(const nlohmann::json& asked);
std::unique_ptr<Learner> make_annealing(const LearnerSetup& setup, const nlohmann::json& options,
                                        const LearnerData& data);
nlohmann::json random_options(const nlohmann::json& asked);
std::unique_ptr<Learner> make_random(const LearnerSetup& setup, const nlohmann::json& options,
                                     const LearnerData& data);
nlohmann::json greedy_options(const nlohmann::json& asked);
std::unique_ptr<Learner> make_greedy(const LearnerSetup& setup, const nlohmann::json& options,
                                     const LearnerData& data);
nlohmann::json bayes_options(const nlohmann::json& asked);
std::unique_ptr<Learner> make_bayes(const LearnerSetup& setup, const nlohmann::json& options,
                                    const LearnerData& data);
nlohmann::json prior_options(const nlohmann::json& asked);
std::unique_ptr<Learner> make_prior(const LearnerSetup& setup, const nlohmann::json& options,
                                    const LearnerData& data);
LearnerData prior_data(const nlohmann::json& options, robot::RobotKind robot,
                       const Criterion& criterion);
void check_prior(const nlohmann::json& options, const LearnerData& data, robot::RobotKind robot,
                 const ToldFault& told, const Criterion& criterion,
                 const std::vector<int>& period_set);

namespace {

// A model-based learner's details: its acquisition score and the forecast of the combination it
// chose (learning/forecast.h).
std::vector<std::string_view> model_details() {
  std::vector<std::string_view> keys{"acquisition"};
  keys.insert(keys.end(), kForecastKeys.begin(), kForecastKeys.end());
  return keys;
}

// The prior's: a model-based learner's and what its priors let a loss of another number of legs
// count for.
std::vector<std::string_view> prior_details() {
  std::vector<std::string_view> keys = model_details();
  keys.push_back(kOtherSizeWeightKey);
  return keys;
}

struct Entry {
  LearnerInfo info;
  nlohmann::json (*options)(const nlohmann::json& asked);
  std::unique_ptr<Learner> (*make)(const LearnerSetup& setup, const nlohmann::json& options,
                                   const LearnerData& data);
  // The data it learns from besides its trials (null: none).
  LearnerData (*data)(const nlohmann::json& options, robot::RobotKind robot,
                      const Criterion& criterion) = nullptr;
  // What can be checked of a run before it starts (null: nothing beyond the options).
  void (*check)(const nlohmann::json& options, const LearnerData& data, robot::RobotKind robot,
                const ToldFault& told, const Criterion& criterion,
                const std::vector<int>& period_set) = nullptr;
};

// The one list of learners.
const std::vector<Entry>& table() {
  static const std::vector<Entry> entries{
      {{"annealing",
        "the paper's simulated annealing over one-leg changes (paper §3, Table 2)",
        {"acceptance_probability", "legs_changed", "redraws", "tabu_redraw"}},
       annealing_options,
       make_annealing},
      {{"random", "random search without replacement over every combination", {}},
       random_options,
       make_random},
      {{"greedy",
        "greedy search over one-leg changes of the best combination so far",
        {"legs_changed"}},
       greedy_options,
       make_greedy},
      {{"bayes", "Gaussian-process Bayesian optimisation over the period grid", model_details()},
       bayes_options,
       make_bayes},
      {{"prior",
        "a GP whose prior mean is what the other leg losses' landscapes predict "
        "(Intelligent Trial and Error)",
        prior_details()},
       prior_options,
       make_prior,
       prior_data,
       check_prior},
  };
  return entries;
}

const Entry& entry(const std::string& name) {
  const std::vector<Entry>& t = table();
  const auto it =
      std::find_if(t.begin(), t.end(), [&](const Entry& e) { return e.info.name == name; });
  if (it == t.end()) {
    std::vector<std::string> names;
    for (const Entry& e : t) names.emplace_back(e.info.name);
    throw OptionError("name", unknown_name("learner", name, names));
  }
  return *it;
}

}  // namespace

std::vector<LearnerInfo> learner_list() {
  std::vector<LearnerInfo> out;
  for (const Entry& e : table()) out.push_back(e.info);
  return out;
}

std::string learner_names() {
  std::string out;
  for (const Entry& e : table()) out += (out.empty() ? "" : ", ") + std::string(e.info.name);
  return out;
}

std::vector<std::string> detail_columns(std::string_view learner,
                                        const std::vector<TrialRecord>& trace) {
  std::set<std::string> keys;
  for (const Entry& e : table()) {
    if (e.info.name == learner) keys.insert(e.info.details.begin(), e.info.details.end());
  }
  for (const TrialRecord& t : trace) {
    for (const auto& [key, value] : t.details.items()) keys.insert(key);
  }
  return {keys.begin(), keys.end()};
}

bool forecasts(std::string_view learner) {
  for (const Entry& e : table()) {
    if (e.info.name != learner) continue;
    return std::find(e.info.details.begin(), e.info.details.end(), kPredictedEKey) !=
           e.info.details.end();
  }
  return false;
}

std::optional<double> annealing_beta(const LearnerChoice& choice) {
  if (choice.name != kPaperLearner) return std::nullopt;
  if (!choice.options.is_object()) return kDefaultBeta;
  const nlohmann::json beta = choice.options.value("beta", nlohmann::json(kDefaultBeta));
  return beta.is_number() ? beta.get<double>() : kDefaultBeta;
}

LearnerChoice resolve_learner(const LearnerChoice& asked) {
  const Entry& e = entry(asked.name);
  if (!asked.options.is_object()) {
    throw OptionError("options", "must be a table of the learner's options");
  }
  LearnerChoice out;
  out.name = asked.name;
  within("options", [&] { out.options = e.options(asked.options); });
  return out;
}

nlohmann::json changed_options(const LearnerChoice& choice) {
  const nlohmann::json defaults = entry(choice.name).options(nlohmann::json::object());
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, value] : choice.options.items()) {
    if (!defaults.contains(key) || defaults.at(key) != value) out[key] = value;
  }
  return out;
}

LearnerData learner_data(const LearnerChoice& choice, robot::RobotKind robot,
                         const Criterion& criterion) {
  const Entry& e = entry(choice.name);
  if (e.data == nullptr) return {};
  LearnerData out;
  within("options", [&] { out = e.data(choice.options, robot, criterion); });
  return out;
}

void check_learner(const LearnerChoice& choice, const LearnerData& data, robot::RobotKind robot,
                   const ToldFault& told, const Criterion& criterion,
                   const std::vector<int>& period_set) {
  const Entry& e = entry(choice.name);
  if (e.check != nullptr) {
    within("options", [&] { e.check(choice.options, data, robot, told, criterion, period_set); });
  }
}

LearnerData check_learner(const LearnerChoice& choice, robot::RobotKind robot,
                          const ToldFault& told, const Criterion& criterion,
                          const std::vector<int>& period_set) {
  LearnerData data = learner_data(choice, robot, criterion);
  check_learner(choice, data, robot, told, criterion, period_set);
  return data;
}

std::unique_ptr<Learner> make_learner(const LearnerChoice& choice, const LearnerSetup& setup,
                                      const LearnerData& data) {
  return entry(choice.name).make(setup, choice.options, data);
}

}  // namespace multicpg::learning
