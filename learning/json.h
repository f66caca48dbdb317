// The learning options as JSON (nlohmann's type macros): keys are the member names, a missing key
// keeps its default, enums are their names (an unknown name is an error, unlike nlohmann's enum
// macro, which silently takes the first value). Recorded with every result and read from
// experiment files.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "body/course_json.h"
#include "common/json_optional.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "learning/learners.h"

namespace multicpg::learning {

inline void to_json(nlohmann::json& j, Mode mode) {
  j = std::string(to_string(mode));
}
inline void from_json(const nlohmann::json& j, Mode& mode) {
  mode = parse_mode(j.get<std::string>());
}
inline void to_json(nlohmann::json& j, Steering steering) {
  j = std::string(to_string(steering));
}
inline void from_json(const nlohmann::json& j, Steering& steering) {
  steering = parse_steering(j.get<std::string>());
}

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(AnnealingParams, beta, threshold_deg, max_trials,
                                                period_set)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SteeringParams, heading_gain, lateral_gain,
                                                integral_gain, max_heading_offset_deg, max_effort)
// The reflex as a run left it (a checkpoint of a steering simulation), every key required.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SteeringState, course, offset_integral_m_steps, last_cut)
// A run's record keeps the form runs had when the paper's annealing was the only learner: the
// search's bounds and the annealing's beta together as "annealing", the learner written only
// when it is not the annealing (every run recorded before there were other learners reads back as
// the annealing, byte for byte). The type macro's own field expansion (NLOHMANN_JSON_PASTE, as
// NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT uses it) writes every other field.
#define MULTICPG_COMPENSATION_FIELDS                                                  \
  mode, window_steps, settle_steps, detection_windows, hold_windows, monitor_windows, \
      max_episodes, step_budget, learn_periods, steering, steering_params, seed
inline void to_json(nlohmann::json& nlohmann_json_j, const CompensationOptions& nlohmann_json_t) {
  NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, MULTICPG_COMPENSATION_FIELDS))
  nlohmann_json_j["annealing"] = annealing_params(
      nlohmann_json_t.search, annealing_beta(nlohmann_json_t.learner).value_or(kDefaultBeta));
  // Written only when off, so every run recorded before it existed reads back byte for byte.
  if (!nlohmann_json_t.tell_fault) nlohmann_json_j["tell_fault"] = false;
  LearnerChoice without_beta = nlohmann_json_t.learner;
  if (without_beta.name == kPaperLearner) without_beta.options.erase("beta");
  if (without_beta != LearnerChoice{}) nlohmann_json_j["learner"] = nlohmann_json_t.learner;
}
// Throws OptionError ("annealing.beta") when the record gives a beta to a learner other than the
// annealing, or two different betas to the annealing.
inline void from_json(const nlohmann::json& nlohmann_json_j, CompensationOptions& nlohmann_json_t) {
  const CompensationOptions nlohmann_json_default_obj;
  NLOHMANN_JSON_EXPAND(
      NLOHMANN_JSON_PASTE(NLOHMANN_JSON_FROM_WITH_DEFAULT, MULTICPG_COMPENSATION_FIELDS))
  const AnnealingParams annealing = nlohmann_json_j.value(
      "annealing", annealing_params(nlohmann_json_default_obj.search, kDefaultBeta));
  nlohmann_json_t.search = {annealing.period_set, annealing.threshold_deg, annealing.max_trials};
  nlohmann_json_t.tell_fault = nlohmann_json_j.value("tell_fault", true);
  nlohmann_json_t.learner = nlohmann_json_j.value("learner", LearnerChoice{});
  LearnerChoice& learner = nlohmann_json_t.learner;
  if (learner.name == kPaperLearner && learner.options.is_object()) {
    if (!learner.options.contains("beta")) {
      learner.options["beta"] = annealing.beta;
    } else if (annealing.beta != kDefaultBeta && learner.options.at("beta") != annealing.beta) {
      throw OptionError("annealing.beta", "and learner.options.beta give the annealing two betas");
    }
  } else if (learner.name != kPaperLearner && annealing.beta != kDefaultBeta) {
    throw OptionError("annealing.beta",
                      "is the annealing's option; the learner '" + learner.name + "' has none");
  }
}
#undef MULTICPG_COMPENSATION_FIELDS

}  // namespace multicpg::learning
