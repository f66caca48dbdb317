// multicpg.Learner: any registered learner driven from Python one trial at a time
// (learning/ask_tell.h), for a user's own simulator, robot or function of the periods.
#include "python/ask_tell.h"

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "learning/ask_tell.h"
#include "learning/compensation.h"
#include "learning/default_learner.h"
#include "neural/cpg.h"
#include "python/args.h"
#include "python/robots.h"
#include "python/typed.h"
#include "python/values.h"

namespace multicpg::python {
namespace {

// A window's E, 0..180 deg (docs/learning.md "Deviation"), and its parts.
constexpr Limits<double> kDeviationLimits{0.0, 180.0};
constexpr Limits<double> kAngleLimits{-180.0, 180.0};
// The reflex's mean swing cut, a share of a side's swing (learning/steering.h).
constexpr Limits<double> kEffortLimits{0.0, 1.0};

// One window: (yaw_deg, path_deg), (yaw_deg, path_deg, steering_effort), or a dict with those
// keys (what Simulation.walk_window returns).
body::WindowMeasure window_of(py::handle value, const std::string& name) {
  body::WindowMeasure w;
  if (PyDict_Check(value.ptr())) {
    const auto d = py::reinterpret_borrow<py::dict>(value);
    for (const char* key : {"yaw_deg", "path_deg"}) {
      if (!d.contains(key)) value_error(name, std::string("has no '") + key + "'");
    }
    w.yaw_deg = real(d["yaw_deg"], name + "['yaw_deg']", kAngleLimits);
    w.path_deg = real(d["path_deg"], name + "['path_deg']", kAngleLimits);
    if (d.contains("steering_effort")) {
      w.steering_effort = real(d["steering_effort"], name + "['steering_effort']", kEffortLimits);
    }
    return w;
  }
  if (!py::isinstance<py::sequence>(value) || PyUnicode_Check(value.ptr())) {
    type_error(name, "(yaw_deg, path_deg[, steering_effort]) or a dict of them", value);
  }
  const auto items = py::reinterpret_borrow<py::sequence>(value);
  if (items.size() != 2 && items.size() != 3) {
    value_error(name, "must be (yaw_deg, path_deg) or (yaw_deg, path_deg, steering_effort)");
  }
  w.yaw_deg = real(items[0], name + "[0]", kAngleLimits);
  w.path_deg = real(items[1], name + "[1]", kAngleLimits);
  if (items.size() == 3) w.steering_effort = real(items[2], name + "[2]", kEffortLimits);
  return w;
}

std::vector<body::WindowMeasure> windows_of(py::handle value, const std::string& name) {
  if (!py::isinstance<py::sequence>(value) || PyUnicode_Check(value.ptr())) {
    type_error(name, "a list of windows", value);
  }
  std::vector<body::WindowMeasure> out;
  const auto items = py::reinterpret_borrow<py::sequence>(value);
  for (std::size_t i = 0; i < items.size(); ++i) {
    out.push_back(window_of(items[i], name + "[" + std::to_string(i) + "]"));
  }
  if (out.empty()) value_error(name, "is empty: a trial walks one window at least");
  return out;
}

// A run of `mode` and `steering` (as learn() takes them) with `threshold`: what its criterion
// (learning::criterion, the one judge of a window, the learners' and the CLI's) is made from.
learning::CompensationOptions judged_run(py::handle mode_value, py::handle steering_value,
                                         py::handle threshold) {
  learning::CompensationOptions run;
  const std::string mode = text(mode_value, "mode");
  run.mode = named("mode", [&] { return learning::parse_mode(mode); });
  const std::string steering = text(steering_value, "steering");
  run.steering = named("steering", [&] { return learning::parse_steering(steering); });
  run.search.threshold_deg = real(threshold, "threshold", learning::kThresholdLimits);
  return run;
}

class Learner {
 public:
  Learner(py::handle name, py::handle options, py::handle seed_value, py::handle robot_value,
          py::handle failed, py::handle start, py::handle windows, py::handle deviation,
          py::handle mode_value, py::handle steering_value, py::handle period_set,
          py::handle threshold, py::handle max_trials, py::handle hold_windows)
      : robot_(robot_arg(robot_value)) {
    const robot::Morphology& morph = robot_->morph();
    learning::AskTellSetup s;
    if (!options.is_none()) {
      if (!PyDict_Check(options.ptr())) {
        type_error("options", "a dict of the learner's options", options);
      }
      s.learner.options = to_json(options, "options");
    }
    s.seed = seed(seed_value, "seed");
    s.robot = morph.kind;
    // None: told nothing about the fault; else the legs it is told failed.
    s.told = failed.is_none() ? learning::ToldFault::nothing()
                              : learning::ToldFault::legs(legs(morph, failed, "failed"));
    s.start = periods(morph, start, "periods");
    // The criterion of the run it stands for (learning/compensation.h): mode and steering as
    // learn() takes them.
    learning::CompensationOptions run = judged_run(mode_value, steering_value, threshold);
    // Robust mode's trial length: a model-based learner weighs by it (docs/learning.md "Holding
    // on after the trial").
    run.hold_windows = whole(hold_windows, "hold_windows", learning::kHoldWindowsLimits);
    if (!period_set.is_none()) {
      s.search.period_set.clear();
      for (const py::handle p : py::iter(period_set)) {
        // The CPG's periods (neural/); validate(SearchBounds) refuses one that gives no gait.
        s.search.period_set.push_back(
            whole(p, "period_set", Limits<int>{neural::kMinPeriod, neural::kMaxPeriod}));
      }
    }
    s.search.threshold_deg = run.search.threshold_deg;
    s.search.max_trials = whole(max_trials, "max_trials", learning::kMaxTrialsLimits);
    run.search = s.search;
    run.tell_fault = s.told.told();
    s.criterion = learning::criterion(run);
    // None: the default of the run it stands for (learning/default_learner.h), as learn()'s.
    s.learner.name =
        name.is_none()
            ? learning::default_learner({run, morph.kind, robot_->spec.file != nullptr, false, {}})
                  .name
            : text(name, "learner");
    if (!windows.is_none()) s.start_windows = windows_of(windows, "windows");
    if (!deviation.is_none()) {
      if (!windows.is_none()) value_error("deviation_deg", "give C0's windows or its E, not both");
      s.start_deviation_deg = real(deviation, "deviation_deg", kDeviationLimits);
    }
    if (windows.is_none() && deviation.is_none()) {
      value_error("windows", "C0 needs what it measured: windows=[...] or deviation_deg=E");
    }
    learner_ = std::make_unique<learning::AskTell>(s);
  }

