#include "body/fault_spec.h"

#include <charconv>
#include <cmath>
#include <optional>

#include "common/errors.h"
#include "robot/leg_sets.h"

namespace multicpg::body {
namespace {

const std::string kForm =
    "takes LEGS@STEP, LEGS[.JOINT]:KIND[=VALUE]@STEP or imu:KIND=VALUE@STEP (e.g. R1@0, "
    "R2.CTr:locked@0, L1:weak=0.3@500, imu:drift=0.5@0)";

// A value written after '=': a finite number, nothing else.
double parse_value(std::string_view text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw BadInput("'" + std::string(text) + "' is not a number");
  }
  return v;
}

std::string number(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

}  // namespace

long parse_step(std::string_view text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < 0 || value > kMaxSteps) {
    throw BadInput("'" + std::string(text) + "' is not a step in 0.." + std::to_string(kMaxSteps));
  }
  return value;
}

Fault parse_malfunction(const robot::Morphology& morph, std::string_view spec, bool recover) {
  if (spec.empty()) throw BadInput(kForm + "; got an empty fault");
  Fault f;
  f.recover = recover;
  const std::size_t colon = spec.find(':');
  const std::string_view target = spec.substr(0, colon);
  if (target.empty()) throw BadInput(kForm + "; got '" + std::string(spec) + "'");
  std::optional<double> value;
  std::string_view kind = LegFault::kName;
  if (colon != std::string_view::npos) {
    std::string_view rest = spec.substr(colon + 1);
    const std::size_t eq = rest.find('=');
    if (eq != std::string_view::npos) value = parse_value(rest.substr(eq + 1));
    kind = rest.substr(0, eq);
  }
  // A recovery may leave out the value: it ends whatever fault of the kind strikes its target.
  f.kind = make_kind(kind, value, /*value_optional=*/recover);
  if (target == kSensorTarget) return f;
  const std::size_t dot = target.find('.');
  f.legs = robot::parse_leg_set(morph, target.substr(0, dot));
  if (f.legs.empty()) throw BadInput(kForm + "; got '" + std::string(spec) + "'");
  if (dot != std::string_view::npos) f.joint = robot::parse_joint(target.substr(dot + 1));
  return f;
}

Fault parse_fault(const robot::Morphology& morph, std::string_view text, bool recover) {
  const std::size_t at = text.rfind('@');
  if (at == std::string_view::npos || at == 0 || at + 1 == text.size()) {
    throw BadInput(kForm + "; got '" + std::string(text) + "'");
  }
  Fault f = parse_malfunction(morph, text.substr(0, at), recover);
  f.step = parse_step(text.substr(at + 1));
  return f;
}

std::string malfunction_text(const robot::Morphology& morph, const Fault& fault) {
  std::string out =
      fault.legs.empty() ? std::string(kSensorTarget) : robot::leg_set_name(morph, fault.legs);
  if (fault.joint) {
    out += '.';
    out += robot::to_string(*fault.joint);
  }
  if (std::holds_alternative<LegFault>(fault.kind)) return out;
  out += ':';
  out += kind_name(fault.kind);
  if (const std::optional<double> v = value_of(fault.kind)) {
    out += '=';
    out += number(*v);
  }
  return out;
}

std::string fault_text(const robot::Morphology& morph, const Fault& fault) {
  return malfunction_text(morph, fault) + "@" + std::to_string(fault.step);
}

}  // namespace multicpg::body
