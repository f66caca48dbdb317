// The learners by name: which one a run uses, with its options, and the one table that lists them
// (learning/learners.cpp). learning/learner.h says what a learner is and how to add one.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.h"
#include "learning/learner.h"

namespace multicpg::learning {

// The paper's simulated annealing (paper §3, Table 2).
inline constexpr std::string_view kDefaultLearner = "annealing";

// Which learner a run uses and its own options, every default filled in once resolved. A run
// records it (learning/json.h) beside the search's bounds (CompensationOptions::annealing), so
// every option that decides a result is saved with it. The options stay a JSON table between
// here and the learner's own file, where they are read into the learner's typed struct: that
// keeps adding a learner to one file and one table row.
struct LearnerChoice {
  std::string name = std::string(kDefaultLearner);
  nlohmann::json options = nlohmann::json::object();
  bool operator==(const LearnerChoice&) const = default;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(LearnerChoice, name, options)

struct LearnerInfo {
  std::string_view name;
  std::string_view summary;  // one line, for --help and the report
  // The keys of the details its trials carry (TrialRecord::details): the columns of trace
  // tables, there even when an episode tried nothing.
  std::vector<std::string_view> details;
};
// Every learner, in the order of the table.
std::vector<LearnerInfo> learner_list();
// "annealing, random, ...": the names, for messages.
std::string learner_names();

// The columns of `learner`'s details for a trace table: the ones it declares, and any other key
// a record of `trace` carries, sorted.
std::vector<std::string> detail_columns(std::string_view learner,
                                        const std::vector<TrialRecord>& trace);

// Whether `learner`'s trials record its model's forecast (learning/forecast.h): the model-based
// learners.
bool forecasts(std::string_view learner);

// The annealing's beta in `choice` (its option "beta", kDefaultBeta when not given); nothing for
// another learner, which has no beta.
std::optional<double> annealing_beta(const LearnerChoice& choice);

// The choice with every default filled in. Throws OptionError: key "name" for an unknown
// learner (naming the known ones), "options.<key>" for an unknown option or a bad value.
LearnerChoice resolve_learner(const LearnerChoice& asked);

// Checks what a learner needs of a run before it starts, for a run of `robot` whose legs
// `failed` fail and whose trials `criterion` judges (its data, walked the way the run judges,
// and that a prior never sees the scenario under test) and, when `period_set` is not empty, that
// its data have the run's period set: all before the robot walks. Throws OptionError
// ("options.<key>") or BadInput naming the file.
void check_learner(const LearnerChoice& choice, robot::RobotKind robot,
                   const std::vector<std::size_t>& failed, const Criterion& criterion,
                   const std::vector<int>& period_set = {});

// A resolved choice's learner for one episode. Throws BadInput for a setup the learner cannot
// search (as start_annealing: every leg fixed, a start outside the period set, ...).
std::unique_ptr<Learner> make_learner(const LearnerChoice& choice, const LearnerSetup& setup);

// A learner without options of its own.
struct NoLearnerOptions {
  bool operator==(const NoLearnerOptions&) const = default;
};
inline void to_json(nlohmann::json& j, const NoLearnerOptions&) {
  j = nlohmann::json::object();
}
inline void from_json(const nlohmann::json&, NoLearnerOptions&) {}
inline void validate(const NoLearnerOptions&) {}

// Reads a learner's options into its struct `Options` (defaults for keys not given; nlohmann's
// type macros with defaults), checks them with its validate(), and returns them whole as JSON.
// Throws OptionError naming the key for an unknown option or a value of the wrong type.
template <class Options>
nlohmann::json read_learner_options(const nlohmann::json& asked) {
  if (!asked.is_object()) throw OptionError("", "must be a table of options");
  const nlohmann::json defaults = Options{};
  for (const auto& [key, value] : asked.items()) {
    if (!defaults.contains(key)) {
      std::string known;
      for (const auto& [k, v] : defaults.items()) known += (known.empty() ? "" : ", ") + k;
      throw OptionError(key, "is not an option of this learner (" +
                                 (known.empty() ? std::string("it has none") : "known: " + known) +
                                 ")");
    }
    nlohmann::json probe = defaults;
    probe[key] = value;
    try {
      (void)probe.get<Options>();
    } catch (const nlohmann::json::exception&) {
      throw OptionError(
          key, "must be a " + std::string(defaults.at(key).type_name()) + ", got " + value.dump());
    }
  }
  const Options options = asked.get<Options>();
  validate(options);
  return options;
}

}  // namespace multicpg::learning
