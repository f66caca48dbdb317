// What walk, learn and tunnel print and keep of a run on a real robot (docs/hardware.md "Outputs").
#pragma once

#include <string>

#include "experiments/bodies.h"

namespace multicpg::apps {

// Where a stopped run's record goes: standard output (--json), and `file` (when not empty), whole
// or not at all.
experiments::StoppedSink stopped_record(bool json, const std::string& file);

}  // namespace multicpg::apps
