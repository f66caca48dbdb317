// libFuzzer target for the fault and terrain texts (docs/faults.md): --fault/--recover specs,
// experiment files' fault scenarios, --terrain, and a fault's JSON as run files record it. Every
// input goes to every parser; each must accept it or throw BadInput (OptionError is one). A
// fault that parses must print as text that parses back to the same fault.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "body/course_json.h"
#include "body/fault_spec.h"
#include "common/errors.h"
#include "robot/morphology.h"
#include "robot/terrain.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace multicpg;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (robot::RobotKind kind : robot::kRobotKinds) {
    const robot::Morphology& morph = robot::morphology(kind);
    for (bool recover : {false, true}) {
      try {
        const body::Fault f = body::parse_fault(morph, text, recover);
        if (body::parse_fault(morph, body::fault_text(morph, f), recover) != f) std::abort();
      } catch (const BadInput&) {
      }
      try {
        body::parse_malfunction(morph, text, recover);
      } catch (const BadInput&) {
      }
    }
  }
  try {
    const robot::Terrain t = robot::parse_terrain(text);
    if (robot::parse_terrain(robot::terrain_text(t)) != t) std::abort();
  } catch (const BadInput&) {
  }
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_discarded()) {
    try {
      j.get<body::Fault>();
    } catch (const BadInput&) {
    } catch (const nlohmann::json::exception&) {
    }
  }
  return 0;
}
