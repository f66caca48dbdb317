// multicpg render: a video (.mp4) or picture (.png) of a simulated walk or learning run, the
// camera following the robot and disabled legs in red.
#include <iostream>

#include "apps/commands.h"
#include "apps/flag_checks.h"
#include "apps/learning_options.h"
#include "apps/options.h"
#include "apps/replay_output.h"
#include "apps/run_flags.h"
#include "apps/sim_flags.h"
#include "common/errors.h"
#include "experiments/learning_run.h"
#include "report/film.h"

namespace multicpg::apps {
namespace {

struct RenderOptions {
  RunFlags run;  // robot, start, faults, learning and simulation flags
  long steps = 400;
  bool learn = false;
  bool tunnel = false;
  std::string out;
  std::string replay;
  int width = report::kDefaultFrameWidth;
  int height = report::kDefaultFrameHeight;
  int speed = 1;
};

void run_render(const RenderOptions& o) {
  report::film_format(o.out);  // an unknown file type fails before any work
  ReplayOutput replay(o.replay);
  experiments::RunSpec run = run_spec(o.run, o.learn);
  run.robot.sim.scene.tunnel = o.tunnel;
  const sim::SimModel model = experiments::make_model(run.robot);
  report::FilmSpec spec;
  spec.out = o.out;
  spec.width = o.width;
  spec.height = o.height;
  spec.speed = o.speed;
  report::Film film(model, spec);

  if (run.learning) {
    report::FilmObserver film_observer(film);
    sim::Observers observer({&film_observer, replay.observer()});
    const experiments::LearningRun learned = experiments::run_learning(model, run, 0, &observer);
    const std::string summary = std::string(learning::to_string(learned.result.outcome)) +
                                " after " + std::to_string(learned.result.trials) + " trials";
    if (film.format() == report::FilmFormat::picture) film.picture(learned.final_state, summary);
    film.finish();
    replay.write();
    std::cout << summary << "; wrote " << o.out << " (" << film.frames() << " frames)\n";
    if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
    return;
  }
  sim::WalkSpec walk;
  walk.start = run.start;
  walk.faults = run.faults;
  walk.steps = o.steps;
  walk.keep_record = false;  // the film sees every step; nothing kept per step
  report::FilmObserver observer(film, "walking");
  sim::Observers observers({&observer, replay.observer()});
  walk.observer = &observers;
  sim::WalkResult r;
  try {
    r = sim::walk(model, walk);
  } catch (const OptionError& e) {
    throw BadInput(flag_of(e.key(), o.run) + ": " + e.what());
  }
  if (film.format() == report::FilmFormat::picture) {
    film.picture(r.final_state, observer.caption());
  }
  film.finish();
  replay.write();
  std::cout << "walked " << r.distance_m << " m; wrote " << o.out << " (" << film.frames()
            << " frames)\n";
  if (!o.replay.empty()) std::cout << "wrote " << o.replay << "\n";
}

}  // namespace

void register_render(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render", "render a walk or a learning run to a video (.mp4) or picture (.png), headless");
  cmd->add_option("--out", o->out, "FILE.mp4 (every step) or FILE.png (the last step)")->required();
  add_replay_flag(*cmd, o->replay);
  add_walk_flags(*cmd, o->run);
  CLI::Option* steps = cmd->add_option("--steps", o->steps, "steps to walk (without --learn)")
                           ->check(in(body::kRunStepsLimits))
                           ->capture_default_str();
  CLI::Option* learn =
      cmd->add_flag("--learn", o->learn, "film a learning run (needs --disable) instead of a walk")
          ->excludes(steps);
  cmd->add_flag("--tunnel", o->tunnel, "walk in the 3.0 m x 1.2 m tunnel of paper §5");
  const std::size_t learning_flags = cmd->get_options().size();
  add_learning_flags(*cmd, o->run.learning);
  require_for_options_from(*cmd, learning_flags, learn);
  add_sim_flags(*cmd, o->run.sim, o->run.body);
  cmd->add_option("--width", o->width, "frame width in pixels")
      ->check(in(report::kFrameSideLimits))
      ->capture_default_str();
  cmd->add_option("--height", o->height, "frame height in pixels")
      ->check(in(report::kFrameSideLimits))
      ->capture_default_str();
  cmd->add_option("--speed", o->speed, "controller steps per video frame (1 = real time)")
      ->check(in(report::kFilmSpeedLimits))
      ->capture_default_str();
  cmd->callback([o] { run_render(*o); });
}

}  // namespace multicpg::apps
