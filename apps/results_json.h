// The JSON results of `learn --json` and `tunnel --json`, one home for the CLI and the Python API
// (issue 11), so both give the same data.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "experiments/tunnel.h"
#include "learning/compensation.h"
#include "robot/morphology.h"

namespace multicpg::apps {

// learning::to_json of the result (failing legs named), with robot, seed, beta, threshold_deg,
// window_steps, disable_at (the --disable-at given) and the options.
nlohmann::json learn_json(const robot::Morphology& morph,
                          const learning::CompensationOptions& options,
                          const learning::LearningResult& result, long disable_at);

// passed, touched_wall, steps, forward_m, lateral_m, deviation_deg, periods (leg name -> period)
// and, after learning, the learning result and its options.
nlohmann::json tunnel_json(const robot::Morphology& morph, const experiments::TunnelRun& run,
                           const std::vector<int>& periods,
                           const std::vector<std::size_t>& disabled,
                           const learning::LearningResult* learned,
                           const learning::CompensationOptions* learn);

}  // namespace multicpg::apps