  py::object ask() {
    std::optional<learning::Periods> next;
    try {
      next = learner_->ask();
    } catch (const std::logic_error& e) {
      throw py::value_error(e.what());
    }
    if (!next) return py::none();
    return periods_dict(*next);
  }

  py::dict tell(py::handle windows, py::handle deviation) {
    if (windows.is_none() == deviation.is_none()) {
      value_error("tell", "takes the trial's windows=[...] or its deviation_deg=E (one of them)");
    }
    try {
      const learning::TrialRecord t =
          windows.is_none() ? learner_->tell(real(deviation, "deviation_deg", kDeviationLimits))
                            : learner_->tell(windows_of(windows, "windows"));
      return record(t);
    } catch (const std::logic_error& e) {
      throw py::value_error(e.what());
    }
  }

  void next_episode(py::handle start, py::handle windows, py::handle deviation) {
    if (windows.is_none() == deviation.is_none()) {
      value_error("next_episode",
                  "takes what C0 measured: windows=[...] or deviation_deg=E (one of them)");
    }
    const learning::Periods p = periods(robot_->morph(), start, "periods");
    try {
      if (windows.is_none()) {
        learner_->next_episode(p, real(deviation, "deviation_deg", kDeviationLimits));
      } else {
        learner_->next_episode(p, windows_of(windows, "windows"));
      }
    } catch (const std::logic_error& e) {
      throw py::value_error(e.what());
    }
  }
  void forget() { learner_->forget(); }
  int episode() const { return learner_->episode(); }

