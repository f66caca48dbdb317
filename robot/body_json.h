// The body parameters and model names as JSON (nlohmann's type macros): keys are the member names,
// a missing key keeps its default, a model is its name (an unknown name is an error). Recorded
// with every result (sim.body, sim.model) and read from experiment files.
#pragma once

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "robot/body_models.h"
#include "robot/body_params.h"

namespace multicpg::robot {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(LegPosture, tc, ctr, fti)
// A leg's posture holds only the joints it sets ({"leg": "R3", "fti": -0.55}).
inline void to_json(nlohmann::json& j, const LegPostureOverride& o) {
  j = nlohmann::json{{"leg", o.leg}};
  if (o.tc) j["tc"] = *o.tc;
  if (o.ctr) j["ctr"] = *o.ctr;
  if (o.fti) j["fti"] = *o.fti;
}
inline void from_json(const nlohmann::json& j, LegPostureOverride& o) {
  o = {};
  o.leg = j.at("leg").get<std::string>();
  if (j.contains("tc")) o.tc = j.at("tc").get<double>();
  if (j.contains("ctr")) o.ctr = j.at("ctr").get<double>();
  if (j.contains("fti")) o.fti = j.at("fti").get<double>();
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(BodyParams, disabled_posture, leg_postures,
                                                lift_body, total_mass, trunk_mass, foot_friction,
                                                trunk_friction, slip, joint_compliance,
                                                torsional_friction, rolling_friction, servo_torque,
                                                servo_speed)
inline void to_json(nlohmann::json& j, BodyModel model) {
  j = std::string(to_string(model));
}
inline void from_json(const nlohmann::json& j, BodyModel& model) {
  model = parse_body_model(j.get<std::string>());
}

// One BodyParams value as listings show it (`model --list`, the report): numbers to 6 digits,
// a posture as TC,CTr,FTi, leg postures as their JSON objects ("none" when there are none).
inline std::string value_text(const BodyParams& params, std::string_view key) {
  const nlohmann::json v = nlohmann::json(params).at(std::string(key));
  const auto number = [](const nlohmann::json& n) {
    return fmt::format("{:.6g}", n.get<double>());
  };
  if (v.is_array()) {
    if (v.empty()) return "none";
    std::string out;
    for (const nlohmann::json& e : v) out += (out.empty() ? "" : "; ") + e.dump();
    return out;
  }
  if (v.is_object())
    return number(v.at("tc")) + "," + number(v.at("ctr")) + "," + number(v.at("fti"));
  return number(v);
}

// `multicpg model --list`: every named model, what it is, and each value with its unit and
// source. The report's calibration section shows the same text (report/stages/calibration.cpp).
inline std::string body_models_listing() {
  std::string out;
  for (BodyModel m : kBodyModels) {
    out += fmt::format("{}{}: {}\n", to_string(m), m == kDefaultBodyModel ? " (default)" : "",
                       describe(m));
    const BodyParams values = body_params(m);
    for (std::string_view key : parameter_keys()) {
      const std::string shown = value_text(values, key) + " " + std::string(value_unit(key));
      out += fmt::format("  {:<20}{:<22}  {}\n", key, shown, value_source(m, key));
    }
    out += "\n";
  }
  return out;
}

}  // namespace multicpg::robot
