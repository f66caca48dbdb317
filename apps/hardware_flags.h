// The flags that put walk, learn and tunnel on a real robot (docs/hardware.md "Running it"):
// --hardware FILE.toml and --lock-step; the run's checks with errors naming the flag; and where a
// run stopped on the robot leaves its record.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/run_flags.h"
#include "hw/hardware_runs.h"

namespace multicpg::apps {

void add_hardware_flags(CLI::App& cmd, hw::HardwareFlags& flags);

// hw::hardware_setup, its errors (exit 2) naming the flag of a bad value.
hw::HardwareSetup hardware_setup(const experiments::RunSpec& spec, const hw::HardwareFlags& flags,
                                 const RunFlags& run);

// Where a stopped run's record goes: standard output (--json), and `file` (when not empty), whole
// or not at all.
hw::StoppedSink stopped_record(bool json, const std::string& file);

// "loop: 27.0 Hz (period 37.00 ms, p99 jitter 0.21 ms, 0 overruns), link errors: none": one line
// of a run's hardware record.
std::string hardware_summary(const nlohmann::json& hardware);

}  // namespace multicpg::apps
