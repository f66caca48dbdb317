#include "body/course_json.h"

#include "common/errors.h"

namespace multicpg::body {

void to_json(nlohmann::json& j, const Fault& fault) {
  j = {{"step", fault.step}, {"legs", fault.legs}, {"recover", fault.recover}};
  if (std::holds_alternative<LegFault>(fault.kind) && !fault.joint) return;
  j["kind"] = kind_name(fault.kind);
  if (fault.joint) j["joint"] = robot::to_string(*fault.joint);
  if (const std::optional<double> v = value_of(fault.kind)) j["value"] = *v;
}

nlohmann::json faults_record(const FaultTimeline& faults) {
  const bool single = faults.size() == 1 && !faults.front().recover &&
                      std::holds_alternative<LegFault>(faults.front().kind) &&
                      !faults.front().joint;
  return {{"disabled", single ? faults.front().legs : std::vector<std::size_t>{}},
          {"fail_step", single ? faults.front().step : 0L},
          {"faults", single ? FaultTimeline{} : faults}};
}

void from_json(const nlohmann::json& j, Fault& fault) {
  fault.step = j.value("step", 0L);
  fault.legs = j.value("legs", std::vector<std::size_t>{});
  fault.recover = j.value("recover", false);
  fault.joint.reset();
  if (j.contains("joint")) fault.joint = robot::parse_joint(j.at("joint").get<std::string>());
  std::optional<double> value;
  if (j.contains("value")) value = j.at("value").get<double>();
  fault.kind = make_kind(j.value("kind", std::string(LegFault::kName)), value, fault.recover);
}

}  // namespace multicpg::body
