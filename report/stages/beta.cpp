// Fig. 14: the influence of the annealing factor β.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/table.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "report/stages/stage.h"

namespace multicpg::report {

Section beta_stage(const StageContext& ctx) {
  experiments::ExperimentSpec spec =
      ctx.experiment(robot::RobotKind::hexapod, "beta", ctx.sizes.beta_runs);
  spec.base.search.max_trials = ctx.sizes.beta_max_trials;
  const std::vector<double> betas =
      ctx.sizes.beta_values.empty()
          ? experiments::kBetaStudyValues
          : std::vector<double>(ctx.sizes.beta_values.begin(), ctx.sizes.beta_values.end());
  const experiments::ExperimentTable t = experiments::run_beta_study(spec, betas);
  std::vector<BetaSummary> bars;
  const experiments::GroupSummary* most = nullptr;
  for (const experiments::GroupSummary& g : t.rows) {
    bars.push_back({std::stod(g.group), g.trials.mean, g.trials.sd, g.share_converged()});
    if (most == nullptr || g.trials.mean > most->trials.mean) most = &g;
  }
  const experiments::Scenario scenario = experiments::beta_study_scenario();
  const FigureFiles f = plot_beta_study(bars, scenario.name, ctx.dir("figures"));
  // β = 0 needs the most only when no other β needs as many (a tie at the trial cap is not it).
  const bool random_most =
      most != nullptr && std::stod(most->group) == 0.0 &&
      std::count_if(t.rows.begin(), t.rows.end(), [&](const experiments::GroupSummary& g) {
        return g.trials.mean >= most->trials.mean;
      }) == 1;
  std::string which_betas;  // the values studied, when not the paper's
  if (!ctx.sizes.beta_values.empty()) {
    std::vector<std::string> values;
    for (double b : betas) values.push_back(shortest(b));
    which_betas = fmt::format(" (β = {})", fmt::join(values, ", "));
  }
  Section section{
      "beta",
      "Influence of β (Fig. 14)",
      "R1 and R2 disabled, " + std::to_string(experiments::kBetaRuns) +
          " runs per β: β = 0 (random search) needs the most trials; the search shortens as "
          "β grows; a large β (greedy) can get stuck above " +
          fixed(experiments::paper::kThresholdDeg, 0) + "°.",
      counted(t.rows.empty() ? 0 : t.rows.front().runs, "run") + " per β" + which_betas +
          ", at most " + std::to_string(ctx.sizes.beta_max_trials) +
          " trials each; the most trials on average at β = " +
          (most ? most->group + " (" + fixed(most->trials.mean, 1) + ")" : "-") + ".",
      {ctx.image(f)},
      {},
      {"experiments/beta/table.csv", "experiments/beta/table.md"},
      {experiments::beta_table(t.rows)}};
  section.verdicts = {
      {"β = 0 (random search) needs the most trials (Fig. 14)", "β = 0 the most",
       most ? "the most at β = " + most->group + " (" + fixed(most->trials.mean, 1) + " on average)"
            : "-",
       random_most ? Reproduced::yes : Reproduced::no}};
  return section;
}

}  // namespace multicpg::report
