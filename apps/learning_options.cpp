#include "apps/learning_options.h"

#include "common/errors.h"

namespace multicpg::apps {

void add_learning_flags(CLI::App& cmd, LearningFlags& f, bool with_beta) {
  cmd.add_option("--mode", f.mode,
                 "robust (yaw and path angle, several windows to accept, monitoring, steering) "
                 "or paper (paper §3 exactly: one window, yaw only)")
      ->capture_default_str();
  cmd.add_option("--steering", f.steering,
                 "robust mode: reflex (orientation reflex on the VRN steering inputs) or off")
      ->capture_default_str();
  cmd.add_option("--hold-windows", f.hold_windows,
                 "robust mode: consecutive windows a combination must hold")
      ->capture_default_str();
  cmd.add_option("--monitor-windows", f.monitor_windows,
                 "robust mode: clean windows after the last fault or episode before the run ends")
      ->capture_default_str();
  cmd.add_flag("--no-period-learning", f.no_period_learning,
               "robust mode: keep the periods, compensate by steering alone");
  if (with_beta) {
    cmd.add_option("--beta", f.beta, "annealing factor: 0 random search, 10 greedy")
        ->capture_default_str();
  }
  cmd.add_option("--threshold", f.threshold, "deviation (deg) below which learning stops")
      ->capture_default_str();
  cmd.add_option("--window", f.window, "steps per measured window")->capture_default_str();
  cmd.add_option("--settle", f.settle,
                 "unmeasured steps after each period change (default: slowest CPG lock + "
                 "longest delay, 337 for the hexapod)");
  cmd.add_option("--max-trials", f.max_trials, "trials before a run ends 'not converged'")
      ->capture_default_str();
  cmd.add_option("--seed", f.seed, "seed of the run's random generator")->capture_default_str();
}

learning::CompensationOptions compensation_options(const LearningFlags& f,
                                                   const robot::Morphology& morph,
                                                   const sim::FaultTimeline& faults) {
  if (faults.empty()) throw BadInput("--disable or --fault: name at least one leg that fails");
  learning::CompensationOptions o;
  o.mode = learning::parse_mode(f.mode);
  o.steering = learning::parse_steering(f.steering);
  if (o.mode == learning::Mode::paper && (f.steering != "reflex" || f.no_period_learning)) {
    throw BadInput("--steering and --no-period-learning are robust-mode options");
  }
  if (o.mode == learning::Mode::paper) o.steering = learning::Steering::off;
  o.hold_windows = f.hold_windows;
  o.monitor_windows = f.monitor_windows;
  o.learn_periods = !f.no_period_learning;
  o.annealing.beta = f.beta;
  o.annealing.threshold_deg = f.threshold;
  o.annealing.max_trials = f.max_trials;
  o.window_steps = f.window;
  o.settle_steps = f.settle;
  // The paper's one fault keeps its shorthand form (paper mode takes only that).
  if (faults.size() == 1 && !faults.front().recover) {
    o.disabled = faults.front().legs;
    o.fail_step = faults.front().step;
  } else {
    o.faults = faults;
  }
  o.seed = f.seed;
  learning::validate(o, morph);
  return o;
}

}  // namespace multicpg::apps
