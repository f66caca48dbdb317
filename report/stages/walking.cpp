// Walking with every period (speed table) and two real-time films: the tripod, and R1 disabled.
#include <algorithm>
#include <cmath>
#include <map>

#include "common/table.h"
#include "experiments/paper.h"
#include "report/film.h"
#include "report/stages/stage.h"
#include "sim/walk.h"

namespace multicpg::report {
namespace {

// Walk of each period for the speed table.
constexpr long kSpeedWalkSteps = 1200;
// Gait names of paper §2.1 (docs/controller.md "Gaits").
const std::map<int, std::string> kGaits{{1, "stop"},       {4, "tripod"},    {5, "tetrapod"},
                                        {6, "transition"}, {8, "fast wave"}, {9, "slow wave"}};

sim::WalkSpec walk_spec(const sim::SimModel& model, int period, long steps) {
  sim::WalkSpec spec;
  spec.start.periods.assign(model.legs.size(), period);
  spec.steps = steps;
  spec.record = false;
  return spec;
}

}  // namespace

Section walking_stage(const StageContext& ctx) {
  const sim::SimModel hexapod = sim::make_sim_model(robot::RobotKind::hexapod, ctx.options.sim);
  Table speeds{{{"period"},
                {"gait", Align::left},
                {"distance (m)"},
                {"speed (cm/s)"},
                {"largest |deviation| per 400 steps (deg)"}},
               {}};
  std::vector<double> speeds_cm_s;
  std::string speeds_text;
  for (const auto& [p, gait] : kGaits) {
    const sim::WalkResult r = sim::walk(hexapod, walk_spec(hexapod, p, kSpeedWalkSteps));
    if (gait != "stop") {
      speeds_cm_s.push_back(100.0 * r.speed_m_s);
      speeds_text += (speeds_text.empty() ? "" : ", ") + fixed(100.0 * r.speed_m_s, 2);
    }
    double worst = 0.0;
    for (double d : r.window_deviations_deg) worst = std::max(worst, std::abs(d));
    speeds.add_row({std::to_string(p), gait, fixed(r.distance_m, 3), fixed(100.0 * r.speed_m_s, 2),
                    fixed(worst, 2)});
  }
  const std::filesystem::path videos = ctx.dir("videos");
  std::vector<std::string> films;
  for (bool broken : {false, true}) {
    const std::filesystem::path out =
        videos / (broken ? "walk-r1-disabled.mp4" : "walk-tripod.mp4");
    Film film(hexapod, {out, kDefaultFrameWidth, kDefaultFrameHeight, 1, {}});
    sim::WalkSpec spec = walk_spec(hexapod, learning::kStartPeriod, ctx.sizes.walk_film_steps);
    if (broken) spec.faults = body::fail_at({0}, 0);
    FilmObserver observer(film, broken ? "R1 disabled" : "all legs working");
    spec.observer = &observer;
    sim::walk(hexapod, spec);
    film.finish();
    films.push_back(ctx.rel(out));
  }
  const bool slower = std::is_sorted(speeds_cm_s.rbegin(), speeds_cm_s.rend());
  Section section{
      "walking",
      "Walking with all legs, and with R1 disabled",
      "With all legs working the robot walks straight; with p = 4, 5, 6, 8, 9 it walks "
      "with the tripod ... slow wave gait, slower as p grows. With R1 disabled and all "
      "periods 4 it turns right (≈" +
          fixed(experiments::paper::kR1SimulatorDeg, 0) +
          "° per 400 steps in the paper's simulator, " +
          fixed(experiments::paper::kTunnel.front().before_deg, 0) + "° on the real robot).",
      "Speeds of each gait over " + std::to_string(kSpeedWalkSteps) +
          " steps, the controller warmed up for " + std::to_string(body::kControllerWarmup) +
          " steps first so the robot starts in its gait (table). Videos: the tripod, and "
          "R1 disabled from the start (R1 drawn red), real time.",
      {},
      films,
      {},
      {speeds}};
  section.verdicts = {{"The gaits of p = 4, 5, 6, 8, 9 walk slower as p grows (§2.1)",
                       "slower as p grows", speeds_text + " cm/s",
                       slower ? Reproduced::yes : Reproduced::no}};
  return section;
}

}  // namespace multicpg::report
