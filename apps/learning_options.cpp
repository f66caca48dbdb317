#include "apps/learning_options.h"

#include "common/errors.h"

namespace multicpg::apps {

void add_learning_flags(CLI::App& cmd, LearningFlags& f, bool with_beta) {
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
                                                   std::vector<std::size_t> disabled,
                                                   long fail_step) {
  if (disabled.empty()) throw BadInput("--disable: name at least one leg to disable");
  learning::CompensationOptions o;
  o.annealing.beta = f.beta;
  o.annealing.threshold_deg = f.threshold;
  o.annealing.max_trials = f.max_trials;
  o.window_steps = f.window;
  o.settle_steps = f.settle;
  o.disabled = std::move(disabled);
  o.fail_step = fail_step;
  o.seed = f.seed;
  learning::validate(o, morph);
  return o;
}

}  // namespace multicpg::apps
