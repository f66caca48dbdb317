#include "neural/validate.h"

#include <string>

#include "common/errors.h"
#include "common/limits.h"
#include "neural/json.h"

namespace multicpg::neural {

void validate(const ControllerParams& params) {
  // Walks the recorded form, so a parameter added to a struct is checked without a new line here.
  const nlohmann::json all = params;
  for (const auto& [stage, values] : all.items()) {
    for (const auto& [name, value] : values.items()) {
      const std::string key = stage + "." + name;
      if (value.is_number_integer()) {
        require_in(key, value.get<int>(), Limits<int>{0, kMaxDelayStep});
      } else {
        require_in(key, value.get<double>(),
                   Limits<double>{-kMaxParamMagnitude, kMaxParamMagnitude});
      }
    }
  }
}

}  // namespace multicpg::neural
