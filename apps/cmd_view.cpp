// multicpg view: the simulated robot walking in a window (issue 5).
#include <iostream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/walk_flags.h"
#include "common/errors.h"
#include "report/viewer.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

struct ViewOptions {
  WalkFlags walk;
  long steps = 0;  // only read when --steps is given
};

// Every flag is checked before the display is touched, so bad input is reported the same with
// or without one.
void run_view(const ViewOptions& o, bool steps_given) {
  const WalkChoice choice = parse_walk_flags(o.walk);
  report::ViewerSpec spec;
  spec.start = {choice.periods, choice.warmup};
  spec.faults = choice.faults;
  if (steps_given) {
    require_faults_within(spec.faults, o.steps);
    spec.steps = o.steps;
  }

  const sim::SimModel model = sim::make_sim_model(choice.kind);
  const long steps = report::run_viewer(model, spec);
  std::cout << "viewed " << steps << " steps (" << static_cast<double>(steps) * model.control_dt
            << " s simulated)\n";
}

}  // namespace

void register_view(CLI::App& app) {
  auto opts = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "watch the robot walk in a window (Space pause, Right step, 1-8 legs, S sync)");
  add_walk_flags(*cmd, opts->walk);
  CLI::Option* steps = cmd->add_option("--steps", opts->steps, "quit after this many steps")
                           ->check(in(sim::kRunStepsLimits));
  cmd->callback([opts, steps] { run_view(*opts, steps->count() > 0); });
}

}  // namespace multicpg::apps