  bool done() const { return learner_->done(); }
  std::string reason() const { return std::string(learning::to_string(learner_->reason())); }
  py::dict answer() const {
    const learning::Answer a = learner_->answer();
    return py::dict(py::arg("periods") = periods_dict(a.periods),
                    py::arg("deviation_deg") = a.deviation_deg);
  }
  int trials() const { return static_cast<int>(learner_->trace().size()); }
  py::list trace() const {
    py::list out;
    for (const learning::TrialRecord& t : learner_->trace()) out.append(record(t));
    return out;
  }
  std::vector<std::string> working() const {
    std::vector<std::string> out;
    for (std::size_t leg : learner_->setup().working())
      out.push_back(robot_->morph().legs[leg].name);
    return out;
  }
  std::string name() const { return learner_->learner().name; }
  py::object options() const { return to_python(learner_->learner().options); }
  py::object dataset() const {
    const learning::LearnerData& d = learner_->data();
    if (!d.landscapes) return py::none();
    return py::str(d.source.string());
  }
  std::string repr() const {
    return "<multicpg.Learner " + name() + " of " + robot_repr(*robot_) + ": " +
           std::to_string(trials()) + " trials, " + reason() + ">";
  }

 private:
  // {leg: period} in leg order.
  py::dict periods_dict(const learning::Periods& p) const {
    py::dict out;
    const robot::Morphology& morph = robot_->morph();
    for (std::size_t leg = 0; leg < morph.size(); ++leg)
      out[py::str(morph.legs[leg].name)] = p[leg];
    return out;
  }
  py::dict record(const learning::TrialRecord& t) const {
    py::dict out;
    out["trial"] = t.trial;
    out["periods"] = periods_dict(t.periods);
    out["deviation_deg"] = t.deviation_deg;
    out["accepted"] = t.accepted;
    for (const auto& [key, value] : t.details.items()) out[py::str(key)] = to_python(value);
    return out;
  }

