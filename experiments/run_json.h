// A run's description and results as they are saved: `learn --json`, `tunnel --json`, the run
// files of experiments. The records keep the form earlier versions wrote, so results stay
// comparable byte for byte: the learning options carry the run's faults as `disabled` and
// `fail_step` (one failure) or `faults` (any other timeline).
#pragma once

#include <nlohmann/json.hpp>

#include "experiments/run_spec.h"
#include "experiments/tunnel.h"
#include "learning/compensation.h"

namespace multicpg::experiments {

// The learning options with the run's faults in the recorded form: one failure as `disabled`
// (leg indices) and `fail_step`, any other timeline as `faults`.
nlohmann::json learning_record(const learning::CompensationOptions& options,
                               const body::FaultTimeline& faults);

// `learn --json`: learning::to_json of the result (failing legs named), with robot (and
// robot_file), disable_at (the step of the first fault) and the options (learning_record).
nlohmann::json learn_json(const RunSpec& spec, const learning::LearningResult& result);

// `tunnel --json`: passed, touched_wall, steps, forward_m, lateral_m, deviation_deg, periods
// (leg name -> period), robot_file with a robot file, the tunnel's size and `scale` when it was
// scaled to the robot, and, after learning, the learning result and its options.
nlohmann::json tunnel_json(const RunSpec& spec, const TunnelOutcome& outcome,
                           const std::optional<TunnelScale>& scale = std::nullopt);

// The run's faults other than whole legs failing, as the CLI writes them ("R2.CTr:locked@0,
// imu:noise=1@0"); empty when there are none.
std::string other_faults_text(const RunSpec& spec);

}  // namespace multicpg::experiments
