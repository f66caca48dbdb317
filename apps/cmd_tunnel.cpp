// multicpg tunnel: walk through the 3.0 m x 1.2 m corridor of paper §5 (Table 1) with given
// periods and disabled legs; report the deviation angle and whether the robot passed.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/commands.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "apps/results_json.h"
#include "apps/sim_flags.h"
#include "apps/walk_flags.h"
#include "common/errors.h"
#include "experiments/scenarios.h"
#include "experiments/tunnel.h"
#include "report/film.h"

namespace multicpg::apps {
namespace {

struct TunnelOptions {
  std::string disable;
  std::string periods = "4";
  long max_steps = experiments::kTunnelMaxSteps;
  std::string video;
  bool json = false;
  bool learn = false;
  LearningFlags learning;
  SimFlags sim;
};

void run_tunnel(const TunnelOptions& o, bool periods_given) {
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  experiments::TunnelSpec spec;
  spec.disabled = robot::parse_leg_list(morph, o.disable);
  require_working_leg(morph, spec.disabled);
  spec.periods = parse_periods(morph, o.periods);
  require_positive(o.max_steps, "--max-steps");
  spec.max_steps = o.max_steps;
  std::optional<learning::CompensationOptions> learn;
  if (o.learn) {
    if (periods_given)
      throw BadInput("--periods and --learn exclude each other: --learn finds them");
    learn = compensation_options(o.learning, morph, sim::fail_at(spec.disabled, 0));
  }
  if (!o.video.empty() && report::film_format(o.video) != report::FilmFormat::video) {
    throw BadInput("--video must name an .mp4 file");
  }
  const sim::SimOptions open_options = sim_options(o.sim);
  sim::SimOptions options = open_options;
  options.scene.tunnel = true;
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod, options);
  std::optional<report::Film> film;
  std::optional<report::FilmObserver> observer;
  if (!o.video.empty()) {
    report::FilmSpec film_spec;
    film_spec.out = o.video;
    film.emplace(model, film_spec);
    observer.emplace(*film, "tunnel 3.0 m x 1.2 m");
  }
  sim::Observer* watch = observer ? &*observer : nullptr;
  experiments::TunnelRun run;
  std::optional<learning::LearningResult> learned;
  if (learn) {
    const sim::SimModel open = sim::make_sim_model(robot::RobotKind::hexapod, open_options);
    experiments::LearnedTunnelRun r =
        experiments::run_tunnel_after_learning(open, model, *learn, spec.max_steps, watch);
    run = std::move(r.tunnel);
    learned = std::move(r.learning);
    spec.periods = learned->periods;
  } else {
    run = experiments::run_tunnel(model, spec, watch);
  }
  if (film) film->finish();
  const std::string result =
      run.passed ? "passed" : (run.touched_wall ? "touched a wall" : "did not reach the end");
  if (o.json) {
    const nlohmann::json j = tunnel_json(morph, run, spec.periods, spec.disabled,
                                         learned ? &*learned : nullptr, learn ? &*learn : nullptr);
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << std::fixed << std::setprecision(2) << "tunnel " << model.scene.tunnel_length
            << " m x " << model.scene.tunnel_width << " m, disabled "
            << (spec.disabled.empty() ? "none" : robot::leg_list_name(morph, spec.disabled))
            << "\n";
  if (learned) {
    std::cout << "learned in the open field (" << learning::to_string(learn->mode)
              << " mode): " << learned->status << " after " << learned->trials << " trials, "
              << experiments::working_periods_text(morph, learned->periods, spec.disabled)
              << (learned->steering ? ", steering reflex on" : "") << "\n";
  }
  std::cout << result << " after " << run.steps << " steps: forward " << run.forward_m
            << " m, lateral " << run.lateral_m << " m, deviation " << run.deviation_deg
            << "° (+ = left)\n";
  if (film) std::cout << "wrote " << o.video << "\n";
}

}  // namespace

void register_tunnel(CLI::App& app) {
  auto o = std::make_shared<TunnelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tunnel", "walk the hexapod through the 3.0 m x 1.2 m tunnel of paper §5 (Table 1)");
  cmd->add_option("--disable", o->disable, "legs that fail, e.g. R1,R3");
  CLI::Option* periods = cmd->add_option("--periods", o->periods, "4 (every leg) or R1=5,R2=4,...")
                             ->capture_default_str();
  cmd->add_flag("--learn", o->learn,
                "learn in the open field first (from a walking robot), then walk the learned "
                "controller through the tunnel");
  add_learning_flags(*cmd, o->learning);
  cmd->add_option("--max-steps", o->max_steps, "steps before giving up")->capture_default_str();
  cmd->add_option("--video", o->video, "also film the run to FILE.mp4");
  cmd->add_flag("--json", o->json, "print one JSON object");
  add_sim_flags(*cmd, o->sim);
  cmd->callback([o, periods] { run_tunnel(*o, periods->count() > 0); });
}

}  // namespace multicpg::apps