  std::shared_ptr<Robot> robot_;
  std::unique_ptr<learning::AskTell> learner_;
};

}  // namespace

void register_ask_tell(py::module_& m) {
  using py::arg;
  static const std::string doc =
      "A learner asked for the next periods and told what each trial measured, by whoever\n"
      "walks the trials (another simulator, a robot, a function of the periods; docs/python.md\n"
      "\"Ask and tell\"). learner: a learner's name (" +
      learning::learner_names() +
      ") or None: the\n"
      "default of the run it stands for, as learn()'s; options: a dict of its own\n"
      "options (as learn()'s learner_options), seed: as learn()'s. robot: its leg layout (a\n"
      "Robot, 'hexapod', 'quadruped' or a robot file). failed: the legs it is told failed\n"
      "(never picked), or None: told nothing, it searches every leg's period. periods: C0,\n"
      "measured as windows=[(yaw_deg, path_deg[, steering_effort]), ...] or deviation_deg=E.\n"
      "mode, steering and hold_windows (robust mode: the windows a trial walks, each of which\n"
      "must hold): how the run it stands for judges a trial (as learn()'s); period_set\n"
      "(None: PERIOD_SET), threshold (deg) and max_trials bound the search. With the same\n"
      "seed and the windows our own simulation walks it gives the trials of learn().";
  m.def(
      "window_error",
      [](AnyArg window, StrArg mode, StrArg steering, FloatArg threshold) {
        return learning::criterion(judged_run(mode, steering, threshold))
            .error(window_of(window, "window"));
      },
      arg("window"), py::kw_only(),
      arg("mode") = std::string(learning::to_string(learning::Mode::robust)),
      arg("steering") = std::string(learning::to_string(learning::Steering::reflex)),
      arg("threshold") = learning::kDefaultThresholdDeg,
      "E of one window (deg) as a run of that mode and steering judges it (docs/learning.md\n"
      "\"Deviation\"): paper mode |yaw change|; robust mode the worst of |yaw change|, |path\n"
      "angle| and, with the reflex, its effort read so that the most it may ask reads as the\n"
      "threshold. window: (yaw_deg, path_deg[, steering_effort]) or a dict of them (what\n"
      "Simulation.walk_window returns).");
  py::class_<Learner>(m, "Learner", doc.c_str())
      .def(py::init([](OptionalStrArg learner, AnyArg options, IntArg seed, RobotArg robot,
                       LegsArg failed, PeriodsArg periods, AnyArg windows,
                       OptionalFloatArg deviation_deg, StrArg mode, StrArg steering,
                       AnyArg period_set, FloatArg threshold, IntArg max_trials,
                       IntArg hold_windows) {
             return std::make_unique<Learner>(learner, options, seed, robot, failed, periods,
                                              windows, deviation_deg, mode, steering, period_set,
                                              threshold, max_trials, hold_windows);
           }),
           arg("learner") = py::none(), py::kw_only(), arg("options") = py::none(), arg("seed") = 1,
           arg("robot") = "hexapod", arg("failed") = py::none(),
           arg("periods") = learning::kStartPeriod, arg("windows") = py::none(),
           arg("deviation_deg") = py::none(),
           arg("mode") = std::string(learning::to_string(learning::Mode::robust)),
           arg("steering") = std::string(learning::to_string(learning::Steering::reflex)),
           arg("period_set") = py::none(), arg("threshold") = learning::kDefaultThresholdDeg,
           arg("max_trials") = learning::kDefaultMaxTrials,
           arg("hold_windows") = learning::kDefaultHoldWindows)
      .def("ask", &Learner::ask,
           "The next periods to walk, {leg: period} in leg order, or None when it is done.")
      .def(
          "tell",
          [](Learner& l, AnyArg windows, OptionalFloatArg deviation_deg) {
            return l.tell(windows, deviation_deg);
          },
          py::kw_only(), arg("windows") = py::none(), arg("deviation_deg") = py::none(),
          "What the trial of the asked periods measured: its windows [(yaw_deg, path_deg[,\n"
          "steering_effort]), ...] (E is their worst, judged as the run judges), or its E\n"
          "(deviation_deg). Returns the trial's record: trial, periods, deviation_deg,\n"
          "accepted and the learner's details.")
      .def(
          "next_episode",
          [](Learner& l, PeriodsArg periods, AnyArg windows, OptionalFloatArg deviation_deg) {
            l.next_episode(periods, windows, deviation_deg);
          },
          py::kw_only(), arg("periods"), arg("windows") = py::none(),
          arg("deviation_deg") = py::none(),
          "Starts the next episode, as robust mode's monitoring does when the combination\n"
          "walked on deviates: a new learner from C0 = periods, measured as windows=[...] or\n"
          "deviation_deg=E, drawing from seed + the episodes before it and told every trial\n"
          "since the last forget(); trials are numbered from 1 again, the trace goes on.")
      .def("forget", &Learner::forget,
           "The trials told so far no longer describe the robot (a fault came): the next\n"
           "episode is told none of them, as a run forgets.")
      .def_property_readonly("episode", &Learner::episode, "the episode asked now, from 1")
      .def_property_readonly("done", &Learner::done, "whether it wants no more trials")
      .def_property_readonly("reason", &Learner::reason,
                             "running, below threshold, trial cap or search space exhausted")
      .def_property_readonly("answer", &Learner::answer,
                             "the combination it ends with: periods and deviation_deg")
      .def_property_readonly("trials", &Learner::trials, "trials told")
      .def_property_readonly("trace", &Learner::trace, "one record per trial told")
      .def_property_readonly("working", &Learner::working, "legs whose period it may change")
      .def_property_readonly("name", &Learner::name, "the learner's name")
      .def_property_readonly("options", &Learner::options, "its options, every default filled")
      .def_property_readonly("dataset", &Learner::dataset,
                             "the dataset it learned from (the prior's), or None")
      .def("__repr__", &Learner::repr);
}

}  // namespace multicpg::python
