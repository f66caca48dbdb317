// The emulator's injected faults (emulator.h Injection): KIND[=VALUE]@STEP parsed and written.
#include <fmt/format.h>

#include <charconv>
#include <cstdlib>
#include <string>

#include "common/errors.h"
#include "common/limits.h"
#include "emulator/emulator.h"

namespace multicpg::emulator {
// The emulator speaks the hardware's protocols (hw/): their frames, files and ports.
using namespace hw;
namespace {

struct KindName {
  Injection::Kind kind;
  std::string_view name;
  bool value;  // takes a value
  Limits<double> limits;
};
constexpr KindName kKinds[] = {
    {Injection::Kind::drop, "drop", true, {0.0, 1.0}},
    {Injection::Kind::corrupt, "corrupt", true, {0.0, 1.0}},
    {Injection::Kind::latency, "latency", true, {0.0, 10'000.0}},
    {Injection::Kind::silent, "silent", true, {0.0, 252.0}},
    {Injection::Kind::drift, "drift", true, {-100.0, 100.0}},
    {Injection::Kind::silent_yaw, "silent-yaw", false, {0.0, 0.0}},
    {Injection::Kind::hangup, "hangup", false, {0.0, 0.0}},
    {Injection::Kind::hangup_yaw, "hangup-yaw", false, {0.0, 0.0}},
};

const KindName& kind_name(Injection::Kind kind) {
  for (const KindName& k : kKinds) {
    if (k.kind == kind) return k;
  }
  return kKinds[0];
}

}  // namespace

Injection parse_injection(std::string_view text, const HardwareFile& file) {
  const std::string usage = fmt::format(
      "'{}': an injection is KIND[=VALUE]@STEP, KIND one of drop, corrupt, latency, silent, "
      "drift, silent-yaw, hangup, hangup-yaw",
      text);
  const std::size_t at = text.rfind('@');
  if (at == std::string_view::npos) throw BadInput(usage);
  const std::string_view head = text.substr(0, at);
  const std::string_view step_text = text.substr(at + 1);
  Injection in;
  const auto [end, error] =
      std::from_chars(step_text.data(), step_text.data() + step_text.size(), in.step);
  if (error != std::errc() || end != step_text.data() + step_text.size() || in.step < 0) {
    throw BadInput(usage + " (STEP: a command frame, 0 or more)");
  }
  const std::size_t eq = head.find('=');
  const std::string_view name = head.substr(0, eq);
  const KindName* kind = nullptr;
  for (const KindName& k : kKinds) {
    if (k.name == name) kind = &k;
  }
  if (kind == nullptr) throw BadInput(usage);
  in.kind = kind->kind;
  if (kind->value != (eq != std::string_view::npos)) {
    throw BadInput("'" + std::string(text) + "': " + std::string(kind->name) +
                   (kind->value ? " needs a value (KIND=VALUE@STEP)" : " takes no value"));
  }
  if (kind->value) {
    const std::string value(head.substr(eq + 1));
    char* stop = nullptr;
    in.value = std::strtod(value.c_str(), &stop);
    if (value.empty() || *stop != '\0' || !kind->limits.contains(in.value)) {
      throw BadInput("'" + std::string(text) + "': " + std::string(kind->name) +
                     " takes a value in " + kind->limits.text());
    }
  }
  if (in.kind == Injection::Kind::silent && file.protocol == Protocol::dynamixel) {
    bool known = false;
    for (const LegServos& leg : file.legs) {
      for (const ServoJoint& j : leg.joints) known = known || j.id == in.value;
    }
    if (!known) {
      throw BadInput(fmt::format("'{}': no servo of the hardware file has ID {}", text, in.value));
    }
  }
  if (in.kind == Injection::Kind::hangup_yaw && file.yaw.source != YawSource::line) {
    throw BadInput("'" + std::string(text) + "': the hardware file has no yaw line");
  }
  return in;
}

std::string to_string(const Injection& in) {
  const KindName& k = kind_name(in.kind);
  return fmt::format("{}{}@{}", k.name, k.value ? fmt::format("={}", in.value) : "", in.step);
}

}  // namespace multicpg::emulator
