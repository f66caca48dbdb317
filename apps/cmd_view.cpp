// multicpg view: the simulated robot walking in a window (issue 5).
#include <iostream>

#include "apps/commands.h"
#include "apps/options.h"
#include "common/errors.h"
#include "report/viewer.h"
#include "sim/sim.h"

namespace multicpg::apps {
namespace {

struct ViewOptions {
  std::string robot = "hexapod";
  std::string periods = "4";
  std::string disable;
  long disable_at = 0;
  long steps = 0;  // only read when --steps is given
};

// Every flag is checked before the display is touched, so bad input is reported the same with
// or without one.
void run_view(const ViewOptions& o, bool steps_given) {
  const robot::RobotKind kind = robot::parse_robot(o.robot);
  const robot::Morphology& morph = robot::morphology(kind);
  report::ViewerSpec spec;
  spec.periods = parse_periods(morph, o.periods);
  spec.disabled = robot::parse_leg_list(morph, o.disable);
  if (spec.disabled.size() == morph.size()) {
    throw BadInput("cannot disable every leg of the " + morph.name);
  }
  if (o.disable_at < 0) {
    throw BadInput("--disable-at must not be negative, got " + std::to_string(o.disable_at));
  }
  if (steps_given) {
    require_positive(o.steps, "--steps");
    if (!spec.disabled.empty() && o.disable_at >= o.steps) {
      throw BadInput("--disable-at must be in 0.." + std::to_string(o.steps - 1) + ", got " +
                     std::to_string(o.disable_at));
    }
    spec.steps = o.steps;
  }
  spec.disable_at = o.disable_at;

  const sim::SimModel model = sim::make_sim_model(kind);
  const long steps = report::run_viewer(model, spec);
  std::cout << "viewed " << steps << " steps (" << static_cast<double>(steps) * model.control_dt
            << " s simulated)\n";
}

}  // namespace

void register_view(CLI::App& app) {
  auto opts = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "watch the robot walk in a window (Space pause, Right step, 1-8 legs, S sync)");
  cmd->add_option("--robot", opts->robot, "hexapod, quadruped or octopod")->capture_default_str();
  cmd->add_option("--periods", opts->periods, "CPG periods: 4 (every leg) or R1=5,R2=4,...")
      ->capture_default_str();
  cmd->add_option("--disable", opts->disable, "legs that fail, e.g. R1,L2");
  cmd->add_option("--disable-at", opts->disable_at, "step before which those legs fail")
      ->capture_default_str();
  CLI::Option* steps = cmd->add_option("--steps", opts->steps, "quit after this many steps");
  cmd->callback([opts, steps] { run_view(*opts, steps->count() > 0); });
}

}  // namespace multicpg::apps
