#include "learning/annealing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/errors.h"
#include "common/random.h"
#include "robot/leg_sets.h"

namespace multicpg::learning {
namespace {

// The 53 bits of a double's significand, and 2^-53 to scale them into [0, 1).

// Legs among `working` whose period differs between the two combinations.
std::size_t distance(const Periods& a, const Periods& b, const std::vector<std::size_t>& working) {
  return static_cast<std::size_t>(std::count_if(working.begin(), working.end(),
                                                [&](std::size_t leg) { return a[leg] != b[leg]; }));
}

// Combinations differing from a given one in exactly d of m legs, q periods each: C(m,d)(q-1)^d.
std::uint64_t neighbours_at(std::size_t m, std::size_t d, std::uint64_t q) {
  std::uint64_t count = 1;
  for (std::size_t i = 0; i < d; ++i) count = count * (m - i) / (i + 1);
  for (std::size_t i = 0; i < d; ++i) count *= q - 1;
  return count;
}

// Smallest number of legs to change so that an untried combination can come out (docs/learning.md
// "Candidates": one-leg changes first, then two, ...); 0 when every combination has been tried.
std::size_t escalation_level(const AnnealingParams& params, const AnnealingState& state) {
  const std::size_t m = state.working.size();
  std::vector<std::uint64_t> tried_at(m + 1, 0);
  for (const Periods& c : state.tried) ++tried_at[distance(c, state.accepted, state.working)];
  for (std::size_t d = 1; d <= m; ++d) {
    if (tried_at[d] < neighbours_at(m, d, params.period_set.size())) return d;
  }
  return 0;
}

void require_pending(const AnnealingState& state) {
  if (state.stop != StopReason::running) throw std::logic_error("annealing run has stopped");
  if (!state.pending) throw std::logic_error("decide() without a proposed candidate");
}

}  // namespace

void validate(const SearchBounds& bounds) {
  require_in("threshold_deg", bounds.threshold_deg, kThresholdLimits);
  require_in("max_trials", bounds.max_trials, kMaxTrialsLimits);
  if (bounds.period_set.empty()) throw OptionError("period_set", "is empty");
  std::set<int> seen;
  for (int p : bounds.period_set) {
    if (!robot::is_gait_period(p)) {
      throw OptionError("period_set",
                        "holds period " + std::to_string(p) +
                            ", which gives no gait (allowed: " + robot::gait_periods_text() + ")");
    }
    if (!seen.insert(p).second) {
      throw OptionError("period_set", "holds period " + std::to_string(p) + " twice");
    }
  }
}

AnnealingParams annealing_params(const SearchBounds& bounds, double beta) {
  return {beta, bounds.threshold_deg, bounds.max_trials, bounds.period_set};
}

void validate(const AnnealingParams& params) {
  require_in("beta", params.beta, kBetaLimits);
  validate(SearchBounds{params.period_set, params.threshold_deg, params.max_trials});
}

std::string_view to_string(StopReason reason) {
  return kStopReasonNames.name(reason);
}

AnnealingState start_annealing(const AnnealingParams& params, const Periods& initial,
                               const std::vector<std::size_t>& disabled, double e_ref_c0,
                               std::uint64_t seed) {
  validate(params);
  std::vector<bool> off(initial.size(), false);
  for (std::size_t leg : disabled) {
    if (leg >= initial.size()) {
      throw BadInput("disabled leg index " + std::to_string(leg) + " is not one of the " +
                     std::to_string(initial.size()) + " legs");
    }
    off[leg] = true;
  }
  AnnealingState state;
  for (std::size_t leg = 0; leg < initial.size(); ++leg) {
    if (off[leg]) continue;
    const bool in_set = std::find(params.period_set.begin(), params.period_set.end(),
                                  initial[leg]) != params.period_set.end();
    if (!in_set) {
      throw BadInput("working leg " + std::to_string(leg) + " starts at period " +
                     std::to_string(initial[leg]) + ", which is not in the period set");
    }
    state.working.push_back(leg);
  }
  if (state.working.empty()) throw BadInput("every leg is disabled: there is nothing to learn");
  if (!std::isfinite(e_ref_c0) || e_ref_c0 < 0.0) {
    throw BadInput("initial deviation must be a finite number >= 0");
  }
  state.accepted = initial;
  state.e_ref = e_ref_c0;
  state.tried.insert(initial);
  state.rng.seed(seed);
  if (e_ref_c0 < params.threshold_deg) state.stop = StopReason::below_threshold;
  return state;
}

std::optional<Candidate> propose(const AnnealingParams& params, AnnealingState& state) {
  if (state.stop != StopReason::running) throw std::logic_error("annealing run has stopped");
  if (state.pending) throw std::logic_error("propose() twice without decide()");
  const std::size_t level = escalation_level(params, state);
  if (level == 0) {
    state.stop = StopReason::space_exhausted;
    return std::nullopt;
  }
  Candidate candidate;
  candidate.legs_changed = static_cast<int>(level);
  std::vector<std::size_t> legs = state.working;
  for (;;) {
    // Table 2 steps 1-2, `level` times without repeating a leg (partial Fisher-Yates); every
    // draw starts again from the accepted combination (Table 2 step 4).
    candidate.periods = state.accepted;
    for (std::size_t i = 0; i < level; ++i) {
      std::swap(legs[i], legs[i + draw_below(state.rng, legs.size() - i)]);
      candidate.periods[legs[i]] =
          params.period_set[draw_below(state.rng, params.period_set.size())];
    }
    if (state.tried.insert(candidate.periods).second) break;
    ++candidate.redraws;
  }
  state.pending = candidate;
  return candidate;
}

Decision decide(const AnnealingParams& params, AnnealingState& state, double deviation_deg) {
  require_pending(state);
  // The draw is only needed, and only taken, when the candidate is not better.
  const double x = deviation_deg < state.e_ref ? 0.0 : draw_unit(state.rng);
  return decide_with_draw(params, state, deviation_deg, x);
}

Decision decide_with_draw(const AnnealingParams& params, AnnealingState& state,
                          double deviation_deg, double uniform_draw) {
  require_pending(state);
  if (!std::isfinite(deviation_deg) || deviation_deg < 0.0) {
    throw RuntimeFailure("measured deviation is not a finite angle >= 0");
  }
  Decision d;
  if (deviation_deg < state.e_ref) {
    d.accepted = true;
  } else {
    d.probability = std::exp(-params.beta * (deviation_deg - state.e_ref));
    d.accepted = uniform_draw < d.probability;
  }
  const Candidate candidate = *state.pending;
  state.pending.reset();
  ++state.trials;
  if (d.accepted) {
    state.accepted = candidate.periods;
    state.e_ref = deviation_deg;
  }
  state.trace.push_back(AnnealingTrial{state.trials, candidate.periods, deviation_deg, d.accepted,
                                       d.probability, candidate.legs_changed, candidate.redraws});
  if (deviation_deg < params.threshold_deg) {
    state.stop = StopReason::below_threshold;
  } else if (state.trials >= params.max_trials) {
    state.stop = StopReason::trial_cap;
  }
  d.stop = state.stop;
  return d;
}

}  // namespace multicpg::learning
