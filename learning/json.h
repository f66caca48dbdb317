// The learning options as JSON (nlohmann's type macros): keys are the member names, a missing key
// keeps its default, enums are their names (an unknown name is an error, unlike nlohmann's enum
// macro, which silently takes the first value). Recorded with every result and read from
// experiment files.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "common/json_optional.h"
#include "learning/compensation.h"
#include "sim/course_json.h"

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
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(CompensationOptions, mode, annealing, window_steps,
                                                settle_steps, detection_windows, hold_windows,
                                                monitor_windows, max_episodes, learn_periods,
                                                steering, steering_params, seed)

}  // namespace multicpg::learning
