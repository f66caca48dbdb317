#include "sim/fault_spec.h"

#include <charconv>

#include "common/errors.h"
#include "robot/leg_sets.h"

namespace multicpg::sim {

long parse_step(std::string_view text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < 0 || value > kMaxSteps) {
    throw BadInput("'" + std::string(text) + "' is not a step in 0.." + std::to_string(kMaxSteps));
  }
  return value;
}

Fault parse_fault(const robot::Morphology& morph, std::string_view text, bool recover) {
  const std::size_t at = text.find('@');
  if (at == std::string_view::npos || at == 0 || at + 1 == text.size()) {
    throw BadInput("takes LEGS@STEP, e.g. R1@0 or R1,R3@6000; got '" + std::string(text) + "'");
  }
  Fault f;
  f.recover = recover;
  f.legs = robot::parse_leg_set(morph, text.substr(0, at));
  f.step = parse_step(text.substr(at + 1));
  return f;
}

std::string fault_text(const robot::Morphology& morph, const Fault& fault) {
  return robot::leg_set_name(morph, fault.legs) + "@" + std::to_string(fault.step);
}

}  // namespace multicpg::sim
