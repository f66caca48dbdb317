#include "apps/learning_output.h"

#include <algorithm>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>

#include "body/fault_spec.h"
#include "experiments/run_json.h"
#include "learning/learners.h"
#include "learning/model_learner.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "robot/terrain.h"

namespace multicpg::apps {
namespace {

std::string degrees(double value) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << value << "°";
  return s.str();
}

std::string number(double value) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << value;
  return s.str();
}

std::string period_cells(const std::vector<int>& periods,
                         const std::vector<std::size_t>& disabled) {
  std::ostringstream row;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    const bool off = std::find(disabled.begin(), disabled.end(), i) != disabled.end();
    row << std::setw(4) << (std::to_string(periods[i]) + (off ? "x" : ""));
  }
  return row.str();
}

// The predicted column's width: "12.34° [10.21, 15.67]" and room.
constexpr int kPredictedWidth = 24;

// A model-based learner's forecast of the trial's E (learning/forecast.h): its median and band,
// "12.34° [10.21, 15.67]"; empty for a trial without one.
std::string predicted_cell(const nlohmann::json& details) {
  const std::optional<learning::ForecastE> e = learning::forecast_e(details);
  if (!e) return "";
  return degrees(e->deg) + " [" + number(e->low_deg) + ", " + number(e->high_deg) + "]";
}

// A table row: label, periods (x = disabled), E, the model's forecast of E when the learner has
// a model (`predicted` set, empty for C0), what became of it.
void row(std::ostream& out, const std::string& label, const std::vector<int>& periods,
         const std::vector<std::size_t>& disabled, double deviation_deg,
         const std::optional<std::string>& predicted, const std::string& decision) {
  out << std::setw(5) << label << period_cells(periods, disabled) << std::setw(10)
      << degrees(deviation_deg);
  if (predicted) out << std::setw(kPredictedWidth) << *predicted;
  out << "  " << decision << std::endl;
}

std::string stop_text(learning::StopReason reason) {
  switch (reason) {
    case learning::StopReason::below_threshold:
      return "held under the threshold";
    case learning::StopReason::trial_cap:
      return "the trial cap (--max-trials) was reached";
    case learning::StopReason::space_exhausted:
      return "every combination was tried";
    case learning::StopReason::episode_cap:
      return "the episode cap (--max-episodes) was reached";
    case learning::StopReason::running:
      break;
  }
  return "stopped";
}

// The trial of the lowest E in the trace (numbered across episodes), if any.
void print_best_trial(std::ostream& out, const experiments::RunSpec& spec,
                      const learning::LearningResult& r) {
  if (r.trace.empty()) return;
  const auto best = std::min_element(
      r.trace.begin(), r.trace.end(),
      [](const auto& a, const auto& b) { return a.deviation_deg < b.deviation_deg; });
  out << "best trial measured: trial " << (best - r.trace.begin()) + 1 << ", "
      << robot::period_map_text(experiments::morphology(spec.robot), best->periods,
                                body::failing_legs(spec.faults))
      << ", E " << degrees(best->deviation_deg) << "\n";
}

}  // namespace

