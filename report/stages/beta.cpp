// Fig. 14: the influence of the annealing factor β.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "common/table.h"
#include "experiments/paper.h"
#include "experiments/scenarios.h"
#include "report/stages/stage.h"

namespace multicpg::report {

namespace {

// Runs that ended without converging: in the capped study, cut at the trial cap.
int cut_runs(const experiments::GroupSummary& g) {
  return g.runs - g.converged - g.no_deviation;
}

// Whether the median falls on a cut run (the cut runs are the largest counts), so that it is
// only a lower bound.
bool median_censored(const experiments::GroupSummary& g) {
  return g.runs > 0 && 2 * cut_runs(g) >= g.runs + g.runs % 2;
}

}  // namespace

BetaMostTrials beta_zero_most_trials(const std::vector<experiments::GroupSummary>& rows,
                                     int max_trials) {
  const experiments::GroupSummary* zero = nullptr;
  int cut = 0;
  int runs = 0;
  std::vector<std::string> medians;
  for (const experiments::GroupSummary& g : rows) {
    if (std::stod(g.group) == 0.0) zero = &g;
    cut += cut_runs(g);
    runs += g.runs;
    medians.push_back("β = " + g.group + ": " + (median_censored(g) ? "≥ " : "") +
                      fixed(g.median_trials, 1));
  }
  BetaMostTrials out;
  out.text = fmt::format("median trials {}; {} of {} runs cut at the {}-trial cap{}",
                         fmt::join(medians, ", "), cut, runs, max_trials,
                         cut > 0 ? " (counted as the cap: they needed more)" : "");
  if (zero == nullptr) return out;
  bool undecided = false;
  for (const experiments::GroupSummary& g : rows) {
    if (&g == zero) continue;
    const bool zero_cut = median_censored(*zero);
    const bool other_cut = median_censored(g);
    if (zero_cut && other_cut) {
      undecided = true;  // both at least the cap: no telling which needed more
    } else if (other_cut || (!zero_cut && zero->median_trials <= g.median_trials)) {
      return out;  // another β needs as many or more
    }
  }
  out.reproduced = undecided ? Reproduced::partly : Reproduced::yes;
  return out;
}

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
          " trials each (a run cut at the cap counts as the cap); the most trials on average at "
          "β = " +
          (most ? most->group + " (" + fixed(most->trials.mean, 1) + ")" : "-") + ".",
      {ctx.image(f)},
      {},
      {"experiments/beta/table.csv", "experiments/beta/table.md"},
      {experiments::beta_table(t.rows)}};
  const BetaMostTrials claim = beta_zero_most_trials(t.rows, ctx.sizes.beta_max_trials);
  section.verdicts = {{"β = 0 (random search) needs the most trials (Fig. 14)", "β = 0 the most",
                       claim.text, claim.reproduced}};
  return section;
}

}  // namespace multicpg::report
