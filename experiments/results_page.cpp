#include "experiments/results_page.h"

#include <algorithm>
#include <sstream>

#include "common/table.h"
#include "experiments/paper.h"

namespace multicpg::experiments {
namespace {

// The paper's Figs. 11, 13 and 14 are not in its text: only what it states (paper.h) is compared.
// Our R1 turn is "of the paper's size" when within this share of the paper's.
constexpr double kSameSizeShare = 0.25;

std::string pct(int part, int whole) {
  return whole > 0 ? fixed(100.0 * part / whole, 0) + " %" : "-";
}

const GroupSummary* find_row(const ExperimentTable& t, const std::string& group) {
  for (const GroupSummary& r : t.rows) {
    if (r.group == group) return &r;
  }
  return nullptr;
}

std::string markdown_table(const ExperimentTable& t) {
  return to_markdown(t.experiment == ExperimentKind::beta ? beta_table(t.rows)
                                                          : scenario_table(t.rows));
}

// Runs whose robot never deviated more than the threshold (e.g. R1+L1, a symmetric loss) have
// nothing to learn; the paper's statements are about the runs that learned.
struct Totals {
  int runs = 0, no_deviation = 0, converged = 0, within = 0;
  int groups_deviating = 0, groups_median_within = 0;
  int learned() const { return runs - no_deviation; }
};

Totals totals(const ExperimentTable& t) {
  Totals s;
  for (const GroupSummary& r : t.rows) {
    s.runs += r.runs;
    s.no_deviation += r.no_deviation;
    s.converged += r.converged;
    s.within += r.within_paper_trials;
    if (r.no_deviation == r.runs) continue;
    ++s.groups_deviating;
    if (r.median_trials <= paper::kMostTrials) ++s.groups_median_within;
  }
  return s;
}

void scenario_section(std::ostringstream& out, const ExperimentTable& t, const std::string& fig) {
  const Totals s = totals(t);
  out << "Per scenario: runs, share converged below the threshold, runs whose first window "
         "never deviated, final deviation and trials (mean ± SD over all runs), and the most "
         "frequent final combination of the working legs among converged runs.\n\n"
      << markdown_table(t) << "\n"
      << "| The paper states | Ours |\n|---|---|\n"
      << "| " << fig << ": \"the learning time for most of the scenarios can be normally "
      << "controlled within " << paper::kMostTrials << " trials\" | " << s.groups_median_within
      << " of the " << s.groups_deviating << " scenarios that deviated have a median of at most "
      << paper::kMostTrials << " trials; " << pct(s.within, s.learned())
      << " of the runs that learned converged within " << paper::kMostTrials << " trials — "
      << (2 * s.groups_median_within > s.groups_deviating ? "agrees" : "**differs**") << " |\n"
      << "| learning ends with a deviation under " << fixed(paper::kThresholdDeg, 0) << "° | "
      << s.converged << " of the " << s.learned() << " runs that learned converged below "
      << fixed(paper::kThresholdDeg, 0) << "° — "
      << (s.converged == s.learned() ? std::string("agrees")
                                     : "**differs**: " + std::to_string(s.learned() - s.converged) +
                                           " ended at the trial cap")
      << "; " << s.no_deviation << " of " << s.runs
      << " runs never deviated more than the threshold (nothing to learn) |\n";
}

void paper_examples(std::ostringstream& out, const ExperimentTable& t) {
  if (const GroupSummary* r1 = find_row(t, "R1")) {
    const double ours = r1->initial_deviation_deg.mean;
    out << "| R1 disabled: " << fixed(paper::kR1InitialDeg, 2) << "° before learning, "
        << fixed(paper::kR1FinalDeg, 2) << "° after " << paper::kR1Trials
        << " trials (Fig. 8) | initial " << mean_pm_sd(ours, r1->initial_deviation_deg.sd, 2)
        << "°, final " << fixed(r1->final_deviation_deg.mean, 2) << "°, median "
        << fixed(r1->median_trials, 1) << " trials — "
        << (std::abs(ours - paper::kR1InitialDeg) < kSameSizeShare * paper::kR1InitialDeg
                ? "the turn is of the paper's size"
                : "**differs**: our turn is " +
                      std::string(ours < paper::kR1InitialDeg ? "weaker" : "stronger") +
                      " than the paper's")
        << " (paper's final " << fixed(paper::kR1FinalDeg, 2) << "° is one run) |\n";
  }
  for (const paper::TunnelResult& learned : paper::kTunnel) {
    const GroupSummary* r = find_row(t, std::string(learned.disabled));
    if (r == nullptr) continue;
    const std::string combination = paper::combination_text(learned.learned);
    out << "| " << learned.disabled << " disabled: learned " << combination
        << " (used on the real robot) | most frequent: "
        << (r->best_periods.empty() ? "none" : r->best_periods) << " — "
        << (r->best_periods == combination
                ? "the same"
                : "**differs**: many combinations walk straight, and ours are found on a "
                  "different body (MuJoCo, not ODE)")
        << " |\n";
  }
}

void beta_section(std::ostringstream& out, const ExperimentTable& t) {
  out << markdown_table(t) << "\n";
  const auto most =
      std::max_element(t.rows.begin(), t.rows.end(),
                       [](const auto& a, const auto& b) { return a.trials.mean < b.trials.mean; });
  const GroupSummary* zero = find_row(t, "0");
  const GroupSummary* greedy = find_row(t, "10");
  out << "| The paper states (Fig. 14, R1+R2 disabled) | Ours |\n|---|---|\n";
  if (zero != nullptr && most != t.rows.end()) {
    out << "| β = 0 (random search) needs the longest search | most trials on average at β = "
        << most->group << " (" << fixed(most->trials.mean, 1)
        << "); β = 0: " << fixed(zero->trials.mean, 1) << " — "
        << (most->group == "0" ? "agrees" : "**differs**") << " |\n";
  }
  if (greedy != nullptr) {
    out << "| a large β (greedy) may get stuck at a worse solution | β = 10: "
        << pct(greedy->converged, greedy->runs) << " converged, final deviation "
        << mean_pm_sd(greedy->final_deviation_deg.mean, greedy->final_deviation_deg.sd, 2)
        << "° |\n";
  }
}

}  // namespace

std::string results_markdown(const ResultsInputs& in) {
  std::ostringstream out;
  out << "# Results\n\n"
      << "Generated by `" << in.command << "` from the experiments' saved runs; do not edit by "
      << "hand. The paper's Figs. 11, 13 and 14 are not in its text, so only what it states "
      << "in words is compared. Our robots walk in MuJoCo, not the authors' ODE simulator (see "
      << "`docs/robots.md`), so the numbers are ours, not a copy of theirs.\n\n";
  if (in.hexapod) {
    out << "## Hexapod: learning per scenario (paper Fig. 11)\n\n";
    scenario_section(out, *in.hexapod, "§4.1");
    paper_examples(out, *in.hexapod);
    out << "\n";
  }
  if (in.quadruped) {
    out << "## Quadruped: learning per scenario (paper Fig. 13)\n\n"
        << "The paper gives no numbers for the quadruped in its text, only that \"the controller "
        << "can find feasible combinations of periods in the different conditions\".\n\n";
    scenario_section(out, *in.quadruped, "§4.2 (by analogy with §4.1)");
    out << "\n";
  }
  if (in.beta) {
    out << "## Influence of β (paper Fig. 14)\n\n";
    beta_section(out, *in.beta);
    out << "\n";
  }
  return out.str();
}

}  // namespace multicpg::experiments
