// libFuzzer target for the text multicpg accepts from users and from disk: leg lists (--disable),
// period specs (--periods) and saved run files (experiments::parse_sealed). Every input goes to
// every parser; each must either accept it or throw BadInput. Anything else (another exception,
// a crash, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "apps/options.h"
#include "common/errors.h"
#include "experiments/runner.h"
#include "robot/leg_sets.h"
#include "robot/morphology.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace multicpg;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (robot::RobotKind kind : robot::kRobotKinds) {
    const robot::Morphology& morph = robot::morphology(kind);
    try {
      robot::parse_leg_set(morph, text);
    } catch (const BadInput&) {
    }
    try {
      robot::parse_period_map(morph, text, robot::kDefaultPeriod);
    } catch (const BadInput&) {
    }
  }
  try {
    experiments::parse_sealed(text, "fuzz.json");
  } catch (const BadInput&) {
  }
  return 0;
}
