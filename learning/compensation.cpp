// Online malfunction compensation (compensation.h): the paper's learning and the robust run.
#include "learning/compensation.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/angles.h"
#include "common/enum_names.h"
#include "common/errors.h"
#include "common/limits.h"
#include "common/user_text.h"
#include "learning/course_walk.h"

namespace multicpg::learning {
namespace {

constexpr auto kModeNames = enum_names<Mode>({{Mode::paper, "paper"}, {Mode::robust, "robust"}});
constexpr auto kSteeringNames =
    enum_names<Steering>({{Steering::off, "off"}, {Steering::reflex, "reflex"}});
constexpr auto kOutcomeNames = enum_names<Outcome>({{Outcome::converged, "converged"},
                                                    {Outcome::not_converged, "not converged"},
                                                    {Outcome::no_deviation, "no deviation"},
                                                    {Outcome::budget_reached, "budget reached"}});

Periods current_periods(body::Body& body) {
  Periods periods;
  for (const neural::LegState& leg : body.controller().legs) periods.push_back(leg.cpg.period);
  return periods;
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

Criterion criterion(const CompensationOptions& options) {
  if (options.mode == Mode::paper) return kPaperCriterion;
  Criterion c =
      options.steering == Steering::reflex
          ? reflex_criterion(options.search.threshold_deg, options.steering_params.max_effort)
          : kPeriodsAloneCriterion;
  c.trial_windows = options.hold_windows;
  return c;
}

double robust_deviation(const CompensationOptions& options, const body::WindowMeasure& window) {
  Criterion c = criterion(options);
  c.path = true;
  return c.error(window);
}

long start_settle_steps(const CompensationOptions& options, const neural::ControllerModel& model) {
  if (options.settle_steps) return *options.settle_steps;
  return options.mode == Mode::paper
             ? default_settle_steps(model)
             : locked_settle_steps(model, Periods(model.size(), kStartPeriod));
}

std::string_view to_string(Mode mode) {
  return kModeNames.name(mode);
}

std::string_view to_string(Outcome outcome) {
  return kOutcomeNames.name(outcome);
}

Outcome parse_outcome(std::string_view text) {
  if (const std::optional<Outcome> outcome = kOutcomeNames.find(text)) return *outcome;
  throw BadInput("unknown outcome '" + std::string(text) + "' (" + kOutcomeNames.list(" or ") +
                 ")");
}

StopReason parse_stop_reason(std::string_view text) {
  if (const std::optional<StopReason> reason = kStopReasonNames.find(text)) return *reason;
  throw BadInput("unknown stop reason '" + std::string(text) + "'");
}

std::string_view to_string(Steering steering) {
  return kSteeringNames.name(steering);
}

Mode parse_mode(std::string_view text) {
  if (const std::optional<Mode> mode = kModeNames.find(text)) return *mode;
  throw BadInput(unknown_name("mode", text, kModeNames.names()));
}

Steering parse_steering(std::string_view text) {
  if (const std::optional<Steering> steering = kSteeringNames.find(text)) return *steering;
  throw BadInput(unknown_name("steering", text, kSteeringNames.names()));
}

void validate(const CompensationOptions& options) {
  // The annealing's beta and the bounds, as the record spells them (learning/json.h).
  within("annealing", [&] {
    if (const std::optional<double> beta = annealing_beta(options.learner)) {
      require_in("beta", *beta, kBetaLimits);
    }
    validate(options.search);
  });
  require_in("window_steps", options.window_steps, kWindowStepsLimits);
  if (options.settle_steps) require_in("settle_steps", *options.settle_steps, kSettleStepsLimits);
  require_in("detection_windows", options.detection_windows, kDetectionWindowsLimits);
  require_in("hold_windows", options.hold_windows, kHoldWindowsLimits);
  require_in("monitor_windows", options.monitor_windows, kMonitorWindowsLimits);
  require_in("max_episodes", options.max_episodes, kMaxEpisodesLimits);
  require_in("step_budget", options.step_budget, kStepBudgetLimits);
  within("steering_params", [&] { validate(options.steering_params); });
  within("learner", [&] { resolve_learner(options.learner); });
}

void validate_faults(const CompensationOptions& options, const body::FaultTimeline& faults) {
  if (options.mode == Mode::paper &&
      (faults.size() > 1 || (!faults.empty() && faults.front().recover))) {
    throw OptionError("mode",
                      "paper mode takes one fault and no recovery; use robust mode for this "
                      "fault timeline");
  }
}

body::Event detection_event(int episode, double deviation_deg, const Periods& periods) {
  body::Event e;
  e.kind = body::EventKind::detection;
  e.episode = episode;
  e.deviation_deg = deviation_deg;
  e.periods = periods;
  return e;
}

body::Event trial_end_event(int episode, const TrialRecord& trial) {
  body::Event e;
  e.kind = body::EventKind::trial_end;
  e.episode = episode;
  e.trial = trial.trial;
  e.periods = trial.periods;
  e.deviation_deg = trial.deviation_deg;
  e.accepted = trial.accepted;
  e.details = trial.details;
  return e;
}

body::Event episode_end_event(int episode, const Episode& ended) {
  body::Event e;
  e.kind = body::EventKind::episode_end;
  e.episode = episode;
  e.trial = ended.trials;
  e.periods = ended.periods;
  e.deviation_deg = ended.final_deviation_deg;
  e.accepted = ended.held;
  return e;
}

namespace {

// Tells the body's observer that a trial starts (kind trial_start) or was decided (trial_end).
void emit_trial_start(body::Body& body, int episode, int trial, const Periods& periods) {
  body::Event e;
  e.kind = body::EventKind::trial_start;
  e.episode = episode;
  e.trial = trial;
  e.periods = periods;
  body.emit(e);
}

// The steps a run spends in trials, against its budget (CompensationOptions::step_budget).
class Budget {
 public:
  explicit Budget(long steps) : steps_(steps) {}
  // Walks one trial's steps through `walk` and counts them.
  template <typename Walk>
  auto count(body::Body& body, Walk&& walk) {
    const long before = body.step_count();
    auto measured = walk();
    spent_ += body.step_count() - before;
    return measured;
  }
  bool used_up() const { return spent_ >= steps_; }

 private:
  long steps_;
  long spent_ = 0;
};

// What the episode's learner is told: the robot, C0 and its E, the failed legs, the bounds.
LearnerSetup learner_setup(const body::Body& body, const CompensationOptions& options,
                           const Periods& start, std::vector<std::size_t> failed,
                           std::vector<body::WindowMeasure> start_windows,
                           double start_deviation_deg, std::uint64_t seed) {
  LearnerSetup setup;
  setup.robot = body.controller_model().morphology.kind;
  setup.start = start;
  setup.told = options.tell_fault ? ToldFault::legs(std::move(failed)) : ToldFault::nothing();
  setup.start_deviation_deg = start_deviation_deg;
  setup.start_windows = std::move(start_windows);
  setup.criterion = criterion(options);
  setup.search = options.search;
  setup.seed = seed;
  return setup;
}

LearningResult compensate_paper(body::Body& body, const CompensationOptions& options,
                                const LearnerData& data) {
  const neural::ControllerModel& model = body.controller_model();
  LearningResult result;
  result.mode = Mode::paper;
  result.settle_steps = start_settle_steps(options, model);
  const SearchBounds& params = options.search;
  CourseWalk walk(body, options);

  // docs/learning.md "Detection": consecutive windows until one deviates more than the threshold.
  walk.steps(result.settle_steps);
  long windows_since_failure = 0;
  double e = 0.0;
  body::WindowMeasure detecting;
  for (;;) {
    detecting = walk.measured_window();
    e = std::abs(detecting.yaw_deg);  // docs/learning.md "Deviation"
    if (!body::holds(e, params.threshold_deg)) break;
    if (walk.failed() && ++windows_since_failure >= options.detection_windows) break;
  }
  result.initial_deviation_deg = e;
  result.final_deviation_deg = e;
  result.periods = current_periods(body);
  if (body::holds(e, params.threshold_deg)) {
    result.outcome = Outcome::no_deviation;
    result.steps_walked = walk.walked();
    return result;
  }
  result.detection_step = walk.walked();
  body.emit(detection_event(1, e, result.periods));

  // Paper §2.3: a deviation desynchronises every client; then learning from C0 = current periods.
  neural::set_synchronised(body.controller(), false);
  const std::unique_ptr<Learner> learner = make_learner(
      options.learner,
      learner_setup(body, options, result.periods, body::failing_legs(body.faults().timeline()),
                    {detecting}, e, options.seed),
      data);
  Budget budget(options.step_budget);
  EpisodeHooks hooks;
  hooks.measure = [&](int trial, const Periods& periods) {
    emit_trial_start(body, 1, trial, periods);
    return budget.count(body, [&] {
      neural::set_periods(model, body.controller(), periods);
      walk.steps(result.settle_steps);
      const body::WindowMeasure window = walk.measured_window();
      return Measurement{std::abs(window.yaw_deg), {window}};  // paper §3: E = |yaw change|
    });
  };
  hooks.decided = [&](const TrialRecord& t) {
    body.emit(trial_end_event(1, t));
    return budget.used_up();
  };
  EpisodeEnd end = run_episode(*learner, hooks);
  result.forecasts = learner->best_forecasts(kBestForecasts);
  // A run that did not converge keeps walking with the accepted combination, the one reported.
  if (current_periods(body) != end.answer.periods) {
    neural::set_periods(model, body.controller(), end.answer.periods);
  }

  result.outcome = end.reason == StopReason::below_threshold ? Outcome::converged
                   : end.reason == StopReason::running       ? Outcome::budget_reached
                                                             : Outcome::not_converged;
  if (end.reason != StopReason::running) result.reason = end.reason;
  result.trials = end.trials;
  result.final_deviation_deg = end.answer.deviation_deg;
  result.periods = end.answer.periods;
  result.trace = std::move(end.trace);
  result.steps_walked = walk.walked();
  Episode episode;
  episode.detection_step = *result.detection_step;
  episode.detection_deg = result.initial_deviation_deg;
  episode.trials = result.trials;
  episode.held = result.converged();
  episode.reason = result.reason;
  episode.periods = result.periods;
  episode.final_deviation_deg = result.final_deviation_deg;
  body.emit(episode_end_event(1, episode));
  result.episodes.push_back(std::move(episode));
  return result;
}

// Robust mode: see compensate() in the header.
class RobustRun {
 public:
  RobustRun(body::Body& body, const CompensationOptions& options, const LearnerData& data)
      : body_(body),
        options_(options),
        data_(data),
        model_(body.controller_model()),
        params_(options.search),
        walk_(body, options),
        budget_(options.step_budget) {}

  LearningResult run() {
    result_.mode = Mode::robust;
    result_.settle_steps = start_settle_steps(options_, model_);
    long monitored = 0;  // windows walked since the last fault or episode
    while (monitored < options_.monitor_windows || walk_.faults_pending()) {
      const body::WindowMeasure m = walk_.measured_window();
      const int faults = walk_.take_fault_count();
      if (walk_.take_full_recovery()) {
        resynchronise();
        forget();
        monitored = 0;
        result_.final_windows.clear();
        continue;
      }
      if (faults > 0) {
        // The window a fault came in measures the transient, not the controller that walks on:
        // neither a trigger for learning nor one of the windows after the last fault. What
        // earlier episodes measured was another body's.
        forget();
        monitored = 0;
        result_.final_windows.clear();
        continue;
      }
      if (!body::holds(error(m), params_.threshold_deg) && options_.learn_periods &&
          !nothing_left_ && static_cast<int>(result_.episodes.size()) < options_.max_episodes &&
          !budget_.used_up()) {
        episode(m);
        monitored = 0;
        result_.final_windows.clear();
        continue;
      }
      result_.final_windows.push_back(m);
      // Held, or nothing left to learn with (steering alone, every episode used): either way
      // the window counts toward the monitored windows that end the run.
      ++monitored;
    }
    finish();
    return std::move(result_);
  }

 private:
  double error(const body::WindowMeasure& m) const { return robust_deviation(options_, m); }

  long settle_for(const Periods& periods) const {
    return options_.settle_steps.value_or(locked_settle_steps(model_, periods));
  }

  Periods periods() {
    Periods p;
    for (const neural::LegState& leg : body_.controller().legs) p.push_back(leg.cpg.period);
    return p;
  }

  void set(const Periods& p) {
    neural::set_periods(model_, body_.controller(), p);
    walk_.steps(settle_for(p));
  }

  // The trials walked so far describe another body (a fault came or went).
  void forget() {
    memory_.clear();
    nothing_left_ = false;
  }

  // Paper §2.3: every leg works again: all legs at the master's period, clients synchronised.
  void resynchronise() {
    neural::ControllerState& c = body_.controller();
    neural::set_period(model_, c, c.legs.front().cpg.period);
    neural::set_synchronised(c, true);
    walk_.steps(settle_for(periods()));
    walk_.take_fault_count();
  }

  void episode(const body::WindowMeasure& detecting) {
    const double detection_deg = error(detecting);
    const int number = static_cast<int>(result_.episodes.size()) + 1;
    Episode ep;
    ep.detection_step = walk_.walked();
    ep.detection_deg = detection_deg;
    if (!result_.detection_step) {
      result_.detection_step = ep.detection_step;
      result_.initial_deviation_deg = detection_deg;
    }
    body_.emit(detection_event(number, detection_deg, periods()));

    neural::set_synchronised(body_.controller(), false);  // paper §2.3
    // Episode k > 1 draws from its own stream, so a run's first episode is the seed's.
    const std::uint64_t seed = options_.seed + static_cast<std::uint64_t>(number - 1);
    LearnerSetup setup = learner_setup(body_, options_, periods(), walk_.failed_now(), {detecting},
                                       detection_deg, seed);
    setup.earlier = memory_;
    const std::unique_ptr<Learner> learner = make_learner(options_.learner, setup, data_);
    walk_.take_fault_count();
    std::vector<EarlierTrial> walked;
    EpisodeHooks hooks;
    hooks.measure = [&](int trial, const Periods& candidate) {
      emit_trial_start(body_, number, trial, candidate);
      Measurement m = budget_.count(
          body_, [&] { return robust_trial(walk_, options_, candidate, options_.hold_windows); });
      walked.push_back({candidate, m.windows});
      return m;
    };
    hooks.decided = [&](const TrialRecord& t) {
      body_.emit(trial_end_event(number, t));
      if (walk_.take_fault_count() > 0) ep.interrupted = true;
      return ep.interrupted || budget_.used_up();
    };
    EpisodeEnd end = run_episode(*learner, hooks);
    // A fault that came during the episode makes what it walked another body's.
    if (ep.interrupted) {
      forget();
    } else {
      memory_.insert(memory_.end(), walked.begin(), walked.end());
      // Nothing was left to try: the next episode would start here, told the same trials, and
      // try nothing either, so none starts until a fault makes the run forget them.
      nothing_left_ = end.reason == StopReason::space_exhausted && end.trials == 0;
    }
    result_.forecasts = learner->best_forecasts(kBestForecasts);
    if (periods() != end.answer.periods) set(end.answer.periods);
    ep.trials = end.trials;
    ep.held = end.reason == StopReason::below_threshold;
    if (end.reason != StopReason::running) ep.reason = end.reason;
    ep.periods = end.answer.periods;
    ep.final_deviation_deg = end.answer.deviation_deg;
    for (TrialRecord& t : end.trace) result_.trace.push_back(std::move(t));
    result_.trials += end.trials;
    body_.emit(episode_end_event(number, ep));
    result_.episodes.push_back(std::move(ep));
  }

  void finish() {
    result_.periods = periods();
    result_.steps_walked = walk_.walked();
    result_.steering_effort = walk_.effort();
    result_.steering = walk_.steering();
    const bool held = std::all_of(
        result_.final_windows.begin(), result_.final_windows.end(),
        [&](const body::WindowMeasure& m) { return body::holds(error(m), params_.threshold_deg); });
    if (result_.episodes.empty()) {
      result_.outcome = held ? Outcome::no_deviation : Outcome::not_converged;
      if (!result_.final_windows.empty()) {
        result_.initial_deviation_deg = error(result_.final_windows.front());
      }
    } else {
      const Episode& last = result_.episodes.back();
      // A budget used up ended the last episode or kept the next one from starting.
      result_.outcome = last.held && held   ? Outcome::converged
                        : budget_.used_up() ? Outcome::budget_reached
                                            : Outcome::not_converged;
      result_.reason = last.reason;
      // Another episode would have started had the cap allowed it: the cap ended the run.
      if (!held && options_.learn_periods && !budget_.used_up() &&
          static_cast<int>(result_.episodes.size()) >= options_.max_episodes) {
        result_.reason = StopReason::episode_cap;
      }
    }
    double worst = 0.0;
    for (const body::WindowMeasure& m : result_.final_windows) worst = std::max(worst, error(m));
    result_.final_deviation_deg = worst;
  }

  body::Body& body_;
  const CompensationOptions& options_;
  const LearnerData& data_;
  const neural::ControllerModel& model_;
  const SearchBounds& params_;
  CourseWalk walk_;
  Budget budget_;
  LearningResult result_;
  // What this run's episodes walked since the faults last changed (LearnerSetup::earlier).
  std::vector<EarlierTrial> memory_;
  // An episode tried nothing, every combination in memory_: no later one can try another.
  bool nothing_left_ = false;
};

}  // namespace

LearningResult compensate(body::Body& body, const CompensationOptions& options,
                          const LearnerData& data) {
  validate(options);
  validate_faults(options, body.faults().timeline());
  if (body.step_count() != 0) {
    throw std::invalid_argument("compensate: the body must be at its start");
  }
  LearningResult result = options.mode == Mode::paper ? compensate_paper(body, options, data)
                                                      : RobustRun(body, options, data).run();
  if (data.landscapes)
    result.learned_from = LearnedFrom{data.source.string(), data.landscapes->walked()};
  return result;
}

}  // namespace multicpg::learning
