#include "apps/results_json.h"

namespace multicpg::apps {

nlohmann::json learn_json(const robot::Morphology& morph,
                          const learning::CompensationOptions& options,
                          const learning::LearningResult& result, long disable_at) {
  nlohmann::json json = learning::to_json(result, morph, learning::failing_legs(options));
  json["robot"] = morph.name;
  json["seed"] = options.seed;
  json["beta"] = options.annealing.beta;
  json["threshold_deg"] = options.annealing.threshold_deg;
  json["window_steps"] = options.window_steps;
  json["disable_at"] = disable_at;
  json["options"] = learning::to_json(options, morph);
  return json;
}

nlohmann::json tunnel_json(const robot::Morphology& morph, const experiments::TunnelRun& run,
                           const std::vector<int>& periods,
                           const std::vector<std::size_t>& disabled,
                           const learning::LearningResult* learned,
                           const learning::CompensationOptions* learn) {
  nlohmann::json j{{"passed", run.passed},       {"touched_wall", run.touched_wall},
                   {"steps", run.steps},         {"forward_m", run.forward_m},
                   {"lateral_m", run.lateral_m}, {"deviation_deg", run.deviation_deg}};
  nlohmann::json by_leg = nlohmann::json::object();
  for (std::size_t i = 0; i < morph.size(); ++i) by_leg[morph.legs[i].name] = periods[i];
  j["periods"] = by_leg;
  if (learned != nullptr && learn != nullptr) {
    j["learning"] = learning::to_json(*learned, morph, disabled);
    j["options"] = learning::to_json(*learn, morph);
  }
  return j;
}

}  // namespace multicpg::apps
