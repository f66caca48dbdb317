// Simulated annealing over the working legs' periods (paper §3, Table 2; docs/learning.md "The
// search"). Model/state split: AnnealingParams is what the search is, AnnealingState what one run
// is doing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <set>
#include <string_view>
#include <vector>

#include "common/limits.h"
#include "learning/search_bounds.h"

namespace multicpg::learning {

inline constexpr double kDefaultBeta = 0.5;  // paper §3: "usually 0.5"
// Documented range: beta far past the paper's greedy 10 (Fig. 14).
inline constexpr Limits<double> kBetaLimits{0.0, 100.0};

// What the search is (immutable during a run): the bounds every learner shares (learning/
// search_bounds.h) and the annealing's own beta.
struct AnnealingParams {
  double beta = kDefaultBeta;                   // 0 = random search, 10 ~ greedy (paper Fig. 14)
  double threshold_deg = kDefaultThresholdDeg;  // stop when E < threshold
  int max_trials = kDefaultMaxTrials;           // reaching it ends the run "not converged"
  std::vector<int> period_set{4, 5, 6, 8, 9};   // Table 2 step (2)
};

// The annealing's parameters for a search of `bounds` with this beta.
AnnealingParams annealing_params(const SearchBounds& bounds, double beta);

// Throws OptionError (key "beta", "threshold_deg", "max_trials", "period_set") for a value
// outside its limits, or a period set that is empty, repeats a value or holds a period outside 1-9.
void validate(const AnnealingParams& params);

// A combination to try next.
struct Candidate {
  Periods periods;
  int legs_changed = 1;  // relative to the accepted combination: >1 after escalation
  int redraws = 0;       // draws thrown away because they were already tried (tabu)
};

// One measured trial of the annealing (paper Fig. 8 row, with the annealing's own details).
struct AnnealingTrial {
  int trial = 0;  // 1-based
  Periods periods;
  double deviation_deg = 0.0;
  bool accepted = false;
  double acceptance_probability = 1.0;  // exp(-beta (E - E_ref)), 1 when E < E_ref
  int legs_changed = 1;
  int redraws = 0;
};

// What one run is doing.
struct AnnealingState {
  std::vector<std::size_t> working;  // legs whose period may change (never the disabled ones)
  Periods accepted;                  // C(n) of Table 2
  double e_ref = 0.0;                // deviation of the accepted combination
  std::set<Periods> tried;           // tabu list: every combination measured, C0 included
  std::optional<Candidate> pending;  // proposed, not yet decided
  int trials = 0;
  StopReason stop = StopReason::running;
  std::mt19937_64 rng;  // the run's only source of randomness (docs/learning.md "Seeding")
  std::vector<AnnealingTrial> trace;
};

// Starts a run from C0 = `initial` whose measured deviation is `e_ref_c0`. `disabled` legs keep
// their period. Throws BadInput for invalid params, an unknown leg, every leg disabled, or a
// working leg whose initial period is outside the period set. If e_ref_c0 is already below the
// threshold the run is over (below_threshold, 0 trials).
AnnealingState start_annealing(const AnnealingParams& params, const Periods& initial,
                               const std::vector<std::size_t>& disabled, double e_ref_c0,
                               std::uint64_t seed);

// Draws the next combination to try (Table 2 steps 1-4) and adds it to the tabu list.
// One-leg changes of the accepted combination first; when all of them have been tried, k-leg
// changes with the smallest k that still has an untried combination. Returns nullopt, and sets
// stop = space_exhausted, when every combination has been tried.
std::optional<Candidate> propose(const AnnealingParams& params, AnnealingState& state);

struct Decision {
  bool accepted = false;
  double probability = 1.0;  // acceptance probability used
  StopReason stop = StopReason::running;
};

// Decides the pending candidate given its measured deviation (Table 2 step 7, docs/learning.md
// "Acceptance"): accept if E < E_ref, else iff a uniform draw x in [0,1) satisfies
// x < exp(-beta (E - E_ref)). Then stops if E < threshold, or if the trial cap is reached.
Decision decide(const AnnealingParams& params, AnnealingState& state, double deviation_deg);
// The same with the uniform draw given (used only when E >= E_ref), for scripted tests.
Decision decide_with_draw(const AnnealingParams& params, AnnealingState& state,
                          double deviation_deg, double uniform_draw);

}  // namespace multicpg::learning