std::string counted(long n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

std::string robot_text(const experiments::RobotSpec& robot) {
  const std::string layout = experiments::morphology(robot).name;
  if (!robot.file) return layout;
  return layout + " from " + robot.file->record.path + " (" + robot.file->record.name + ")";
}

std::string world_text(const experiments::RunSpec& spec) {
  std::string text = "terrain " + robot::terrain_text(spec.robot.sim.scene.terrain) + ", ";
  if (spec.robot.file) return text + "body from the robot file's model";
  return text + "body model " + std::string(robot::to_string(spec.robot.sim.model));
}

void print_learning_header(std::ostream& out, const experiments::RunSpec& spec, long settle_steps) {
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  const learning::CompensationOptions& options = *spec.learning;
  out << robot_text(spec.robot) << ", " << learning::to_string(options.mode) << " mode";
  if (options.mode == learning::Mode::robust) {
    out << " (steering " << learning::to_string(options.steering) << ", "
        << counted(options.hold_windows, "window") << " to hold)";
  }
  out << ", faults";
  for (const body::Fault& f : spec.faults) {
    out << " " << body::malfunction_text(morph, f) << (f.recover ? " recover" : " fail") << "@"
        << f.step;
  }
  // Robust mode's learner depends on the robot's data (learning/default_learner.h): always named.
  if (options.mode == learning::Mode::robust || options.learner.name != learning::kPaperLearner) {
    out << ", learner " << options.learner.name;
    // Its options where they are not its defaults (the annealing's beta has a place of its own).
    nlohmann::json changed = learning::changed_options(options.learner);
    if (learning::annealing_beta(options.learner)) changed.erase("beta");
    std::string listed;
    for (const auto& [key, value] : changed.items()) {
      listed += (listed.empty() ? "" : ", ") + key + "=" +
                (value.is_string() ? value.get<std::string>() : value.dump());
    }
    if (!listed.empty()) out << " (" << listed << ")";
  }
  if (!options.tell_fault) out << " told nothing of the fault";
  if (const std::optional<double> beta = learning::annealing_beta(options.learner))
    out << ", beta " << *beta;
  out << ", threshold " << degrees(options.search.threshold_deg) << ", window "
      << options.window_steps << ", settle " << settle_steps << ", seed " << options.seed << "\n"
      << world_text(spec) << ", step budget " << options.step_budget << "\n\n";
  out << "trial";
  for (const robot::Leg& leg : morph.legs) out << std::setw(4) << leg.name;
  out << "  deviation";
  // The model's median E of a window and its band (docs/learning.md "Inside the model").
  if (learning::forecasts(options.learner.name))
    out << std::setw(kPredictedWidth) << "predicted E [band]";
  out << "  decision" << std::endl;
}

LearningTable::LearningTable(std::ostream& out, const experiments::RunSpec& spec)
    : out_(out),
      spec_(spec),
      disabled_(body::failing_legs(spec.faults)),
      forecasts_(learning::forecasts(spec.learning->learner.name)) {}

std::optional<std::string> LearningTable::predicted(const std::string& cell) const {
  return forecasts_ ? std::optional<std::string>(cell) : std::nullopt;
}

void LearningTable::event(const body::Event& e) {
  const robot::Morphology& morph = experiments::morphology(spec_.robot);
  const double threshold = spec_.learning->search.threshold_deg;
  switch (e.kind) {
    case body::EventKind::fault:
    case body::EventKind::recovery:
      if (e.fault) {
        out_ << "-- step " << e.step << ": " << body::malfunction_text(morph, *e.fault)
             << (e.fault->recover ? " recovers" : " fails") << std::endl;
      }
      return;
    case body::EventKind::detection:
      out_ << "-- episode " << e.episode << ": the window ending at step " << e.step << " deviated "
           << degrees(e.deviation_deg) << " (threshold " << degrees(threshold)
           << "): CPGs desynchronised, learning starts" << std::endl;
      row(out_, "start", e.periods, disabled_, e.deviation_deg, predicted(""),
          "C0, the periods it deviated with");
      return;
    case body::EventKind::trial_end: {
      ++trials_;
      std::ostringstream decision;
      // "kept" is the annealing's: the search moves on from this combination (E_ref), a worse one
      // with probability P (paper §3). The other learners answer with their best so far.
      if (spec_.learning->learner.name == learning::kPaperLearner) {
        decision << (e.accepted ? "kept" : "rejected");
      } else {
        decision << (e.accepted ? "new best" : "not better");
      }
      // The annealing's acceptance probability of a worse combination (paper §3).
      const double p = e.details.value("acceptance_probability", 1.0);
      if (p < 1.0) decision << " (P = " << std::setprecision(3) << std::scientific << p << ")";
      row(out_, std::to_string(trials_), e.periods, disabled_, e.deviation_deg,
          predicted(predicted_cell(e.details)), decision.str());
      return;
    }
    case body::EventKind::episode_end:
      out_ << "-- episode " << e.episode << " ended after " << counted(e.trial, "trial") << ": "
           << (e.accepted ? "held under " + degrees(threshold) : "not held") << "; walks on with "
           << robot::period_map_text(morph, e.periods, disabled_) << " (E "
           << degrees(e.deviation_deg) << ")" << std::endl;
      return;
    case body::EventKind::trial_start:
      return;
  }
}

LearningStream::LearningStream(std::ostream& out, std::ostream& progress,
                               const experiments::RunSpec& spec)
    : table_(out, spec), progress_(progress) {}

void LearningStream::on_step(const sim::SimModel& /*model*/, const sim::SimState& /*state*/) {
  ++steps_;
  if (steps_ - last_line_ < kProgressEverySteps) return;
  last_line_ = steps_;
  progress_ << "learn: step " << steps_ << ", " << doing_ << std::endl;
}

void LearningStream::on_event(const sim::SimModel& /*model*/, const sim::SimState& /*state*/,
                              const body::Event& event) {
  switch (event.kind) {
    case body::EventKind::trial_start:
      doing_ = "walking trial " + std::to_string(table_.trials() + 1);
      break;
    case body::EventKind::episode_end:
      doing_ = "walking on, watching for a deviation";
      break;
    default:
      break;
  }
  table_.event(event);
  if (event.kind != body::EventKind::trial_start) last_line_ = steps_;
}

std::vector<body::Event> result_events(const learning::LearningResult& r) {
  std::vector<body::Event> events;
  learning::Periods before(r.periods.size(), learning::kStartPeriod);
  std::size_t next = 0;
  for (std::size_t i = 0; i < r.episodes.size(); ++i) {
    const learning::Episode& episode = r.episodes[i];
    const int number = static_cast<int>(i) + 1;
    body::Event detected = learning::detection_event(number, episode.detection_deg, before);
    detected.step = episode.detection_step;
    events.push_back(std::move(detected));
    for (int k = 0; k < episode.trials && next < r.trace.size(); ++k, ++next) {
      events.push_back(learning::trial_end_event(number, r.trace[next]));
    }
    events.push_back(learning::episode_end_event(number, episode));
    before = episode.periods;
  }
  return events;
}

void print_learning_end(std::ostream& out, const experiments::RunSpec& spec,
                        const learning::LearningResult& r) {
  const robot::Morphology& morph = experiments::morphology(spec.robot);
  const learning::CompensationOptions& options = *spec.learning;
  const std::vector<std::size_t> failing = body::failing_legs(spec.faults);
  const double threshold = options.search.threshold_deg;
  const bool robust = r.mode == learning::Mode::robust;
  const bool reflex = robust && options.steering == learning::Steering::reflex;
  if (robust) {
    out << "\n";
    for (std::size_t i = 0; i < r.episodes.size(); ++i) {
      const learning::Episode& e = r.episodes[i];
      out << "episode " << i + 1 << ": detected " << degrees(e.detection_deg) << " at step "
          << e.detection_step << ", " << counted(e.trials, "trial") << ", "
          << robot::period_map_text(morph, e.periods, failing) << ", "
          << (e.held          ? "held"
              : e.interrupted ? "interrupted by a fault"
              : e.reason      ? "not held: " + stop_text(*e.reason)
                              : "stopped by the step budget")
          << "\n";
    }
    out << "windows after the last fault or episode (E = the largest of |yaw change|, |path "
           "angle|"
        << (reflex ? " and the reflex's effort x " + degrees(threshold) + " / " +
                         number(options.steering_params.max_effort)
                   : "")
        << "):\n";
    out << "  window  yaw change  path angle" << (reflex ? "  reflex effort" : "")
        << "         E\n";
    for (std::size_t i = 0; i < r.final_windows.size(); ++i) {
      const body::WindowMeasure& m = r.final_windows[i];
      out << std::setw(8) << i + 1 << std::setw(12) << degrees(m.yaw_deg) << std::setw(12)
          << degrees(m.path_deg);
      if (reflex) out << std::setw(15) << number(m.steering_effort);
      out << std::setw(11) << degrees(learning::robust_deviation(options, m)) << "\n";
    }
    if (r.final_windows.empty()) out << "  (none)\n";
  }
  if (!r.detection_step) {
    out << "no window's E exceeded the threshold " << degrees(threshold)
        << ": learning never started (E of the "
        << (robust ? "first window after the last fault" : "last window walked") << ": "
        << degrees(r.initial_deviation_deg) << ")\n";
  }

  if (r.learned_from) {
    out << "\nthe " << options.learner.name << " learner learned from " << r.learned_from->dataset
        << " (" << r.learned_from->walked << ")\n";
  }
  out << "\n" << learning::to_string(r.outcome);
  if (r.detection_step) {
    out << " after " << counted(r.trials, "trial") << ": "
        << robot::period_map_text(morph, r.periods, failing) << " (E "
        << degrees(r.initial_deviation_deg) << " detected -> " << degrees(r.final_deviation_deg)
        << " after)";
  }
  out << "\n";
  // Every number the lines above print, in their own words (docs/learning.md "What learn prints").
  if (robust) {
    out << "E: over one " << options.window_steps
        << "-step window, the largest of |yaw change|, |path angle|"
        << (reflex ? " and the steering reflex's mean swing cut scaled so that " +
                         number(options.steering_params.max_effort) + " reads as the threshold"
                   : "")
        << "; a combination is kept after " << counted(options.hold_windows, "window")
        << " in a row under " << degrees(threshold) << ".";
    if (r.detection_step) {
      out << " Detected: E of the window that started the first episode (step " << *r.detection_step
          << "); after: the largest E of the "
          << counted(static_cast<long>(r.final_windows.size()), "window")
          << " walked after the last fault or episode.";
    }
  } else {
    out << "E (paper §3): |yaw change| over one " << options.window_steps << "-step window.";
    if (r.detection_step) {
      out << " Detected: E of the window that started learning (step " << *r.detection_step
          << "); after: E of the trial window of the combination the robot walks on with.";
    }
  }
  out << "\n";

  // What happened, where the table alone does not say it.
  if (r.outcome == learning::Outcome::budget_reached) {
    out << "The trials used up the step budget of " << options.step_budget
        << " steps (--step-budget): learning stopped, and the robot walks on with the "
           "learner's answer so far.\n";
    print_best_trial(out, spec, r);
  } else if (r.outcome == learning::Outcome::not_converged &&
             r.reason == learning::StopReason::episode_cap) {
    const learning::Episode& last = r.episodes.back();
    out << "Learning gave up: the episode cap (--max-episodes " << options.max_episodes
        << ") was reached. The last episode "
        << (last.held ? std::string("held under the threshold")
                      : "ended: " + stop_text(last.reason.value_or(learning::StopReason::running)))
        << ", but the windows walked after it did not hold, and no episode was left to learn "
           "again.\n";
    print_best_trial(out, spec, r);
  } else if (r.outcome == learning::Outcome::not_converged && r.reason) {
    out << "Learning gave up: " << stop_text(*r.reason);
    if (robust && *r.reason == learning::StopReason::space_exhausted && !r.episodes.empty() &&
        r.episodes.back().trials == 0) {
      out << " and none held; a later episode could try nothing new, so none started";
    }
    out << ".\n";
    print_best_trial(out, spec, r);
  }
  if (robust && !options.learn_periods) {
    out << "Period learning was off (--no-period-learning): the steering reflex walked alone.\n";
  } else if (reflex && r.episodes.empty() && r.outcome == learning::Outcome::no_deviation) {
    out << "The steering reflex held the course: no window's E exceeded " << degrees(threshold)
        << ", so no period was learned. To see period learning: --steering off (robust mode "
           "without the reflex) or --mode paper (paper §3: yaw only, no reflex).\n";
  } else if (reflex) {
    out << "The steering reflex steered against the fault in every window: each E above is what "
           "was left with it at work (mean swing cut in the last window "
        << number(r.steering_effort)
        << "), which can be far less than the fault turns the robot without it. To see the "
           "periods learn the whole turn: --steering off, or --mode paper (paper §3).\n";
  } else if (!robust && r.outcome == learning::Outcome::no_deviation) {
    out << "The fault did not turn the robot more than " << degrees(threshold) << " in "
        << counted(options.detection_windows, "window") << " after it (--threshold sets the "
        << "threshold).\n";
  }
}

}  // namespace multicpg::apps
