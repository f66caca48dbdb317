// multicpg tunnel: walk through the 3.0 m x 1.2 m corridor of paper §5 (Table 1) with given
// periods and disabled legs; report the deviation angle and whether the robot passed.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "apps/sim_flags.h"
#include "apps/tunnel_command.h"
#include "apps/walk_flags.h"
#include "common/errors.h"
#include "experiments/scenarios.h"
#include "experiments/tunnel.h"
#include "report/film.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {
namespace {

struct TunnelOptions {
  TunnelRequest request;
  std::string periods = "4";
  bool json = false;
};

void run_tunnel(TunnelOptions o, bool periods_given) {
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  if (periods_given) o.request.periods = o.periods;
  const TunnelOutcome out = run_tunnel_command(o.request);
  const experiments::TunnelRun& run = out.run;
  const std::string result =
      run.passed ? "passed" : (run.touched_wall ? "touched a wall" : "did not reach the end");
  if (o.json) {
    std::cout << tunnel_json(morph, out).dump(2) << "\n";
    return;
  }
  std::cout << std::fixed << std::setprecision(2) << "tunnel " << out.tunnel_length_m << " m x "
            << out.tunnel_width_m << " m, disabled "
            << (out.disabled.empty() ? "none" : robot::leg_set_name(morph, out.disabled)) << "\n";
  if (out.learned) {
    std::cout << "learned in the open field (" << learning::to_string(out.options->mode)
              << " mode): " << learning::to_string(out.learned->outcome) << " after "
              << out.learned->trials << " trials, "
              << robot::period_map_text(morph, out.learned->periods, out.disabled)
              << (out.learned->steering ? ", steering reflex on" : "") << "\n";
  }
  std::cout << result << " after " << run.steps << " steps: forward " << run.forward_m
            << " m, lateral " << run.lateral_m << " m, deviation " << run.deviation_deg
            << "° (+ = left)\n";
  if (!o.request.video.empty()) std::cout << "wrote " << o.request.video << "\n";
}

}  // namespace

void register_tunnel(CLI::App& app) {
  auto o = std::make_shared<TunnelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tunnel", "walk the hexapod through the 3.0 m x 1.2 m tunnel of paper §5 (Table 1)");
  cmd->add_option("--disable", o->request.disable, "legs that fail, e.g. R1,R3");
  CLI::Option* periods = cmd->add_option("--periods", o->periods, "4 (every leg) or R1=5,R2=4,...")
                             ->capture_default_str();
  cmd->add_flag("--learn", o->request.learn,
                "learn in the open field first (from a walking robot), then walk the learned "
                "controller through the tunnel");
  add_learning_flags(*cmd, o->request.learning);
  cmd->add_option("--max-steps", o->request.max_steps, "steps before giving up")
      ->check(in(sim::kRunStepsLimits))
      ->capture_default_str();
  cmd->add_option("--video", o->request.video, "also film the run to FILE.mp4");
  cmd->add_flag("--json", o->json, "print one JSON object");
  add_sim_flags(*cmd, o->request.sim, o->request.body);
  cmd->callback([o, periods] { run_tunnel(*o, periods->count() > 0); });
}

}  // namespace multicpg::apps
