// A run's description and results as they are saved: `learn --json`, `walk --json`, `tunnel
// --json`, the run files of experiments; each record's reader beside its writer. The records keep
// the form earlier versions wrote, so results stay comparable byte for byte: the learning options
// carry the run's faults as `disabled` and `fail_step` (one failure) or `faults` (any other
// timeline).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "body/deviation.h"
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

// The run a learn_json record describes, to make it again (report/replay/rerun.h): its robot,
// learning options, faults and start; the simulation options are `sim`. Throws BadInput "NAME:
// KEY: what" for a bad value (an unknown robot or leg, a robot file that changed since) and
// nlohmann's exception for a missing or mistyped field.
RunSpec read_learn_json(const nlohmann::json& saved, const std::string& name,
                        const sim::SimOptions& sim = {});

// A walk as `walk --json` records it: what was walked and what it measured, on the simulation or
// a real robot.
struct WalkRecord {
  const RunSpec* spec = nullptr;  // robot, start (warm-up) and faults
  long settle = 0;
  long steps = 0;
  long window = 0;
  std::vector<int> periods;  // every leg's, as the walk started
  double control_dt = 0.0;
  std::optional<double> physics_dt;  // the simulation's
  bool senses_position = true;
  body::WalkMeasure measure;
  double duration_s = 0.0;
  nlohmann::json hardware;  // a real robot's record
};

// `walk --json`: robot (and robot_file), periods, faults (legs named), warmup, settle, steps,
// window, the time steps, and what was measured: distance_m, forward_m, lateral_m, speed_m_s
// (null without a sensed position), window_deviations_deg, windows, final_yaw_deg; hardware for a
// real robot's walk.
nlohmann::json walk_json(const WalkRecord& walk);

// The walk a walk_json record describes, to walk it again (report/replay/rerun.h): the run
// (robot, periods, warm-up, faults; the simulation options `sim` with the recorded time steps)
// and its settle, steps and window.
struct RecordedWalk {
  RunSpec spec;
  long settle = 0;
  long steps = 0;
  long window = 0;
};
// Throws BadInput "NAME: KEY: what" for a bad value (an unknown robot or leg, a robot file that
// changed since) and nlohmann's exception for a missing or mistyped field.
RecordedWalk read_walk_json(const nlohmann::json& saved, const std::string& name,
                            const sim::SimOptions& sim = {});

// `tunnel --json`: passed, touched_wall, steps, forward_m, lateral_m, deviation_deg, periods
// (leg name -> period), robot_file with a robot file, the tunnel's size and `scale` when it was
// scaled to the robot, and, after learning, the learning result and its options.
nlohmann::json tunnel_json(const RunSpec& spec, const TunnelOutcome& outcome,
                           const std::optional<TunnelScale>& scale = std::nullopt);

// The run's faults other than whole legs failing, as the CLI writes them ("R2.CTr:locked@0,
// imu:noise=1@0"); empty when there are none.
std::string other_faults_text(const RunSpec& spec);

}  // namespace multicpg::experiments
