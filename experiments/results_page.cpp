#include "experiments/results_page.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

namespace multicpg::experiments {
namespace {

// What the paper states in its text (its Figs. 11, 13 and 14 are not in the text).
constexpr double kPaperR1InitialDeg = 37.86;  // §4.1, Fig. 8
constexpr double kPaperR1FinalDeg = 0.25;
constexpr int kPaperR1Trials = 7;
constexpr double kThresholdDeg = 8.0;  // E_req, §4.1
// Learned combinations the paper uses on the real robot (§5; reference §5.4).
const std::map<std::string, std::string> kPaperCombinations{{"R1", "R2=5 R3=4 L1=5 L2=6 L3=5"},
                                                            {"R1+R3", "R2=4 L1=6 L2=4 L3=9"},
                                                            {"R1+R3+L2", "R2=4 L1=4 L3=9"}};

std::string num(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string pct(int part, int whole) {
  return whole > 0 ? num(100.0 * part / whole, 0) + " %" : "-";
}

const GroupSummary* find_row(const ExperimentTable& t, const std::string& group) {
  for (const GroupSummary& r : t.rows) {
    if (r.group == group) return &r;
  }
  return nullptr;
}

std::string markdown_table(const ExperimentTable& t) {
  return t.experiment == "beta" ? beta_table_markdown(t.rows) : scenario_table_markdown(t.rows);
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
    if (r.median_trials <= kPaperTrials) ++s.groups_median_within;
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
      << "controlled within 20 trials\" | " << s.groups_median_within << " of the "
      << s.groups_deviating << " scenarios that deviated have a median of at most 20 trials; "
      << pct(s.within, s.learned()) << " of the runs that learned converged within 20 trials — "
      << (2 * s.groups_median_within > s.groups_deviating ? "agrees" : "**differs**") << " |\n"
      << "| learning ends with a deviation under " << num(kThresholdDeg, 0) << "° | " << s.converged
      << " of the " << s.learned() << " runs that learned converged below " << num(kThresholdDeg, 0)
      << "° — "
      << (s.converged == s.learned() ? std::string("agrees")
                                     : "**differs**: " + std::to_string(s.learned() - s.converged) +
                                           " ended at the trial cap")
      << "; " << s.no_deviation << " of " << s.runs
      << " runs never deviated more than the threshold (nothing to learn) |\n";
}

void paper_examples(std::ostringstream& out, const ExperimentTable& t) {
  if (const GroupSummary* r1 = find_row(t, "R1")) {
    out << "| R1 disabled: 37.86° before learning, 0.25° after " << kPaperR1Trials
        << " trials (Fig. 8) | initial " << num(r1->initial_deviation_deg.mean, 2) << " ± "
        << num(r1->initial_deviation_deg.sd, 2) << "°, final "
        << num(r1->final_deviation_deg.mean, 2) << "°, median " << num(r1->median_trials, 1)
        << " trials — "
        << (std::abs(r1->initial_deviation_deg.mean - kPaperR1InitialDeg) <
                    0.25 * kPaperR1InitialDeg
                ? "the turn is of the paper's size"
                : "**differs**: our turn is " +
                      std::string(r1->initial_deviation_deg.mean < kPaperR1InitialDeg
                                      ? "weaker"
                                      : "stronger") +
                      " than the paper's")
        << " (paper's final " << num(kPaperR1FinalDeg, 2) << "° is one run) |\n";
  }
  for (const auto& [scenario, combination] : kPaperCombinations) {
    const GroupSummary* r = find_row(t, scenario);
    if (r == nullptr) continue;
    out << "| " << scenario << " disabled: learned " << combination << " (used on the real "
        << "robot) | most frequent: " << (r->best_periods.empty() ? "none" : r->best_periods)
        << " — "
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
        << most->group << " (" << num(most->trials.mean, 1)
        << "); β = 0: " << num(zero->trials.mean, 1) << " — "
        << (most->group == "0" ? "agrees" : "**differs**") << " |\n";
  }
  if (greedy != nullptr) {
    out << "| a large β (greedy) may get stuck at a worse solution | β = 10: "
        << pct(greedy->converged, greedy->runs) << " converged, final deviation "
        << num(greedy->final_deviation_deg.mean, 2) << " ± "
        << num(greedy->final_deviation_deg.sd, 2) << "° |\n";
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
