#include "learning/compensation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/angles.h"
#include "common/errors.h"

namespace multicpg::learning {
namespace {

// Walks the robot on, failing the legs at the configured step (SPEC §4: faults at any step).
class Walk {
 public:
  Walk(Walker& walker, const CompensationOptions& options)
      : walker_(walker), options_(options), start_(walker.step_count()) {}

  void steps(long n) {
    for (long i = 0; i < n; ++i) {
      if (!failed_ && walked() >= options_.fail_step) {
        walker_.disable(options_.disabled);
        failed_ = true;
      }
      walker_.step();
    }
  }

  // E of one measured window (SPEC §6): |yaw(end) - yaw(start)| wrapped.
  double window() {
    const double start_yaw = walker_.yaw_deg();
    steps(options_.window_steps);
    const double e = std::abs(wrap_degrees(walker_.yaw_deg() - start_yaw));
    if (!std::isfinite(e)) throw RuntimeFailure("the walker's yaw is not a finite number");
    return e;
  }

  long walked() const { return walker_.step_count() - start_; }
  bool failed() const { return failed_; }

 private:
  Walker& walker_;
  const CompensationOptions& options_;
  long start_;
  bool failed_ = false;
};

Periods current_periods(Walker& walker) {
  Periods periods;
  for (const neural::LegState& leg : walker.controller().legs) periods.push_back(leg.cpg.period);
  return periods;
}

nlohmann::json periods_json(const robot::Morphology& morph, const Periods& periods) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < periods.size(); ++i) out[morph.legs[i].name] = periods[i];
  return out;
}

}  // namespace

namespace {
int longest_delay(const neural::ControllerModel& model) {
  int longest = 0;
  for (const neural::LegCircuit& leg : model.legs) longest = std::max(longest, leg.delay);
  return longest;
}
}  // namespace

long default_settle_steps(const neural::ControllerModel& model) {
  return kSlowestLockSteps + longest_delay(model);
}

long locked_settle_steps(const neural::ControllerModel& model, const Periods& periods) {
  long slowest = 0;
  for (int p : periods) slowest = std::max(slowest, neural::lock_steps(p));
  return slowest + longest_delay(model);
}

void validate(const CompensationOptions& options, const robot::Morphology& morph) {
  validate(options.annealing);
  if (options.window_steps < 1) {
    throw BadInput("window must be at least 1 step, got " + std::to_string(options.window_steps));
  }
  if (options.settle_steps && *options.settle_steps < 0) {
    throw BadInput("settle steps must not be negative, got " +
                   std::to_string(*options.settle_steps));
  }
  if (options.fail_step < 0) {
    throw BadInput("fail step must not be negative, got " + std::to_string(options.fail_step));
  }
  if (options.detection_windows < 1) {
    throw BadInput("detection windows must be at least 1, got " +
                   std::to_string(options.detection_windows));
  }
  std::vector<bool> seen(morph.size(), false);
  for (std::size_t leg : options.disabled) {
    if (leg >= morph.size()) {
      throw BadInput("the " + morph.name + " has no leg number " + std::to_string(leg));
    }
    if (seen[leg]) throw BadInput("leg " + morph.legs[leg].name + " is disabled twice");
    seen[leg] = true;
  }
  if (options.disabled.size() == morph.size()) {
    throw BadInput("every leg of the " + morph.name + " is disabled: there is nothing to learn");
  }
}

LearningResult compensate(Walker& walker, const CompensationOptions& options) {
  const neural::ControllerModel& model = walker.controller_model();
  validate(options, model.morphology);
  LearningResult result;
  result.settle_steps = options.settle_steps.value_or(default_settle_steps(model));
  const AnnealingParams& params = options.annealing;
  Walk walk(walker, options);

  // Detection (SPEC §6): consecutive windows until one deviates more than the threshold.
  walk.steps(result.settle_steps);
  long windows_since_failure = 0;
  double e = 0.0;
  for (;;) {
    e = walk.window();
    if (e > params.threshold_deg) break;
    if (walk.failed() && ++windows_since_failure >= options.detection_windows) break;
  }
  result.initial_deviation_deg = e;
  result.final_deviation_deg = e;
  result.periods = current_periods(walker);
  if (!(e > params.threshold_deg)) {
    result.status = "no deviation";
    result.steps_walked = walk.walked();
    return result;
  }
  result.detection_step = walk.walked();

  // SPEC §5: a deviation desynchronises every client; then learning from C0 = current periods.
  neural::set_synchronised(walker.controller(), false);
  AnnealingState state = start_annealing(params, result.periods, options.disabled, e, options.seed);
  while (std::optional<Candidate> candidate = propose(params, state)) {
    neural::set_periods(model, walker.controller(), candidate->periods);
    walk.steps(result.settle_steps);
    if (decide(params, state, walk.window()).stop != StopReason::running) break;
  }
  // A run that did not converge keeps walking with the accepted combination, the one reported.
  if (current_periods(walker) != state.accepted) {
    neural::set_periods(model, walker.controller(), state.accepted);
  }

  result.converged = state.stop == StopReason::below_threshold;
  result.status = result.converged ? "converged" : "not converged";
  result.reason = state.stop;
  result.trials = state.trials;
  result.final_deviation_deg = state.e_ref;
  result.periods = state.accepted;
  result.trace = std::move(state.trace);
  result.steps_walked = walk.walked();
  return result;
}

nlohmann::json to_json(const LearningResult& result, const robot::Morphology& morph,
                       const std::vector<std::size_t>& disabled) {
  nlohmann::json trace = nlohmann::json::array();
  for (const TrialRecord& t : result.trace) {
    trace.push_back({{"trial", t.trial},
                     {"periods", periods_json(morph, t.periods)},
                     {"deviation_deg", t.deviation_deg},
                     {"accepted", t.accepted},
                     {"acceptance_probability", t.acceptance_probability},
                     {"legs_changed", t.legs_changed},
                     {"redraws", t.redraws},
                     {"tabu_redraw", t.redraws > 0}});
  }
  nlohmann::json disabled_names = nlohmann::json::array();
  for (std::size_t leg : disabled) disabled_names.push_back(morph.legs.at(leg).name);
  return {{"converged", result.converged},
          {"status", result.status},
          {"reason", result.reason ? nlohmann::json(std::string(to_string(*result.reason)))
                                   : nlohmann::json(nullptr)},
          {"trials", result.trials},
          {"initial_deviation_deg", result.initial_deviation_deg},
          {"final_deviation_deg", result.final_deviation_deg},
          {"periods", periods_json(morph, result.periods)},
          {"disabled", disabled_names},
          {"steps_walked", result.steps_walked},
          {"detection_step", result.detection_step ? nlohmann::json(*result.detection_step)
                                                   : nlohmann::json(nullptr)},
          {"settle_steps", result.settle_steps},
          {"trace", trace}};
}

}  // namespace multicpg::learning
