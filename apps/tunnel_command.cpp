#include "apps/tunnel_command.h"

#include "apps/options.h"
#include "apps/walk_flags.h"
#include "common/errors.h"
#include "learning/json.h"
#include "report/film.h"
#include "robot/leg_sets.h"

namespace multicpg::apps {

TunnelOutcome run_tunnel_command(const TunnelRequest& o, sim::Observer* learning_observer) {
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  TunnelOutcome out;
  experiments::TunnelSpec spec;
  spec.disabled = parse_leg_flag(morph, o.disable, "--disable");
  require_working_leg(morph, spec.disabled);
  spec.periods = parse_periods_flag(morph, o.periods.value_or("4"), "--periods");
  spec.max_steps = o.max_steps;
  if (o.learn) {
    if (o.periods) throw BadInput("--periods and --learn exclude each other: --learn finds them");
    out.options = compensation_options(o.learning, morph, sim::fail_at(spec.disabled, 0));
  }
  if (!o.video.empty() && report::film_format(o.video) != report::FilmFormat::video) {
    throw BadInput("--video must name an .mp4 file");
  }
  const sim::SimOptions open_options = sim_options(o.sim, o.body, robot::RobotKind::hexapod);
  sim::SimOptions options = open_options;
  options.scene.tunnel = true;
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod, options);
  out.tunnel_length_m = model.scene.tunnel_length;
  out.tunnel_width_m = model.scene.tunnel_width;
  std::optional<report::Film> film;
  std::optional<report::FilmObserver> observer;
  if (!o.video.empty()) {
    report::FilmSpec film_spec;
    film_spec.out = o.video;
    film.emplace(model, film_spec);
    observer.emplace(*film, "tunnel 3.0 m x 1.2 m");
  }
  sim::Observer* watch = observer ? &*observer : nullptr;
  if (out.options) {
    const sim::SimModel open = sim::make_sim_model(robot::RobotKind::hexapod, open_options);
    experiments::LearnedTunnelRun r = experiments::run_tunnel_after_learning(
        open, model, *out.options, spec.max_steps, watch, learning_observer);
    out.run = std::move(r.tunnel);
    out.learned = std::move(r.learning);
    spec.periods = out.learned->periods;
  } else {
    out.run = experiments::run_tunnel(model, spec, watch);
  }
  if (film) film->finish();
  out.disabled = spec.disabled;
  out.periods = spec.periods;
  return out;
}

nlohmann::json tunnel_json(const robot::Morphology& morph, const TunnelOutcome& o) {
  const experiments::TunnelRun& run = o.run;
  nlohmann::json j{{"passed", run.passed},       {"touched_wall", run.touched_wall},
                   {"steps", run.steps},         {"forward_m", run.forward_m},
                   {"lateral_m", run.lateral_m}, {"deviation_deg", run.deviation_deg}};
  j["periods"] = robot::period_map_json(morph, o.periods);
  if (o.learned) {
    j["learning"] = learning::to_json(*o.learned, morph, o.disabled);
    j["options"] = *o.options;
  }
  return j;
}

}  // namespace multicpg::apps
