// The learners by name: which one a run uses, with its options, and the one table that lists them
// (learning/learners.cpp). learning/learner.h says what a learner is and how to add one.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.h"
#include "learning/landscapes.h"
#include "learning/learner.h"

namespace multicpg::learning {

// The paper's simulated annealing (paper §3, Table 2): paper mode's learner, and the one a record
// that names none ran. A run that names none gets learning/default_learner.h's.
inline constexpr std::string_view kPaperLearner = "annealing";

// Which learner a run uses and its own options, every default filled in once resolved. A run
// records it (learning/json.h) beside the search's bounds (CompensationOptions::annealing), so
// every option that decides a result is saved with it. The options stay a JSON table between
// here and the learner's own file, where they are read into the learner's typed struct: that
// keeps adding a learner to one file and one table row.
struct LearnerChoice {
  std::string name = std::string(kPaperLearner);
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

// The options of a resolved `choice` that differ from its learner's defaults (a run's header names
// them), keys sorted.
nlohmann::json changed_options(const LearnerChoice& choice);

// What the prior computed from its data once (learning/prior.cpp).
class PriorMeans;

// What a learner learns from besides its trials (docs/learning.md "A learner's data"), resolved
// once before a run and passed to every learner the run makes: the prior's landscape dataset and
// the file it was read from; nothing for a learner that learns from its trials alone.
struct LearnerData {
  std::shared_ptr<const LandscapeDataset> landscapes;  // null: no data
  std::filesystem::path source;                        // the file the landscapes were read from
  // Scenarios (failed legs, sorted) the learner may never learn from, nor from their mirror
  // images, whatever it is told: the scenario a replay benchmark replays. What it may see is
  // this rule, apart from what it is told (ToldFault).
  std::vector<std::vector<std::size_t>> withheld;
  // What learners computed from the landscapes once (the prior's means, learning/prior.cpp),
  // shared by every copy of these data: the benchmark makes thousands of learners from one.
  std::shared_ptr<PriorMeans> computed;
};

// The data `choice` learns from in a run of `robot` whose trials `criterion` judges: the dataset
// its options name, or the repository's walked that way (repository_dataset), read here; empty
// for a learner that needs none. Throws BadInput naming the file it cannot read.
LearnerData learner_data(const LearnerChoice& choice, robot::RobotKind robot,
                         const Criterion& criterion);

// Checks what a learner needs of a run before it starts, for a run of `robot` whose learner is
// `told` about the fault and whose trials `criterion` judges: its data, walked the way the run
// judges and of the run's robot, that a prior never sees the scenario it is told nor a withheld
// one, and, when `period_set` is not empty, that its data have the run's period set: all before
// the robot walks. Throws OptionError ("options.<key>") or BadInput naming the file.
void check_learner(const LearnerChoice& choice, const LearnerData& data, robot::RobotKind robot,
                   const ToldFault& told, const Criterion& criterion,
                   const std::vector<int>& period_set = {});
// The same with the data resolved here (learner_data), which it returns for the run.
LearnerData check_learner(const LearnerChoice& choice, robot::RobotKind robot,
                          const ToldFault& told, const Criterion& criterion,
                          const std::vector<int>& period_set = {});

// A resolved choice's learner for one episode, learning from `data` (learner_data's, checked).
// Throws BadInput for a setup the learner cannot search (as start_annealing: every leg fixed, a
// start outside the period set, ...).
std::unique_ptr<Learner> make_learner(const LearnerChoice& choice, const LearnerSetup& setup,
                                      const LearnerData& data);

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
      const nlohmann::json& wanted = defaults.at(key);
      const std::string type = wanted.type_name();
      if (value.type() == wanted.type()) {
        throw OptionError(key, "holds a value of the wrong type: got " + value.dump());
      }
      const bool vowel = type == "array" || type == "object";
      throw OptionError(
          key, std::string(vowel ? "must be an " : "must be a ") + type + ", got " + value.dump());
    }
  }
  const Options options = asked.get<Options>();
  validate(options);
  return options;
}

}  // namespace multicpg::learning
