// Flags of every command that simulates a robot: time steps and servo gain (issue 3, SPEC §7),
// bound directly to sim::SimOptions.
#pragma once

#include <CLI/CLI.hpp>

#include "sim/sim.h"

namespace multicpg::apps {

// Adds --control-dt --physics-dt, and --servo-gain unless `with_servo` is false (commands that
// only write the model), writing into `options`, each range shown in --help and checked at parse
// time.
void add_sim_flags(CLI::App& cmd, sim::SimOptions& options, bool with_servo = true);

// `options` checked whole (sim::validate: a control step that is not a whole multiple of the
// physics step); throws OptionError naming the flag.
sim::SimOptions sim_options(const sim::SimOptions& options);

}  // namespace multicpg::apps
