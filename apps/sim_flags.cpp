#include "apps/sim_flags.h"

#include "apps/options.h"

namespace multicpg::apps {

void add_sim_flags(CLI::App& cmd, SimFlags& f, bool with_servo) {
  cmd.add_option("--control-dt", f.control_dt,
                 "simulated seconds per controller step (paper: 0.037 s, 27 Hz)")
      ->capture_default_str();
  cmd.add_option("--physics-dt", f.physics_dt,
                 "MuJoCo time step in seconds (default: the largest step <= 0.005 s that divides "
                 "--control-dt, 0.004625 s for 0.037 s); --control-dt must be a whole multiple "
                 "of it (relative tolerance 1e-6)");
  if (!with_servo) return;
  cmd.add_option("--servo-gain", f.servo_gain,
                 "servo gain K in 1/s (default: the reference's 5.24 1/s at its 0.1 s step, "
                 "scaled to --control-dt: 14.15 1/s at 0.037 s)");
}

sim::SimOptions sim_options(const SimFlags& f) {
  require_positive(f.control_dt, "--control-dt");
  sim::SimOptions o;
  o.control_dt = f.control_dt;
  if (f.physics_dt) {
    require_positive(*f.physics_dt, "--physics-dt");
    o.physics_dt = *f.physics_dt;
  }
  if (f.servo_gain) {
    require_positive(*f.servo_gain, "--servo-gain");
    o.servo_gain = *f.servo_gain;
  }
  sim::physics_substeps(o.control_dt,
                        o.physics_dt > 0.0 ? o.physics_dt : sim::default_physics_dt(o.control_dt));
  return o;
}

}  // namespace multicpg::apps
