// The JSON result of `learn --json`, one home for the CLI and the Python API
// (issue 11), so both give the same data.
#pragma once

#include <nlohmann/json.hpp>

#include "learning/compensation.h"
#include "robot/morphology.h"

namespace multicpg::apps {

// learning::to_json of the result (failing legs named), with robot, seed, beta, threshold_deg,
// window_steps, disable_at (the --disable-at given) and the options.
nlohmann::json learn_json(const robot::Morphology& morph,
                          const learning::CompensationOptions& options,
                          const learning::LearningResult& result, long disable_at);

}  // namespace multicpg::apps
