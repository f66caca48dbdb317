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

}  // namespace multicpg::apps
