#include "apps/options.h"

#include "common/errors.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {
void require_gait_period(int period, const std::string& flag) {
  if (!robot::is_gait_period(period)) throw BadInput(flag + ": " + robot::no_gait_message(period));
}

std::vector<std::size_t> parse_leg_flag(const robot::Morphology& morph, const std::string& text,
                                        const std::string& flag) {
  try {
    return robot::parse_leg_set(morph, text);
  } catch (const BadInput& e) {
    throw BadInput(flag + ": " + e.what());
  }
}

std::vector<int> parse_periods_flag(const robot::Morphology& morph, const std::string& text,
                                    const std::string& flag) {
  try {
    return robot::parse_period_map(morph, text, robot::kDefaultPeriod);
  } catch (const BadInput& e) {
    throw BadInput(flag + ": " + e.what());
  }
}

}  // namespace multicpg::apps
