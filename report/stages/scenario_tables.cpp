// Figs. 11 and 13: learning per disabled-leg scenario, hexapod and quadruped (one function, two
// stages: the robots differ only in their runs and captions).
#include "common/table.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "report/stages/stage.h"

namespace multicpg::report {
namespace {

namespace paper = experiments::paper;

Section scenario_table(const StageContext& ctx, robot::RobotKind kind) {
  const bool hexapod = kind == robot::RobotKind::hexapod;
  const std::string name(robot::to_string(kind));
  const experiments::ExperimentTable t = experiments::run_scenario_table(
      ctx.experiment(kind, name, hexapod ? ctx.sizes.hexapod_runs : ctx.sizes.quadruped_runs));
  std::vector<ScenarioSummary> bars;
  int converged = 0, runs = 0, within = 0, no_deviation = 0;
  for (const experiments::GroupSummary& g : t.rows) {
    bars.push_back({g.group, g.trials.mean, g.trials.sd, g.final_deviation_deg.mean,
                    g.final_deviation_deg.sd, g.share_converged(), g.no_deviation == g.runs});
    converged += g.converged;
    runs += g.runs;
    within += g.within_paper_trials;
    no_deviation += g.no_deviation;
  }
  const FigureFiles f = plot_learning_summary(bars, name, paper::kThresholdDeg, ctx.dir("figures"));
  const std::string base = "experiments/" + name + "/";
  const std::string threshold = fixed(paper::kThresholdDeg, 0) + "°";
  const std::string trials = std::to_string(paper::kMostTrials) + " trials";
  const std::string paper_runs = std::to_string(experiments::kScenarioRuns);
  const int held = converged + no_deviation;
  const Verdict verdict =
      hexapod
          ? Verdict{"Most runs (more than half) of the disabled-leg scenarios converge below " +
                        threshold + " within " + trials + " (Fig. 11, §4.1)",
                    "most scenarios within " + trials,
                    std::to_string(within) + " of " + counted(runs, "run") + " (" +
                        std::to_string(converged) + " converged)",
                    2 * within > runs ? Reproduced::yes
                                      : (within > 0 ? Reproduced::partly : Reproduced::no)}
          : Verdict{
                "The quadruped finds a combination that walks straight with any one leg "
                "disabled (Fig. 13; partly = in some runs)",
                "feasible combinations for R1, R2, L1, L2",
                std::to_string(held) + " of " + counted(runs, "run") +
                    " converged or never deviated",
                held == runs ? Reproduced::yes : (held > 0 ? Reproduced::partly : Reproduced::no)};
  Section section{name + "-table",
                  hexapod ? "Hexapod: learning per scenario (Fig. 11)"
                          : "Quadruped: learning per scenario (Fig. 13)",
                  hexapod
                      ? "24 scenarios of 1-3 disabled legs (its Fig. 11 shows 21; the numbers are "
                        "not in the text), " +
                            paper_runs + " runs each: learning for most scenarios ends within " +
                            trials + ", below " + threshold + "."
                      : "R1, R2, L1, L2 disabled, " + paper_runs +
                            " runs each: the controller finds feasible combinations (no numbers in "
                            "the text).",
                  counted(runs, "run") + ": " + std::to_string(converged) + " converged below " +
                      threshold + ", " + std::to_string(within) + " of them within " + trials +
                      " (mean ± SD over runs in the table).",
                  {ctx.image(f)},
                  {},
                  {base + "table.csv", base + "table.md", base + "summary.json"},
                  {experiments::scenario_table(t.rows)}};
  section.verdicts = {verdict};
  return section;
}

}  // namespace

Section hexapod_table_stage(const StageContext& ctx) {
  return scenario_table(ctx, robot::RobotKind::hexapod);
}

Section quadruped_table_stage(const StageContext& ctx) {
  return scenario_table(ctx, robot::RobotKind::quadruped);
}

}  // namespace multicpg::report
