#include "apps/results_json.h"

#include "learning/json.h"

namespace multicpg::apps {

nlohmann::json learn_json(const robot::Morphology& morph,
                          const learning::CompensationOptions& options,
                          const learning::LearningResult& result, long disable_at) {
  nlohmann::json json = learning::to_json(result, morph, learning::failing_legs(options));
  json["robot"] = morph.name;
  json["disable_at"] = disable_at;
  json["options"] = options;
  return json;
}

}  // namespace multicpg::apps
