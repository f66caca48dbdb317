// What walk, learn and tunnel print and keep of a run on a real robot (docs/hardware.md "Outputs").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "experiments/bodies.h"

namespace multicpg::apps {

// Where a stopped run's record goes: standard output (--json), and `file` (when not empty), whole
// or not at all.
experiments::StoppedSink stopped_record(bool json, const std::string& file);

// "loop: 27.0 Hz (period 37.00 ms, p99 jitter 0.21 ms, 0 overruns), link errors: none": one line
// of a run's hardware record.
std::string hardware_summary(const nlohmann::json& hardware);

}  // namespace multicpg::apps
