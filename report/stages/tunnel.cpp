// The tunnel (paper §5, Table 1): the real robot beside our two bodies, paper-sim and real
// (robot/body_models.h, docs/fidelity.md), each scenario before learning, with the paper's
// periods, after learning with periods alone and after robust learning; and on the run's own
// body the films, the trunk paths and the combination the hexapod table learned.
#include "experiments/tunnel.h"

#include <algorithm>
#include <future>
#include <optional>
#include <sstream>

#include "common/table.h"
#include "experiments/learning_run.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "learning/default_learner.h"
#include "report/film.h"
#include "report/replay/page.h"
#include "report/stages/stage.h"
#include "robot/leg_sets.h"
#include "sim/json.h"

namespace multicpg::report {
namespace {

namespace paper = experiments::paper;

// The tunnel films look down the corridor from behind the robot, far enough to see both walls.
const CameraSpec kTunnelCamera{true, {}, 2.5, 0.0, -45.0, {}};

std::string file_stem(std::string text) {
  std::replace(text.begin(), text.end(), '+', '-');
  return text;
}

std::vector<std::size_t> disabled_legs(const robot::Morphology& morph,
                                       const paper::TunnelResult& sc) {
  std::string legs(sc.disabled);
  std::replace(legs.begin(), legs.end(), '+', ',');
  return robot::parse_leg_set(morph, legs);
}

std::vector<int> papers_periods(const robot::Morphology& morph, const paper::TunnelResult& sc) {
  return robot::parse_period_map(morph, paper::combination_text(sc.learned),
                                 learning::kStartPeriod);
}

sim::SimModel corridor_model(const sim::SimOptions& options) {
  sim::SimOptions with_tunnel = options;
  with_tunnel.scene.tunnel = true;
  return sim::make_sim_model(robot::RobotKind::hexapod, with_tunnel);
}

// The paper's angles signed as ours (+ = left): before learning the real robot deviated right
// (§5), so negative; Table 1 does not say to which side the learned periods erred, so ±.
std::string papers_before_text(const paper::TunnelResult& sc) {
  return fixed(paper::signed_before_deg(sc), 0) + "°";
}
std::string papers_after_text(const paper::TunnelResult& sc) {
  return "±" + fixed(sc.after_deg, 2) + "°";
}

// "passed, -5.1°", "wall at 0.82 m, -21.1°", "too slow, -3.0°".
std::string outcome_text(const experiments::TunnelRun& t) {
  const std::string angle = fixed(t.deviation_deg, 1) + "°";
  if (t.passed_or_false()) return "passed, " + angle;
  if (t.touched_wall) return "wall at " + fixed(t.forward_m, 2) + " m, " + angle;
  return "too slow, " + angle;
}

// --- Table 1 side by side ----------------------------------------------------------------------

// A body the side-by-side table walks.
struct Body {
  std::string name;
  sim::SimOptions sim;
};

// The named models paper-sim and real (with the run's time steps), and the run's own body when
// it is neither; or (Sizes::tunnel_every_body false) the run's own body alone, under its model's
// name when it is one.
std::vector<Body> table_bodies(const StageContext& ctx) {
  std::vector<Body> out;
  bool own = false;
  for (robot::BodyModel m : robot::kBodyModels) {
    sim::SimOptions s = ctx.options.sim;
    s.model = m;
    s.body = robot::body_params(m);
    const bool this_run = nlohmann::json(s) == nlohmann::json(ctx.options.sim);
    own = own || this_run;
    if (ctx.sizes.tunnel_every_body || this_run)
      out.push_back({std::string(robot::to_string(m)), s});
  }
  if (!own) out.push_back({"this run's body", ctx.options.sim});
  return out;
}

// The four rows of one scenario on one body.
struct BodyScenario {
  experiments::TunnelRun before, papers;
  experiments::TunnelOutcome periods_alone, robust;
};

experiments::TunnelOutcome learn_and_walk(const StageContext& ctx, const sim::SimOptions& body,
                                          const sim::SimModel& corridor,
                                          const std::vector<std::size_t>& disabled,
                                          bool periods_alone) {
  experiments::RunSpec spec;
  spec.robot.sim = body;
  learning::CompensationOptions& l = spec.learning.emplace();
  l.seed = ctx.options.seed;
  if (periods_alone) {
    // `tunnel --learn --steering off`, as docs/learning.md measures it.
    l.steering = learning::Steering::off;
    l.search.max_trials = ctx.sizes.periods_alone_max_trials;
    l.max_episodes = ctx.sizes.periods_alone_max_episodes;
  }
  spec.start = experiments::learning_start(l.mode);
  spec.faults = body::fail_at(disabled, 0);
  // The learner `tunnel --learn` takes (docs/learning.md "Which learner a run uses").
  l.learner = learning::default_learner({l, spec.robot.kind, false, false, spec.faults});
  experiments::validate(spec);
  return experiments::run_tunnel(spec, corridor);
}

BodyScenario walk_body_scenario(const StageContext& ctx, const Body& body,
                                const paper::TunnelResult& sc) {
  const sim::SimModel corridor = corridor_model(body.sim);
  const robot::Morphology& morph = corridor.controller.morphology;
  const std::vector<std::size_t> disabled = disabled_legs(morph, sc);
  BodyScenario out;
  experiments::TunnelSpec t;
  t.faults = body::fail_at(disabled, 0);
  out.before = experiments::run_tunnel(corridor, t);
  t.start.periods = papers_periods(morph, sc);
  out.papers = experiments::run_tunnel(corridor, t);
  out.periods_alone = learn_and_walk(ctx, body.sim, corridor, disabled, /*periods_alone=*/true);
  out.robust = learn_and_walk(ctx, body.sim, corridor, disabled, /*periods_alone=*/false);
  ctx.progress("tunnel: " + std::string(sc.disabled) + " on " + body.name + " learned and walked");
  return out;
}

std::string learned_text(const robot::Morphology& morph, const experiments::TunnelOutcome& o) {
  std::string text =
      outcome_text(o.run) + " (" + robot::period_map_text(morph, o.periods, o.disabled);
  if (o.learned) {
    text += o.learned->steering ? " + reflex" : "";
    text += ", " + counted(o.learned->trials, "trial");
  }
  return text + ")";
}

Table side_by_side_table(const std::vector<Body>& bodies,
                         const std::vector<std::vector<BodyScenario>>& results) {
  Table table{
      {{"disabled", Align::left}, {"row", Align::left}, {"real AMOSII (paper §5)", Align::left}},
      {}};
  for (const Body& b : bodies) table.columns.push_back({b.name, Align::left});
  const robot::Morphology& morph = robot::morphology(robot::RobotKind::hexapod);
  for (std::size_t s = 0; s < paper::kTunnel.size(); ++s) {
    const paper::TunnelResult& sc = paper::kTunnel[s];
    const std::string name(sc.disabled);
    const auto row = [&](std::string label, std::string real, auto cell) {
      std::vector<std::string> cells{name, std::move(label), std::move(real)};
      for (std::size_t b = 0; b < bodies.size(); ++b) cells.push_back(cell(results[b][s]));
      table.add_row(std::move(cells));
    };
    row("before learning (all periods 4)", "hit the right wall, ≈" + papers_before_text(sc),
        [](const BodyScenario& r) { return outcome_text(r.before); });
    row("the paper's periods " + paper::combination_text(sc.learned),
        "passed, ≈" + papers_after_text(sc),
        [](const BodyScenario& r) { return outcome_text(r.papers); });
    row("periods-alone learning (tunnel --learn --steering off)",
        "the row above: learned in the paper's simulator",
        [&](const BodyScenario& r) { return learned_text(morph, r.periods_alone); });
    row("robust learning (tunnel --learn)", "–",
        [&](const BodyScenario& r) { return learned_text(morph, r.robust); });
  }
  return table;
}

// --- the run's own body: films, paths, our learning ----------------------------------------------

struct Variant {
  std::string source;
  std::vector<int> periods;
  std::string paper;  // the paper's angle, signed as ours
  bool filmed;
  std::vector<Point2>* path;  // where its trunk path is drawn, if anywhere
};

// One scenario's rows, films and path figure.
struct ScenarioOutput {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> films;
  std::vector<std::string> replays;  // beside each film, of the same name
  std::string image;
};

ScenarioOutput run_scenario(const StageContext& ctx, const sim::SimModel& corridor,
                            const paper::TunnelResult& sc, const std::string& learned) {
  const robot::Morphology& morph = corridor.controller.morphology;
  const std::string name(sc.disabled);
  const std::vector<std::size_t> disabled = disabled_legs(morph, sc);
  ScenarioOutput out;
  TrunkPaths paths;
  std::vector<Variant> variants{{"all 4", std::vector<int>(morph.size(), learning::kStartPeriod),
                                 papers_before_text(sc), true, &paths.before}};
  if (!learned.empty()) {
    variants.push_back({"our learning",
                        robot::parse_period_map(morph, learned, learning::kStartPeriod),
                        papers_after_text(sc), true, &paths.after});
  }
  variants.push_back(
      {"the paper's learning", papers_periods(morph, sc), papers_after_text(sc), false, nullptr});
  for (const Variant& v : variants) {
    const std::filesystem::path video =
        ctx.dir("videos") /
        ("tunnel-" + file_stem(name) + (v.path == &paths.before ? "-before" : "-after") + ".mp4");
    std::optional<Film> film;
    std::optional<FilmObserver> observer;
    ReplayRecorder replay;
    if (v.filmed) {
      film.emplace(corridor, FilmSpec{video, kDefaultFrameWidth, kDefaultFrameHeight,
                                      ctx.sizes.tunnel_film_speed, kTunnelCamera});
      observer.emplace(*film, name + " disabled, " + v.source);
    }
    sim::Observers observers({observer ? &*observer : nullptr, v.filmed ? &replay : nullptr});
    experiments::TunnelSpec spec;
    spec.start.periods = v.periods;
    spec.faults = body::fail_at(disabled, 0);
    const experiments::TunnelRun t = experiments::run_tunnel(corridor, spec, &observers);
    if (film) {
      film->finish();
      out.films.push_back(ctx.rel(video));
      const std::filesystem::path page =
          ctx.dir("replays") / video.filename().replace_extension(".html");
      write_replay(replay.recording(), "The tunnel (Table 1): " + name + " disabled, " + v.source,
                   page);
      out.replays.push_back(ctx.rel(page));
    }
    out.rows.push_back(
        {name, robot::period_map_text(morph, v.periods, disabled), v.source,
         fixed(t.deviation_deg, 2), fixed(t.forward_m, 2), fixed(t.lateral_m, 2),
         t.passed_or_false() ? "passed" : (t.touched_wall ? "hit a wall" : "too slow"),
         "≈" + v.paper});
    if (v.path == nullptr) continue;
    for (std::size_t i = 0; i < t.record.rows(); ++i) {
      v.path->push_back({t.record.x[i], t.record.y[i]});
    }
  }
  const double half = corridor.scene.tunnel_width / 2.0;
  const double length = corridor.scene.tunnel_length;
  paths.walls = {{{0.0, half}, {length, half}}, {{0.0, -half}, {length, -half}}};
  paths.before_label = "all periods 4";
  paths.after_label = "learned";
  out.image =
      ctx.image(plot_trunk_paths(paths, ctx.dir("figures"), "tunnel-path-" + file_stem(name)));
  ctx.progress("tunnel: " + name + " filmed");
  return out;
}

}  // namespace

Section tunnel_stage(const StageContext& ctx) {
  const sim::SimModel corridor = corridor_model(ctx.options.sim);
  const experiments::ExperimentTable hexapod =
      experiments::read_experiment(ctx.options.out / "experiments" / "hexapod");
  // Every scenario on every body is independent: each walks (and films) on its own thread, the
  // models shared read-only, so the films of one render while another learns.
  std::vector<std::future<ScenarioOutput>> filmed;
  for (const paper::TunnelResult& sc : paper::kTunnel) {
    std::string learned;
    for (const experiments::GroupSummary& g : hexapod.rows) {
      if (g.group == sc.disabled) learned = g.best_periods;
    }
    filmed.push_back(std::async(std::launch::async, run_scenario, std::cref(ctx),
                                std::cref(corridor), std::cref(sc), learned));
  }
  const std::vector<Body> bodies = table_bodies(ctx);
  std::vector<std::vector<std::future<BodyScenario>>> walking(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    for (const paper::TunnelResult& sc : paper::kTunnel) {
      walking[b].push_back(std::async(std::launch::async, walk_body_scenario, std::cref(ctx),
                                      std::cref(bodies[b]), std::cref(sc)));
    }
  }
  Table detail{{{"disabled", Align::left},
                {"periods", Align::left},
                {"source", Align::left},
                {"deviation (deg)"},
                {"forward (m)"},
                {"lateral (m)"},
                {"result", Align::left},
                {"paper (deg)"}},
               {}};
  std::vector<std::string> films;
  std::vector<std::string> replays;
  std::vector<std::string> images;
  for (std::future<ScenarioOutput>& f : filmed) {
    ScenarioOutput out = f.get();
    for (auto& row : out.rows) detail.add_row(std::move(row));
    films.insert(films.end(), out.films.begin(), out.films.end());
    replays.insert(replays.end(), out.replays.begin(), out.replays.end());
    images.push_back(out.image);
  }
  std::vector<std::vector<BodyScenario>> results(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    for (std::future<BodyScenario>& f : walking[b]) results[b].push_back(f.get());
  }
  std::string paper_before, paper_after, scenarios;
  for (const paper::TunnelResult& sc : paper::kTunnel) {
    const bool last = &sc == &paper::kTunnel.back();
    const std::string sep = last ? "" : ", ";
    scenarios += std::string(sc.disabled) + sep;
    paper_before += papers_before_text(sc) + sep;
    paper_after += papers_after_text(sc) + sep;
  }
  std::string own = "this run's body";
  std::size_t own_index = bodies.size() - 1;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (nlohmann::json(bodies[b].sim) == nlohmann::json(ctx.options.sim)) {
      own = bodies[b].name;
      own_index = b;
    }
  }
  std::vector<Verdict> verdicts;
  for (std::size_t i = 0; i < paper::kTunnel.size(); ++i) {
    const paper::TunnelResult& sc = paper::kTunnel[i];
    const BodyScenario& r = results[own_index][i];
    const std::string name(sc.disabled);
    verdicts.push_back(
        {"Tunnel, " + name +
             " disabled, all periods 4: the robot deviates right and hits the wall "
             "(§5; yes = it touched a wall turning right, on " +
             own + ")",
         "hit the right wall, " + papers_before_text(sc), outcome_text(r.before),
         r.before.touched_wall && r.before.deviation_deg < 0.0
             ? Reproduced::yes
             : (r.before.deviation_deg < 0.0 ? Reproduced::partly : Reproduced::no)});
    verdicts.push_back({"Tunnel, " + name + " disabled, the paper's learned periods " +
                            paper::combination_text(sc.learned) +
                            ": the robot passes (Table 1, on " + own + ")",
                        "passed, " + papers_after_text(sc), outcome_text(r.papers),
                        r.papers.passed_or_false() ? Reproduced::yes : Reproduced::no});
  }
  Section section{
      "tunnel",
      "The tunnel (Table 1)",
      "Tunnel " + fixed(corridor.scene.tunnel_length, 1) + " m × " +
          fixed(corridor.scene.tunnel_width, 1) + " m, the real AMOSII. Disabled " + scenarios +
          " with all periods 4: the robot deviated right and hit the wall (≈" + paper_before +
          "); with the periods learned in the paper's simulator (periods " +
          "alone, no reflex) it passed (≈" + paper_after + ").",
      std::string(ctx.sizes.tunnel_every_body
                      ? "First table: Table 1 on the real robot beside our two bodies, paper-sim "
                        "(the paper's simulator) and real (calibrated against the real robot's "
                        "before-learning column, docs/fidelity.md)"
                      : "First table: Table 1 on the real robot beside this run's body (a quick "
                        "run walks it alone; the full run adds paper-sim, the paper's "
                        "simulator, and real, calibrated against the real robot's "
                        "before-learning column, docs/fidelity.md)") +
          ", deviation = atan(lateral / forward) of the trunk from the entrance "
          "to the end or to the wall it touched, + = left. \"Periods-alone learning\" learns "
          "with --mode robust --steering off (--max-trials " +
          std::to_string(ctx.sizes.periods_alone_max_trials) + " per episode, at most " +
          counted(ctx.sizes.periods_alone_max_episodes, "episode") +
          ") in the open field from a walking robot and walks the learned periods through "
          "the tunnel; \"robust learning\" learns with --mode robust (yaw and path, held "
          "windows, the steering reflex) and walks the periods with the reflex; seed " +
          std::to_string(ctx.options.seed) +
          ". Angles are signed on both sides, + = left: the paper's before-learning angles "
          "are negative because §5 says the robot deviated to the right; Table 1 does not say "
          "to which side the learned periods erred, so those are shown ±. Second table, on " +
          own +
          ": rows \"our learning\" walk the most frequent combination the hexapod table "
          "learned for the scenario (experiments/hexapod) on open ground, rows \"the "
          "paper's learning\" replay the paper's combinations; films and paths of all 4 "
          "and of our learning.",
      images,
      films,
      {},
      {side_by_side_table(bodies, results), detail},
      replays};
  section.verdicts = std::move(verdicts);
  return section;
}

}  // namespace multicpg::report
