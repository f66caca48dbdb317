// Fig. 2: the gait of every period.
#include "common/table.h"
#include "experiments/gait.h"
#include "report/stages/stage.h"
#include "sim/sim.h"

namespace multicpg::report {
namespace {

const std::vector<int> kGaitFigurePeriods{1, 4, 5, 6, 8, 9};
constexpr long kShownCycles = 2;
constexpr long kSlowestCycle = 9 * (2 * 9 + 1);  // p = 9: p(2p + 1) = 171 steps
constexpr int kFractionDecimals = 3;

}  // namespace

Section gaits_stage(const StageContext& ctx) {
  const neural::ControllerModel controller = neural::make_controller_model(
      robot::RobotKind::hexapod, ctx.options.sim.controller, ctx.options.sim.body);
  std::vector<GaitPanel> panels;
  std::string fractions;
  for (int p : kGaitFigurePeriods) {
    neural::ControllerState state = neural::make_controller_state(controller, p);
    const experiments::GaitRecord g = experiments::record_gait(
        controller, state, experiments::kDefaultGaitWarmup, kShownCycles * kSlowestCycle);
    panels.push_back({p, g.swing});
    fractions += (fractions.empty() ? "" : ", ") + std::string("p") + std::to_string(p) + " " +
                 fixed(experiments::swing_fractions(g).front(), kFractionDecimals);
  }
  const FigureFiles f = plot_gait_diagrams(panels, leg_names(controller.morphology),
                                           sim::kDefaultControlDt, ctx.dir("figures"));
  return {"gaits",
          "Gaits for each period (Fig. 2)",
          "Periods 9, 8, 6, 5, 4 give the slow wave, fast wave, transition, tetrapod and tripod "
          "gaits; p = 1 stops with all legs on the ground. One step ≈ 0.037 s.",
          "Swing fraction of every leg = 1/p (" + fractions +
              "); p = 4 is an exact tripod (R1, R3, L2 against R2, L1, L3); p = 1 holds every "
              "joint constant (τ = 18, τ_L = 90, the authors' code).",
          {ctx.image(f)},
          {},
          {},
          {}};
}

}  // namespace multicpg::report
