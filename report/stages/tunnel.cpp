// The tunnel (paper §5, Table 1): each scenario with all periods 4, with our learned
// combination (the hexapod table's most frequent one) and with the paper's; films and paths.
#include "experiments/tunnel.h"

#include <algorithm>
#include <future>
#include <optional>
#include <sstream>

#include "common/table.h"
#include "experiments/learning_run.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "report/film.h"
#include "report/stages/stage.h"
#include "robot/leg_sets.h"

namespace multicpg::report {
namespace {

namespace paper = experiments::paper;

// The tunnel films look down the corridor from behind the robot, far enough to see both walls.
const CameraSpec kTunnelCamera{"trunk", 2.5, 0.0, -45.0, {}};

std::string file_stem(std::string text) {
  std::replace(text.begin(), text.end(), '+', '-');
  return text;
}

struct Variant {
  std::string source;
  std::vector<int> periods;
  double paper_deg;
  bool filmed;
  std::vector<Point2>* path;                         // where its trunk path is drawn, if anywhere
  std::optional<learning::SteeringParams> steering;  // robust learning walks with its reflex
};

// One scenario's rows, films and path figure.
struct ScenarioOutput {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> films;
  std::string image;
};

ScenarioOutput run_scenario(const StageContext& ctx, const sim::SimModel& corridor,
                            const paper::TunnelResult& sc, const std::string& learned) {
  const robot::Morphology& morph = corridor.controller.morphology;
  const std::string name(sc.disabled);
  std::string legs = name;
  std::replace(legs.begin(), legs.end(), '+', ',');
  const std::vector<std::size_t> disabled = robot::parse_leg_set(morph, legs);
  ScenarioOutput out;
  TrunkPaths paths;
  std::vector<Variant> variants{{"all 4", std::vector<int>(morph.size(), learning::kStartPeriod),
                                 sc.before_deg, true, &paths.before, std::nullopt}};
  if (!learned.empty()) {
    variants.push_back({"our learning",
                        robot::parse_period_map(morph, learned, learning::kStartPeriod),
                        sc.after_deg, true, &paths.after, std::nullopt});
  }
  variants.push_back(
      {"the paper's learning",
       robot::parse_period_map(morph, paper::combination_text(sc.learned), learning::kStartPeriod),
       sc.after_deg, false, nullptr, std::nullopt});
  // Issue 8: robust learning (learn --mode robust) in the open field from a walking robot, then
  // its periods and steering reflex through the tunnel.
  {
    const sim::SimModel open = sim::make_sim_model(robot::RobotKind::hexapod, ctx.options.sim);
    experiments::RunSpec robust;
    robust.sim = ctx.options.sim;
    robust.learning.emplace().seed = ctx.options.seed;
    robust.start = experiments::learning_start(robust.learning->mode);
    robust.faults = sim::fail_at(disabled, 0);
    const experiments::LearningRun run = experiments::run_learning(open, robust);
    std::optional<learning::SteeringParams> steering;
    if (run.result.steering) steering = robust.learning->steering_params;
    variants.push_back({"robust learning (" + std::to_string(run.result.trials) + " trials)",
                        run.result.periods, sc.after_deg, false, nullptr, steering});
  }
  for (const Variant& v : variants) {
    const std::filesystem::path video =
        ctx.dir("videos") /
        ("tunnel-" + file_stem(name) + (v.path == &paths.before ? "-before" : "-after") + ".mp4");
    std::optional<Film> film;
    std::optional<FilmObserver> observer;
    if (v.filmed) {
      film.emplace(corridor, FilmSpec{video, kDefaultFrameWidth, kDefaultFrameHeight,
                                      ctx.sizes.tunnel_film_speed, kTunnelCamera});
      observer.emplace(*film, name + " disabled, " + v.source);
    }
    experiments::TunnelSpec spec;
    spec.start.periods = v.periods;
    spec.faults = sim::fail_at(disabled, 0);
    spec.steering = v.steering;
    const experiments::TunnelRun t =
        experiments::run_tunnel(corridor, spec, observer ? &*observer : nullptr);
    if (film) {
      film->finish();
      out.films.push_back(ctx.rel(video));
    }
    out.rows.push_back({name, robot::period_map_text(morph, v.periods, disabled), v.source,
                        fixed(t.deviation_deg, 2), fixed(t.forward_m, 2), fixed(t.lateral_m, 2),
                        t.passed ? "passed" : (t.touched_wall ? "hit a wall" : "too slow"),
                        "≈" + fixed(v.paper_deg, 2)});
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
  return out;
}

}  // namespace

Section tunnel_stage(const StageContext& ctx) {
  sim::SimOptions with_tunnel = ctx.options.sim;
  with_tunnel.scene.tunnel = true;
  const sim::SimModel corridor = sim::make_sim_model(robot::RobotKind::hexapod, with_tunnel);
  const experiments::ExperimentTable hexapod =
      experiments::read_experiment(ctx.options.out / "experiments" / "hexapod");
  // The scenarios are independent: each walks and films on its own thread (the model is
  // shared read-only), so the films of one render while another walks.
  std::vector<std::future<ScenarioOutput>> running;
  for (const paper::TunnelResult& sc : paper::kTunnel) {
    std::string learned;
    for (const experiments::GroupSummary& g : hexapod.rows) {
      if (g.group == sc.disabled) learned = g.best_periods;
    }
    running.push_back(std::async(std::launch::async, run_scenario, std::cref(ctx),
                                 std::cref(corridor), std::cref(sc), learned));
  }
  Table table{{{"disabled", Align::left},
               {"periods", Align::left},
               {"source", Align::left},
               {"deviation (deg)"},
               {"forward (m)"},
               {"lateral (m)"},
               {"result", Align::left},
               {"paper (deg)"}},
              {}};
  std::vector<std::string> films;
  std::vector<std::string> images;
  for (std::future<ScenarioOutput>& f : running) {
    ScenarioOutput out = f.get();
    for (auto& row : out.rows) table.add_row(std::move(row));
    films.insert(films.end(), out.films.begin(), out.films.end());
    images.push_back(out.image);
  }
  std::string paper_before, paper_after, scenarios;
  for (const paper::TunnelResult& sc : paper::kTunnel) {
    const bool last = &sc == &paper::kTunnel.back();
    const std::string sep = last ? "" : ", ";
    scenarios += std::string(sc.disabled) + sep;
    paper_before += fixed(sc.before_deg, 0) + "°" + sep;
    paper_after += fixed(sc.after_deg, 2) + "°" + sep;
  }
  return {"tunnel",
          "The tunnel (Table 1)",
          "Tunnel " + fixed(corridor.scene.tunnel_length, 1) + " m × " +
              fixed(corridor.scene.tunnel_width, 1) + " m. Disabled " + scenarios +
              " with all periods 4: the robot deviated right and hit the wall (≈" + paper_before +
              "); with the learned periods it passed (≈" + paper_after + ").",
          "Deviation = atan(lateral / forward) of the trunk from the entrance to the end, or "
          "to where it touched a wall. Rows \"our learning\" walk the most frequent combination "
          "the hexapod table learned for the scenario (experiments/hexapod, seed " +
              std::to_string(ctx.options.seed) +
              ") on open ground; rows \"the paper's learning\" replay the paper's combinations "
              "on our robot; rows \"robust learning\" learn with --mode robust (yaw and path, "
              "held windows, the steering reflex) from a walking robot and walk the learned "
              "periods with the reflex through the tunnel.",
          images,
          films,
          {},
          {table}};
}

}  // namespace multicpg::report
