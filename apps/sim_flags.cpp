#include "apps/sim_flags.h"

#include <algorithm>

#include "apps/flag_checks.h"

namespace multicpg::apps {

void add_sim_flags(CLI::App& cmd, sim::SimOptions& o, bool with_servo) {
  cmd.add_option("--control-dt", o.control_dt,
                 "simulated seconds per controller step (paper: 0.037 s, 27 Hz)")
      ->check(in(sim::kControlDtLimits))
      ->capture_default_str();
  cmd.add_option("--physics-dt", o.physics_dt,
                 "MuJoCo time step in seconds (0, the default: the largest step <= 0.005 s that "
                 "divides --control-dt, 0.004625 s for 0.037 s); --control-dt must be a whole "
                 "multiple of it (relative tolerance 1e-6)")
      ->check(in(sim::kPhysicsDtLimits));
  if (!with_servo) return;
  cmd.add_option("--servo-gain", o.servo_gain,
                 "servo gain K in 1/s (0, the default: the reference's 5.24 1/s at its 0.1 s "
                 "step, scaled to --control-dt: 14.15 1/s at 0.037 s)")
      ->check(in(sim::kServoGainLimits));
}

sim::SimOptions sim_options(const sim::SimOptions& options) {
  try {
    sim::validate(options);
  } catch (const OptionError& e) {
    // The flag bound to the key, so the message names what the user typed.
    std::string flag = "--" + e.key();
    std::replace(flag.begin(), flag.end(), '_', '-');
    throw BadInput(flag + " " + e.what());
  }
  return options;
}

}  // namespace multicpg::apps
