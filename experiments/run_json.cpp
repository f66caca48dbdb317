#include "experiments/run_json.h"

#include "body/course_json.h"
#include "body/fault_spec.h"
#include "common/json_optional.h"
#include "learning/json.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {

nlohmann::json learning_record(const learning::CompensationOptions& options,
                               const body::FaultTimeline& faults) {
  nlohmann::json j = options;
  j.update(body::faults_record(faults));
  return j;
}

nlohmann::json learn_json(const RunSpec& spec, const learning::LearningResult& result) {
  const robot::Morphology& morph = morphology(spec.robot);
  nlohmann::json json = learning::to_json(result, morph, body::failing_legs(spec.faults));
  json["robot"] = morph.name;
  json["disable_at"] = spec.faults.empty() ? 0L : spec.faults.front().step;
  json["options"] = learning_record(*spec.learning, spec.faults);
  record_robot_file(json, spec.robot);
  return json;
}

std::string other_faults_text(const RunSpec& spec) {
  std::string out;
  for (const body::Fault& f : spec.faults) {
    if (std::holds_alternative<body::LegFault>(f.kind) && !f.joint) continue;
    out += (out.empty() ? "" : ", ") + body::fault_text(morphology(spec.robot), f);
  }
  return out;
}

nlohmann::json tunnel_json(const RunSpec& spec, const TunnelOutcome& o,
                           const std::optional<TunnelScale>& scale) {
  const robot::Morphology& morph = morphology(spec.robot);
  const TunnelRun& run = o.run;
  nlohmann::json j{{"passed", run.passed},       {"touched_wall", run.touched_wall},
                   {"steps", run.steps},         {"forward_m", run.forward_m},
                   {"lateral_m", run.lateral_m}, {"deviation_deg", run.deviation_deg}};
  j["periods"] = robot::period_map_json(morph, o.periods);
  if (spec.hardware) {
    // What a real robot adds: the heading's change (all there is without a sensed position) and
    // its hardware record.
    j["yaw_change_deg"] = run.yaw_change_deg;
    j["hardware"] = run.hardware;
  }
  // Faults other than whole legs failing (those are in "learning" or the periods' gaps).
  if (!other_faults_text(spec).empty()) j["faults"] = spec.faults;
  if (o.learned) {
    j["learning"] = learning::to_json(*o.learned, morph, o.disabled);
    j["options"] = learning_record(*spec.learning, spec.faults);
  }
  record_robot_file(j, spec.robot);
  if (scale) {
    j["tunnel"] = {{"length_m", spec.robot.sim.scene.tunnel_length},
                   {"width_m", spec.robot.sim.scene.tunnel_width},
                   {"scale", *scale}};
  }
  return j;
}

}  // namespace multicpg::experiments
