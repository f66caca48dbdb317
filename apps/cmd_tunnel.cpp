// multicpg tunnel: walk through the 3.0 m x 1.2 m corridor of paper §5 (Table 1) with given
// periods and disabled legs; report the deviation angle and whether the robot passed.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/hardware_output.h"
#include "apps/learning_options.h"
#include "apps/learning_output.h"
#include "apps/options.h"
#include "apps/plot_output.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "common/errors.h"
#include "experiments/run_json.h"
#include "experiments/scenarios.h"
#include "experiments/tunnel.h"
#include "hw/hardware_record.h"
#include "report/film.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {
namespace {

struct TunnelOptions {
  RunFlags run;  // robot, the legs that fail, learning and simulation flags
  bool learn = false;
  long max_steps = experiments::kTunnelMaxSteps;
  std::string video;   // .mp4 to film the tunnel walk; empty = none
  std::string replay;  // .html of the tunnel walk; empty = none
  std::string plot;    // .png of the tunnel walk; empty = none
  bool json = false;
  bool scale_tunnel = false;
};

void run_tunnel(const TunnelOptions& o, bool periods_given) {
  if (o.learn && periods_given) {
    throw BadInput("--periods and --learn exclude each other: --learn finds them");
  }
  if (!o.video.empty() && report::film_format(o.video) != report::FilmFormat::video) {
    throw BadInput("--video must name an .mp4 file");
  }
  ReplayOutput replay(o.replay);
  PlotOutput plot(o.plot);
  experiments::RunSpec spec = run_spec(o.run, o.learn);
  const std::optional<experiments::HardwareSetup> setup = hardware_setup(spec, o.run);
  if (setup && !o.video.empty()) {
    throw BadInput("--video films the simulated tunnel; a real robot's run has --replay");
  }
  if (setup && o.scale_tunnel) {
    throw BadInput("--scale-tunnel scales the simulated tunnel; not with --hardware");
  }
  std::optional<experiments::TunnelScale> scale;
  if (o.scale_tunnel) {
    try {
      scale = experiments::scale_tunnel(spec);
    } catch (const OptionError& e) {
      throw BadInput("--scale-tunnel: " + e.key() + " " + e.what());
    }
  }
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  const sim::SimModel corridor = experiments::tunnel_model(spec);
  std::optional<report::Film> film;
  std::optional<report::FilmObserver> observer;
  if (!o.video.empty()) {
    report::FilmSpec film_spec;
    film_spec.out = o.video;
    film.emplace(corridor, film_spec);
    std::ostringstream label;
    label << std::fixed << std::setprecision(1) << "tunnel " << corridor.scene.tunnel_length
          << " m x " << corridor.scene.tunnel_width << " m";
    observer.emplace(*film, label.str());
  }
  sim::Observers observers({observer ? &*observer : nullptr, replay.observer(), plot.observer()});
  // Learning streams its table as it goes (learn's, apps/learning_output.h); --json prints one
  // object at the end instead.
  std::optional<LearningStream> stream;
  if (o.learn && !o.json) {
    if (setup) {
      std::cout << "on " << setup->file.name << " (" << hw::to_string(setup->file.protocol) << ", "
                << setup->file.path.string() << "): learning where it stands, then on into "
                << "its tunnel\n";
    } else {
      std::cout << "learning in the open field first, then the tunnel\n";
    }
    print_learning_header(std::cout, spec,
                          learning::start_settle_steps(*spec.learning, corridor.controller));
    stream.emplace(std::cout, std::cerr, spec);
  }
  experiments::Watchers hardware;
  hardware.stopped = stopped_record(o.json, "");
  const experiments::TunnelOutcome out =
      experiments::run_tunnel(spec, corridor, o.max_steps, &observers, stream ? &*stream : nullptr,
                              setup ? &*setup : nullptr, hardware);
  if (film) film->finish();
  replay.write();
  plot.tunnel(corridor.scene.tunnel_length, corridor.scene.tunnel_width);
  if (out.learned) plot.learning(*out.learned, spec.learning->search.threshold_deg, out.disabled);
  plot.write();
  const experiments::TunnelRun& run = out.run;
  if (o.json) {
    std::cout << experiments::tunnel_json(spec, out, scale).dump(2) << "\n";
    return;
  }
  const std::string result = !run.passed   ? "walked on: no position sensed, whether it passed is "
                                             "for you to see"
                             : *run.passed ? "passed"
                             : run.touched_wall ? "touched a wall"
                                                : "did not reach the end";
  if (stream) std::cout << "\n";
  std::cout << std::fixed << std::setprecision(2) << robot_text(spec.robot) << ", tunnel "
            << corridor.scene.tunnel_length << " m x " << corridor.scene.tunnel_width
            << " m, disabled "
            << (out.disabled.empty() ? "none" : robot::leg_set_name(morph, out.disabled));
  if (scale) {
    std::cout << " (scaled " << std::setprecision(3) << scale->factor << ": robot "
              << scale->robot_width_m << " m wide, the " << morph.name << " "
              << scale->layout_width_m << " m)" << std::setprecision(2);
  }
  std::cout << "\n" << world_text(spec) << "\n";
  if (const std::string other = experiments::other_faults_text(spec); !other.empty()) {
    std::cout << "faults " << other << "\n";
  }
  if (out.learned) {
    std::cout << "learned in the open field (" << learning::to_string(spec.learning->mode)
              << " mode): " << learning::to_string(out.learned->outcome) << " after "
              << counted(out.learned->trials, "trial") << ", "
              << robot::period_map_text(morph, out.learned->periods, out.disabled)
              << (out.learned->steering ? ", steering reflex on" : "") << "\n";
  }
  if (run.passed) {
    std::cout << result << " after " << run.steps << " steps: forward " << run.forward_m
              << " m, lateral " << run.lateral_m << " m, deviation " << run.deviation_deg
              << "° (+ = left)\n";
  } else {
    std::cout << result << " (" << run.steps << " steps, yaw change " << run.yaw_change_deg
              << "°, + = left)\n";
  }
  if (setup) std::cout << hw::hardware_summary(run.hardware) << "\n";
  if (!o.video.empty()) std::cout << "wrote " << o.video << "\n";
  if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
  if (!o.plot.empty()) std::cout << "wrote " << o.plot << "\n";
  if (plot.model_map()) std::cout << "wrote " << model_map_path(o.plot) << "\n";
}

}  // namespace

