// Fig. 2: the gait of every period.
#include <algorithm>

#include "common/table.h"
#include "experiments/gait.h"
#include "experiments/paper.h"
#include "report/stages/stage.h"
#include "sim/sim.h"

namespace multicpg::report {
namespace {

const std::vector<int> kGaitFigurePeriods{1, 4, 5, 6, 8, 9};
constexpr long kShownCycles = 2;
constexpr long kSlowestCycle = 9 * (2 * 9 + 1);  // p = 9: p(2p + 1) = 171 steps
constexpr int kFractionDecimals = 3;
// Paper §2.1: p = 4 is the tripod, p = 1 stops.
constexpr int kTripodPeriod = 4;
constexpr int kStopPeriod = 1;

// The legs whose swing columns are identical, each group as "R1, R3, L2", in leg order.
std::vector<std::string> swing_groups(const std::vector<std::vector<bool>>& swing,
                                      const std::vector<std::string>& legs) {
  std::vector<std::string> groups;
  std::vector<bool> grouped(legs.size(), false);
  for (std::size_t a = 0; a < legs.size(); ++a) {
    if (grouped[a]) continue;
    std::string group = legs[a];
    for (std::size_t b = a + 1; b < legs.size(); ++b) {
      bool same = !grouped[b];
      for (const auto& row : swing) same = same && row[a] == row[b];
      if (!same) continue;
      grouped[b] = true;
      group += ", " + legs[b];
    }
    groups.push_back(group);
  }
  return groups;
}

}  // namespace

Section gaits_stage(const StageContext& ctx) {
  const neural::ControllerModel controller = neural::make_controller_model(
      robot::RobotKind::hexapod, ctx.options.sim.controller, ctx.options.sim.body);
  std::vector<GaitPanel> panels;
  std::string fractions;
  const std::vector<std::string> legs = leg_names(controller.morphology);
  std::vector<std::string> tripod;
  long stop_swings = 0;
  for (int p : kGaitFigurePeriods) {
    neural::ControllerState state = neural::make_controller_state(controller, p);
    const experiments::GaitRecord g = experiments::record_gait(
        controller, state, experiments::kDefaultGaitWarmup, kShownCycles * kSlowestCycle);
    panels.push_back({p, g.swing});
    if (p == kTripodPeriod) tripod = swing_groups(g.swing, legs);
    if (p == kStopPeriod) {
      for (const auto& row : g.swing) stop_swings += std::count(row.begin(), row.end(), true);
    }
    fractions += (fractions.empty() ? "" : ", ") + std::string("p") + std::to_string(p) + " " +
                 fixed(experiments::swing_fractions(g).front(), kFractionDecimals);
  }
  const FigureFiles f =
      plot_gait_diagrams(panels, legs, sim::kDefaultControlDt, ctx.dir("figures"));
  std::string groups;
  for (const std::string& g : tripod) groups += (groups.empty() ? "" : " against ") + g;
  // Two alternating halves: two groups, each of half the legs.
  bool is_tripod = tripod.size() == 2;
  for (const std::string& g : tripod) {
    is_tripod = is_tripod && static_cast<std::size_t>(std::count(g.begin(), g.end(), ',')) + 1 ==
                                 legs.size() / 2;
  }
  Section section{
      "gaits",
      "Gaits for each period (Fig. 2)",
      "Periods 9, 8, 6, 5, 4 give the slow wave, fast wave, transition, tetrapod and tripod "
      "gaits; p = 1 stops with all legs on the ground. One step ≈ " +
          fixed(experiments::paper::kStepSeconds, 3) + " s.",
      "Swing fraction of every leg = 1/p (" + fractions + "); p = 4: legs swinging together " +
          groups + "; p = 1: " + counted(stop_swings, "swing step") + " over all legs.",
      {ctx.image(f)},
      {},
      {},
      {}};
  section.verdicts = {
      {"p = 4 is the tripod gait: two halves of the legs swing in turn (Fig. 2)", "tripod", groups,
       is_tripod ? Reproduced::yes : Reproduced::no},
      {"p = 1 stops with all legs on the ground (Fig. 2)", "no swing",
       counted(stop_swings, "swing step"), stop_swings == 0 ? Reproduced::yes : Reproduced::no}};
  return section;
}

}  // namespace multicpg::report
