// TEMPORARY (removed when main's typed option serialisation, issue 9 item 1, is merged):
// nlohmann to_json/from_json of the option structs with the contract's keys (C++ member names,
// missing keys keep defaults), so the experiment-file layer can be built and tested before.
#pragma once

#include <nlohmann/json.hpp>

#include "learning/compensation.h"
#include "sim/sim.h"

namespace multicpg::learning {
NLOHMANN_JSON_SERIALIZE_ENUM(Mode, {{Mode::robust, "robust"}, {Mode::paper, "paper"}})
NLOHMANN_JSON_SERIALIZE_ENUM(Steering, {{Steering::off, "off"}, {Steering::reflex, "reflex"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(AnnealingParams, beta, threshold_deg, max_trials,
                                                period_set)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SteeringParams, heading_gain, lateral_gain,
                                                integral_gain, max_heading_offset_deg, max_effort)
}  // namespace multicpg::learning
namespace multicpg::sim {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Fault, step, legs, recover)
}
namespace multicpg::learning {
inline void to_json(nlohmann::json& j, const CompensationOptions& o) {
  j = {{"mode", o.mode},
       {"annealing", o.annealing},
       {"disabled", o.disabled},
       {"fail_step", o.fail_step},
       {"faults", o.faults},
       {"window_steps", o.window_steps},
       {"settle_steps", o.settle_steps ? nlohmann::json(*o.settle_steps) : nlohmann::json()},
       {"detection_windows", o.detection_windows},
       {"hold_windows", o.hold_windows},
       {"monitor_windows", o.monitor_windows},
       {"max_episodes", o.max_episodes},
       {"learn_periods", o.learn_periods},
       {"steering", o.steering},
       {"steering_params", o.steering_params},
       {"seed", o.seed}};
}
inline void from_json(const nlohmann::json& j, CompensationOptions& o) {
  const CompensationOptions d;
  o.mode = j.value("mode", d.mode);
  o.annealing = j.value("annealing", d.annealing);
  o.disabled = j.value("disabled", d.disabled);
  o.fail_step = j.value("fail_step", d.fail_step);
  o.faults = j.value("faults", d.faults);
  o.window_steps = j.value("window_steps", d.window_steps);
  if (j.contains("settle_steps") && !j.at("settle_steps").is_null()) {
    o.settle_steps = j.at("settle_steps").get<long>();
  }
  o.detection_windows = j.value("detection_windows", d.detection_windows);
  o.hold_windows = j.value("hold_windows", d.hold_windows);
  o.monitor_windows = j.value("monitor_windows", d.monitor_windows);
  o.max_episodes = j.value("max_episodes", d.max_episodes);
  o.learn_periods = j.value("learn_periods", d.learn_periods);
  o.steering = j.value("steering", d.steering);
  o.steering_params = j.value("steering_params", d.steering_params);
  o.seed = j.value("seed", d.seed);
}
}  // namespace multicpg::learning
namespace multicpg::robot {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(Scene, tunnel, tunnel_length, tunnel_width)
}
namespace multicpg::sim {
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(SimOptions, control_dt, physics_dt, servo_gain,
                                                scene)
}
