// Flags of every command that simulates a robot: time steps and servo gain (issue 3, SPEC §7).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "sim/sim.h"

namespace multicpg::apps {

struct SimFlags {
  double control_dt = sim::kDefaultControlDt;
  std::optional<double> physics_dt;
  std::optional<double> servo_gain;
};

// Adds --control-dt --physics-dt, and --servo-gain unless `with_servo` is false (commands that
// only write the model).
void add_sim_flags(CLI::App& cmd, SimFlags& flags, bool with_servo = true);

// The simulation options; throws BadInput (one line) for a step <= 0, a control step that is not
// a whole multiple of the physics step, or a servo gain <= 0.
sim::SimOptions sim_options(const SimFlags& flags);

}  // namespace multicpg::apps
