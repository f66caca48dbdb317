#include "experiments/run_json.h"

#include "body/course_json.h"
#include "body/events.h"
#include "body/fault_spec.h"
#include "common/errors.h"
#include "common/json_optional.h"
#include "learning/json.h"
#include "robot/leg_sets.h"

namespace multicpg::experiments {
namespace {

// What `read` reads from the field `key` of the record `name`; a bad value (BadInput, e.g. an
// unknown leg) names the record and the field.
template <class Read>
auto field(const std::string& name, std::string_view key, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const OptionError& e) {
    throw BadInput(name + ": " + e.key() + ": " + e.what());
  } catch (const BadInput& e) {
    throw BadInput(name + ": " + std::string(key) + ": " + e.what());
  }
}

}  // namespace

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

RunSpec read_learn_json(const nlohmann::json& saved, const std::string& name,
                        const sim::SimOptions& sim) {
  RunSpec spec;
  spec.robot = field(name, "robot", [&] { return recorded_robot(saved); });
  spec.robot.sim = sim;
  const nlohmann::json& recorded = saved.at("options");
  const learning::CompensationOptions& options = spec.learning.emplace(field(name, "options", [&] {
    learning::CompensationOptions o;
    from_json(recorded, o);
    return o;
  }));
  spec.faults = field(name, "options.faults", [&] {
    return !recorded.at("faults").empty()
               ? recorded.at("faults").get<body::FaultTimeline>()
               : body::fail_at(recorded.at("disabled").get<std::vector<std::size_t>>(),
                               recorded.at("fail_step").get<long>());
  });
  spec.start = learning_start(options.mode);
  return spec;
}

nlohmann::json walk_json(const WalkRecord& w) {
  const robot::Morphology& morph = morphology(w.spec->robot);
  nlohmann::json faults = nlohmann::json::array();
  for (const body::Fault& f : w.spec->faults) {
    // A fault's one shape (body/course_json.h), its legs named as --disable names them.
    nlohmann::json fault = f;
    fault["legs"] = robot::leg_set_name(morph, f.legs);
    faults.push_back(fault);
  }
  // Without a sensed position there is no path angle nor distance: null, never a made-up one.
  const auto sensed = [&](double v) {
    return w.senses_position ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  nlohmann::json windows = nlohmann::json::array();
  for (const body::WindowMeasure& m : w.measure.windows) {
    windows.push_back({{"yaw_deg", m.yaw_deg}, {"path_deg", sensed(m.path_deg)}});
  }
  const double speed = w.measure.distance_m / w.duration_s;
  nlohmann::json j{{"robot", morph.name}, {"periods", robot::period_map_json(morph, w.periods)},
                   {"faults", faults},    {"warmup", w.spec->start.warmup},
                   {"settle", w.settle},  {"steps", w.steps},
                   {"window", w.window},  {"control_dt_s", w.control_dt}};
  if (w.physics_dt) j["physics_dt_s"] = *w.physics_dt;
  j["duration_s"] = w.duration_s;
  j["distance_m"] = sensed(w.measure.distance_m);
  j["forward_m"] = sensed(w.measure.forward_m);
  j["lateral_m"] = sensed(w.measure.lateral_m);
  j["speed_m_s"] = sensed(speed);
  j["window_deviations_deg"] = w.measure.window_deviations_deg;
  j["windows"] = windows;
  j["final_yaw_deg"] = w.measure.final_yaw_deg;
  if (!w.hardware.is_null()) j["hardware"] = w.hardware;
  record_robot_file(j, w.spec->robot);
  return j;
}

RecordedWalk read_walk_json(const nlohmann::json& saved, const std::string& name,
                            const sim::SimOptions& sim) {
  RecordedWalk walk;
  RunSpec& spec = walk.spec;
  spec.robot = field(name, "robot", [&] { return recorded_robot(saved); });
  spec.robot.sim = sim;
  spec.robot.sim.control_dt = saved.at("control_dt_s").get<double>();
  spec.robot.sim.physics_dt = saved.at("physics_dt_s").get<double>();
  const robot::Morphology& morph = morphology(spec.robot);
  spec.start.periods = field(
      name, "periods", [&] { return robot::period_map_from_json(morph, saved.at("periods")); });
  spec.start.warmup = saved.at("warmup").get<long>();
  for (const nlohmann::json& f : saved.at("faults")) {
    spec.faults.push_back(field(name, "faults", [&] {
      if (f.contains("fault")) {
        // Walk records before the fault's one shape gave any other kind as its text.
        return body::parse_fault(
            morph,
            f.at("fault").get<std::string>() + '@' + std::to_string(f.at("step").get<long>()),
            f.at("recover").get<bool>());
      }
      nlohmann::json indexed = f;  // body/course_json.h, its legs named as walk_json names them
      indexed["legs"] = robot::parse_leg_set(morph, f.at("legs").get<std::string>());
      return indexed.get<body::Fault>();
    }));
  }
  body::sort_timeline(spec.faults);
  walk.settle = saved.at("settle").get<long>();
  walk.steps = saved.at("steps").get<long>();
  walk.window = saved.at("window").get<long>();
  return walk;
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