void register_tunnel(CLI::App& app) {
  auto o = std::make_shared<TunnelOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tunnel", "walk a robot through the 3.0 m x 1.2 m tunnel of paper §5 (Table 1)");
  add_robot_flag(*cmd, o->run);
  add_fault_flags(*cmd, o->run);
  CLI::Option* periods =
      cmd->add_option("--periods", o->run.periods, "4 (every leg) or R1=5,R2=4,...")
          ->capture_default_str();
  CLI::Option* learn =
      cmd->add_flag("--learn", o->learn,
                    "learn in the open field first (from a walking robot), then walk the learned "
                    "controller through the tunnel");
  const std::size_t learning_flags = cmd->get_options().size();
  add_learning_flags(*cmd, o->run.learning);
  require_for_options_from(*cmd, learning_flags, learn);
  cmd->add_option("--max-steps", o->max_steps, "steps before giving up")
      ->check(in(body::kRunStepsLimits))
      ->capture_default_str();
  cmd->add_option("--video", o->video, "also film the run to FILE.mp4");
  add_replay_flag(*cmd, o->replay);
  add_plot_flag(*cmd, o->plot);
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->add_flag("--scale-tunnel", o->scale_tunnel,
                "scale the tunnel's length and width by the robot's width (its feet's span at the "
                "start) over the built-in robot's of its layout");
  add_sim_flags(*cmd, o->run.sim, o->run.body);
  add_hardware_flags(*cmd, o->run);
  cmd->callback([o, periods] { run_tunnel(*o, periods->count() > 0); });
}

}  // namespace multicpg::apps
