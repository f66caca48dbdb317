// multicpg view: the simulated robot walking in a window.
#include <iostream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/options.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "common/errors.h"
#include "report/viewer.h"
#include "sim/sim.h"
#include "sim/walk.h"

namespace multicpg::apps {
namespace {

struct ViewOptions {
  RunFlags run;    // robot, start and faults
  long steps = 0;  // only read when --steps is given
};

// Every flag is checked before the display is touched, so bad input is reported the same with
// or without one.
void run_view(const ViewOptions& o, bool steps_given) {
  const experiments::RunSpec run = run_spec(o.run, /*learn=*/false);
  report::ViewerSpec spec;
  spec.start = run.start;
  spec.faults = run.faults;
  if (steps_given) {
    for (const body::Fault& f : spec.faults) {
      if (f.step >= o.steps) {
        throw BadInput(std::string(f.recover ? "--recover" : "--disable-at") + " must be in 0.." +
                       std::to_string(o.steps - 1) + ", got " + std::to_string(f.step));
      }
    }
    spec.steps = o.steps;
  }

  const sim::SimModel model = experiments::make_model(run.robot);
  const long steps = report::run_viewer(model, spec);
  std::cout << "viewed " << steps << " steps (" << static_cast<double>(steps) * model.control_dt
            << " s simulated)\n";
}

}  // namespace

void register_view(CLI::App& app) {
  auto opts = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "watch the robot walk in a window (Space pause, Right step, 1-8 legs, S sync)");
  add_walk_flags(*cmd, opts->run);
  add_body_flags(*cmd, opts->run.body);
  CLI::Option* steps = cmd->add_option("--steps", opts->steps, "quit after this many steps")
                           ->check(in(body::kRunStepsLimits));
  cmd->callback([opts, steps] { run_view(*opts, steps->count() > 0); });
}

}  // namespace multicpg::apps
