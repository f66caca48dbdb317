// Learning in Python: learn() and tunnel() (`multicpg learn` and `multicpg tunnel`, their
// arguments described once in python/run_args.h), the annealing one step at a time
// (multicpg.Annealer), and experiments as `multicpg run` runs them.
#include "python/learning.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <exception>
#include <future>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/errors.h"
#include "common/interrupt.h"
#include "experiments/experiment_file.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/sweep.h"
#include "experiments/tunnel.h"
#include "learning/annealing.h"
#include "learning/choice_options.h"
#include "learning/learners.h"
#include "learning/number_options.h"
#include "python/args.h"
#include "python/run_args.h"
#include "python/typed.h"
#include "python/values.h"
#include "python/watch.h"
#include "report/film.h"
#include "robot/leg_sets.h"

namespace multicpg::python {
namespace {

using Json = nlohmann::json;

// A window's deviation E, 0..180 deg: the size of a wrapped yaw change (docs/learning.md
// "Deviation").
constexpr Limits<double> kDeviationLimits{0.0, 180.0};

// The trace of a learning run as arrays, one row per trial from trial 0 (C0, every leg at
// the start period, with the deviation that started learning, as the CLI's trace and Fig. 8
// show it): trial, periods [trials, legs], deviation_deg, accepted, and one array per detail
// of the learner (the annealing's acceptance_probability, ...; NaN where a trial has none,
// as trial 0 has).
py::dict trace_arrays(std::string_view learner, const learning::LearningResult& result,
                      std::size_t legs) {
  const std::vector<learning::TrialRecord>& trace = result.trace;
  std::vector<int> trial{0};
  std::vector<int> periods(legs, learning::kStartPeriod);
  std::vector<double> deviation{result.initial_deviation_deg};
  const auto n = static_cast<py::ssize_t>(trace.size() + 1);
  py::array_t<bool> accepted(n);
  accepted.mutable_at(0) = true;  // C0 is the accepted combination until a trial replaces it
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const learning::TrialRecord& t = trace[i];
    trial.push_back(t.trial);
    periods.insert(periods.end(), t.periods.begin(), t.periods.end());
    deviation.push_back(t.deviation_deg);
    accepted.mutable_at(static_cast<py::ssize_t>(i + 1)) = t.accepted;
  }
  py::dict out;
  out["trial"] = array(trial, {n});
  out["periods"] = array(periods, {n, static_cast<py::ssize_t>(legs)});
  out["deviation_deg"] = array(deviation, {n});
  out["accepted"] = accepted;
  for (const std::string& key : learning::detail_columns(learner, trace)) {
    std::vector<double> values{std::numeric_limits<double>::quiet_NaN()};
    for (const learning::TrialRecord& t : trace) values.push_back(learning::detail_number(t, key));
    out[py::str(key)] = array(values, {n});
  }
  return out;
}

// A model-based learner's map after its last trial (docs/learning.md "Inside the model"): the
// combinations its model gives the best chance to hold, best first, as arrays: periods
// [rows, legs], hold, keep, e_deg, e_low_deg, e_high_deg, yaw_deg, yaw_sd_deg, path_deg,
// path_sd_deg, effort_deg, effort_sd_deg and tried.
py::dict model_arrays(const std::vector<learning::Forecast>& forecasts, std::size_t legs) {
  const auto n = static_cast<py::ssize_t>(forecasts.size());
  std::vector<int> periods;
  std::vector<double> hold, keep, e, low, high, yaw, yaw_sd, path, path_sd, effort, effort_sd;
  py::array_t<bool> tried(n);
  for (std::size_t i = 0; i < forecasts.size(); ++i) {
    const learning::Forecast& f = forecasts[i];
    periods.insert(periods.end(), f.periods.begin(), f.periods.end());
    hold.push_back(f.hold);
    keep.push_back(f.keep);
    e.push_back(f.e_deg);
    low.push_back(f.e_low_deg);
    high.push_back(f.e_high_deg);
    yaw.push_back(f.yaw.mean);
    yaw_sd.push_back(f.yaw.sd);
    path.push_back(f.path.mean);
    path_sd.push_back(f.path.sd);
    effort.push_back(f.effort.mean);
    effort_sd.push_back(f.effort.sd);
    tried.mutable_at(static_cast<py::ssize_t>(i)) = f.tried;
  }
  py::dict out;
  out["periods"] = array(periods, {n, static_cast<py::ssize_t>(legs)});
  out["hold"] = array(hold, {n});
  out["keep"] = array(keep, {n});
  out["e_deg"] = array(e, {n});
  out["e_low_deg"] = array(low, {n});
  out["e_high_deg"] = array(high, {n});
  out["yaw_deg"] = array(yaw, {n});
  out["yaw_sd_deg"] = array(yaw_sd, {n});
  out["path_deg"] = array(path, {n});
  out["path_sd_deg"] = array(path_sd, {n});
  out["effort_deg"] = array(effort, {n});
  out["effort_sd_deg"] = array(effort_sd, {n});
  out["tried"] = tried;
  return out;
}

py::dict path_arrays(const sim::WalkRecord& r) {
  const auto n = static_cast<py::ssize_t>(r.rows());
  py::dict out;
  out["time"] = array(r.time, {n});
  out["x"] = array(r.x, {n});
  out["y"] = array(r.y, {n});
  out["yaw_deg"] = array(r.yaw_deg, {n});
  return out;
}

// observer: a callable told every learning trial (python/watch.h).
Params observer_params() {
  return {{"observer", py::none()}};
}

const Signature& learn_signature() {
  // Never destroyed: its Python objects must not outlive the interpreter.
  static const auto* s = new Signature("learn", {{"robot", py::str("hexapod")}},
                                       join({{{"terrain", py::none()}},
                                             fault_params(),
                                             learning_params(),
                                             {{"record", py::bool_(false)}},
                                             hardware_params(),
                                             observer_params(),
                                             progress_params()}));
  return *s;
}

py::dict learn(const Keywords& k) {
  const std::shared_ptr<Robot> robot = with_terrain(robot_arg(k["robot"]), k["terrain"]);
  const robot::Morphology& morph = robot->morph();
  const body::FaultTimeline timeline = fault_timeline(morph, k);
  experiments::RunSpec spec =
      run_spec(*robot, {}, timeline, learning_options(k, &robot->spec, timeline));
  spec.record.steps = flag(k["record"], "record");
  const std::optional<experiments::HardwareSetup> setup = hardware_setup(k, spec);
  if (setup && spec.record.steps) {
    value_error("record", "records the simulation's every step; a real robot's run has none");
  }
  Watch watch(k["progress"], "learn", 0, k["observer"], &morph);
  experiments::LearningRun run;
  {
    const py::gil_scoped_release release;
    experiments::Watchers watchers;
    watchers.observer = &watch;
    run = experiments::run_learning(*robot->model, spec, setup ? &*setup : nullptr, 0, watchers);
  }
  watch.finish();
  Json json = experiments::learn_json(spec, run.result);
  if (setup) json["hardware"] = run.hardware;
  py::dict out = to_python(json);
  out["trace_arrays"] = trace_arrays(spec.learning->learner.name, run.result, morph.size());
  if (!run.result.forecasts.empty())
    out["model_arrays"] = model_arrays(run.result.forecasts, morph.size());
  if (spec.record.steps) out["path"] = path_arrays(run.record);
  return out;
}

// The learning arguments alone, for multicpg.env's CompensationEnv: the same description, the
// same checks.
const Signature& learning_signature() {
  static const auto* s = new Signature("CompensationEnv", {}, learning_params());
  return *s;
}

py::dict checked_learning_options(const Keywords& k) {
  learning::CompensationOptions o = learning_options(k, nullptr);  // read by the tables' fields
  py::dict out;
  for (const learning::NameOption& option : learning::kLearningNames) {
    out[py::str(learning::keyword(option.flag))] = std::string(option.get(o));
  }
  // None: the run's default, which depends on the robot (learning/default_learner.h).
  out["learner"] = k["learner"].is_none() ? py::object(py::none()) : py::str(o.learner.name);
  out["learner_options"] = to_python(o.learner.options);
  add_number_options(out, o);
  for (const learning::SwitchOption& option : learning::kLearningSwitches) {
    out[py::str(learning::keyword(option.flag))] = option.field(o);
  }
  const std::optional<double> beta = learning::annealing_beta(o.learner);
  out["beta"] = beta ? py::object(py::float_(*beta)) : py::none();
  out["seed"] = o.seed;
  out["given"] = k.given_of(learning_params());
  return out;
}

const Signature& tunnel_signature() {
  static const auto* s = new Signature("tunnel", {},
                                       join({{{"robot", py::str("hexapod")}},
                                             fault_params(),
                                             {{"periods", py::none()},
                                              {"learn", py::bool_(false)},
                                              {"max_steps", py::int_(experiments::kTunnelMaxSteps)},
                                              {"video", py::none()}},
                                             learning_params(),
                                             sim_params(),
                                             hardware_params(),
                                             observer_params(),
                                             progress_params(),
                                             {{"scale_tunnel", py::bool_(false)}}}));
  return *s;
}

py::dict tunnel(const Keywords& k) {
  const bool learns = flag(k["learn"], "learn");
  if (learns && !k["periods"].is_none()) {
    value_error("periods", "periods and learn=True exclude each other: learning finds the periods");
  }
  if (!learns) {
    const std::vector<std::string> given = k.given_of(learning_params());
    if (!given.empty()) {
      value_error(given.front(), "is a learning argument: it needs learn=True");
    }
  }
  // The robot's kind or file; the tunnel's arguments set its simulation.
  const std::shared_ptr<Robot> base = robot_arg(k["robot"]);
  experiments::RobotSpec walked = base->spec;
  walked.sim = sim_options(k, false);
  const std::shared_ptr<Robot> robot = robot_of(std::move(walked));
  const robot::Morphology& morph = robot->morph();
  const long max_steps = whole(k["max_steps"], "max_steps", body::kRunStepsLimits);
  std::string video;
  if (!k["video"].is_none()) video = path(k["video"], "video");
  if (!video.empty() &&
      named("video", [&] { return report::film_format(video); }) != report::FilmFormat::video) {
    value_error("video", "must name an .mp4 file");
  }
  body::StartSpec start;
  if (!k["periods"].is_none()) start.periods = periods(morph, k["periods"], "periods");
  const body::FaultTimeline faults = fault_timeline(morph, k);
  std::optional<learning::CompensationOptions> options;
  if (learns) options = learning_options(k, &robot->spec, faults);
  experiments::RunSpec spec = run_spec(*robot, start, faults, options);
  const std::optional<experiments::HardwareSetup> setup = hardware_setup(k, spec);
  if (setup && !video.empty()) {
    value_error("video", "films the simulated tunnel; a real robot's run has none");
  }
  if (setup && flag(k["scale_tunnel"], "scale_tunnel")) {
    value_error("scale_tunnel", "scales the simulated tunnel; not with hardware");
  }
  std::optional<experiments::TunnelScale> scale;
  if (flag(k["scale_tunnel"], "scale_tunnel")) {
    try {
      scale = experiments::scale_tunnel(spec);
    } catch (const OptionError& e) {
      value_error("scale_tunnel", e.key() + " " + e.what());
    }
  }
  Watch watch(k["progress"], "tunnel", 0, k["observer"], &morph);
  experiments::TunnelOutcome out;
  {
    const py::gil_scoped_release release;
    const sim::SimModel corridor = experiments::tunnel_model(spec);
    std::optional<report::Film> film;
    std::optional<report::FilmObserver> film_observer;
    if (!video.empty()) {
      report::FilmSpec film_spec;
      film_spec.out = video;
      film.emplace(corridor, film_spec);
      std::ostringstream label;
      label << std::fixed << std::setprecision(1) << "tunnel " << corridor.scene.tunnel_length
            << " m x " << corridor.scene.tunnel_width << " m";
      film_observer.emplace(*film, label.str());
    }
    sim::Observers walk({film_observer ? &*film_observer : nullptr, &watch});
    out = experiments::run_tunnel(spec, corridor, max_steps, &walk, &watch,
                                  setup ? &*setup : nullptr);
    if (film) film->finish();
  }
  watch.finish();
  py::dict result = to_python(experiments::tunnel_json(spec, out, scale));
  if (out.learned) {
    result["trace_arrays"] = trace_arrays(spec.learning->learner.name, *out.learned, morph.size());
    if (!out.learned->forecasts.empty())
      result["model_arrays"] = model_arrays(out.learned->forecasts, morph.size());
  }
  if (!setup) result["path"] = path_arrays(out.run.record);
  return result;
}

// The annealing search of learning/annealing.h, one call per step, for agents written in
// Python: the same draws as learning::compensate, so the same seed gives the same trace.
class Annealer {
 public:
  Annealer(py::handle robot_value, py::handle periods_value, py::handle disabled_value,
           py::handle e_ref_value, py::handle seed_value, py::handle beta, py::handle threshold,
           py::handle max_trials)
      : robot_(robot_arg(robot_value)) {
    const robot::Morphology& morph = robot_->morph();
    const std::vector<int> start = periods(morph, periods_value, "periods");
    const robot::LegSet disabled = legs(morph, disabled_value, "disabled");
    if (disabled.size() == morph.size()) {
      value_error("disabled", "every leg of the " + morph.name + " is disabled: none can learn");
    }
    const double e_ref = real(e_ref_value, "e_ref", kDeviationLimits);
    const std::uint64_t draws = seed(seed_value, "seed");
    params_.beta = real(beta, "beta", learning::kBetaLimits);
    params_.threshold_deg = real(threshold, "threshold", learning::kThresholdLimits);
    params_.max_trials = whole(max_trials, "max_trials", learning::kMaxTrialsLimits);
    state_ = named("periods", [&] {
      return learning::start_annealing(params_, start, disabled, e_ref, draws);
    });
  }

  std::optional<std::vector<int>> propose() {
    if (state_.stop != learning::StopReason::running) return std::nullopt;
    if (state_.pending) {
      throw py::value_error(
          "propose(): the proposed combination has not been decided (call decide first)");
    }
    const std::optional<learning::Candidate> c = learning::propose(params_, state_);
    if (!c) return std::nullopt;
    return c->periods;
  }

  py::dict decide(FloatArg deviation) {
    const double e = real(deviation, "deviation_deg", kDeviationLimits);
    if (!state_.pending) {
      throw py::value_error("decide(): no proposed combination (call propose first)");
    }
    const learning::Decision d = learning::decide(params_, state_, e);
    return py::dict(py::arg("accepted") = d.accepted, py::arg("probability") = d.probability,
                    py::arg("stop") = std::string(learning::to_string(d.stop)));
  }

  std::string stop() const { return std::string(learning::to_string(state_.stop)); }
  int trials() const { return state_.trials; }
  std::vector<int> accepted() const { return state_.accepted; }
  double e_ref() const { return state_.e_ref; }
  std::vector<std::string> working() const {
    std::vector<std::string> out;
    for (std::size_t leg : state_.working) out.push_back(robot_->morph().legs[leg].name);
    return out;
  }
  const std::shared_ptr<Robot>& robot() const { return robot_; }
  std::string repr() const {
    const robot::Morphology& morph = robot_->morph();
    std::string accepted;
    // A fixed (disabled) leg's period marked x, as the CLI's trace marks it.
    for (std::size_t leg = 0; leg < morph.size(); ++leg) {
      const bool working =
          std::find(state_.working.begin(), state_.working.end(), leg) != state_.working.end();
      accepted += " " + morph.legs[leg].name + "=" + std::to_string(state_.accepted[leg]) +
                  (working ? "" : "x");
    }
    return "<multicpg.Annealer of " + robot_repr(*robot_) + ": " + std::to_string(state_.trials) +
           " trials, " + std::string(learning::to_string(state_.stop)) + ", accepted" + accepted +
           ">";
  }
  py::list trace() const {
    py::list out;
    for (const learning::AnnealingTrial& t : state_.trace) {
      out.append(
          py::dict(py::arg("trial") = t.trial, py::arg("periods") = t.periods,
                   py::arg("deviation_deg") = t.deviation_deg, py::arg("accepted") = t.accepted,
                   py::arg("acceptance_probability") = t.acceptance_probability,
                   py::arg("legs_changed") = t.legs_changed, py::arg("redraws") = t.redraws));
    }
    return out;
  }

 private:
  std::shared_ptr<Robot> robot_;
  learning::AnnealingParams params_;
  learning::AnnealingState state_;
};

// Runs an experiment as `multicpg run` does: an experiment file, or its document as JSON text,
// into `out` on `jobs` threads (None: every core); the Python side reads out/runs.csv. The
// sweep runs on a thread of its own while this one looks at Python's signals every
// kPollInterval: Ctrl-C asks the sweep to stop as the CLI's SIGINT does (common/interrupt.h),
// and once it has stopped raises KeyboardInterrupt; the runs finished in `out` stay, so the
// same call resumes.
void run_experiment(py::handle source_value, py::handle is_document, py::handle jobs,
                    py::handle out) {
  const bool document = flag(is_document, "is_document");
  const std::string source =
      document ? text(source_value, "file_or_dict") : path(source_value, "file_or_dict");
  experiments::SweepRunOptions options;
  options.out = path(out, "out");
  if (!jobs.is_none()) options.jobs = whole(jobs, "jobs", experiments::kJobsLimits);
  options.progress = false;
  const experiments::Sweep sweep = document ? experiments::resolve_sweep(Json::parse(source))
                                            : experiments::load_experiment_file(source);
  if (!sweep.landscapes.empty()) {
    throw py::value_error(
        "file_or_dict: a landscape has no tidy table; run it with `multicpg run`");
  }
  std::future<void> done;
  {
    const py::gil_scoped_release release;
    done = std::async(std::launch::async, [&] { experiments::run_sweep(sweep, options); });
  }
  bool interrupted = false;
  while (true) {
    std::future_status status;
    {
      const py::gil_scoped_release release;
      status = done.wait_for(kPollInterval);
    }
    if (status == std::future_status::ready) break;
    if (!interrupted && PyErr_CheckSignals() != 0) {
      interrupted = true;  // the error stays set until the sweep has stopped
      request_interrupt(SIGINT);
    }
  }
  if (interrupted) {
    clear_interrupt();
    try {
      done.get();
    } catch (const Interrupted&) {  // what was asked for
    } catch (...) {
      // The Python error set above is what the caller sees.
    }
    throw py::error_already_set();
  }
  const py::gil_scoped_release release;
  done.get();
}

}  // namespace

void register_learning(py::module_& m) {
  namespace mp = multicpg::python;
  using py::arg;
  static const std::string learn_doc =
      learn_signature().text("learn", "dict") +
      "\n\n"
      "`multicpg learn`: legs fail and the robot learns periods that walk straight again.\n"
      "robot: a Robot, a robot name or a robot file; terrain: as for Simulation (None: the\n"
      "robot's). disable/disable_at/faults/recoveries as for Simulation. mode: 'robust' (the\n"
      "CLI's default) or 'paper' (paper §3); steering ('reflex' or 'off'), hold_windows,\n"
      "monitor_windows and period_learning are robust-mode arguments. learner: which learner\n"
      "searches (" +
      learning::learner_names() +
      "; None: the prior in robust mode where the\n"
      "robot's dataset is, else the annealing; docs/learning.md \"Which learner a run uses\"), "
      "with\n"
      "learner_options, a dict of its own options (`--learner-option KEY=VALUE`). beta\n"
      "(0..100), threshold (deg, 0.001..180), window (steps), settle (steps; None: the mode's),\n"
      "max_trials (1..100000), max_episodes (robust mode's episodes, 1..1000), step_budget\n"
      "(controller steps its trials may spend over all episodes, 1..100000000), tell_fault\n"
      "(False: the learner is told nothing of the fault and searches every leg's period, the\n"
      "CLI's --no-tell-fault), seed (0..4294967295). hardware: a hardware file (FILE.toml,\n"
      "docs/hardware.md): the run drives that robot over its serial bus in real time;\n"
      "lock_step=True: no pacing, for a rehearsal against `multicpg emulate` (never on a real\n"
      "robot). Returns the dict of `learn --json`, plus\n"
      "trace_arrays (trial from 0, periods [trials,legs], deviation_deg, accepted, the\n"
      "learner's details: a model-based learner's forecast of each trial, predicted_e_deg ...),\n"
      "for a model-based learner model_arrays (its map after the last trial: periods\n"
      "[rows,legs], hold, e_deg, e_low_deg, e_high_deg, yaw/path/effort _deg and _sd_deg,\n"
      "tried) and, with record=True, path (time, x, y, yaw_deg). observer(trial)\n"
      "is called after every trial with episode, trial, step, periods, deviation_deg and\n"
      "accepted. Releases the GIL while it walks; Ctrl-C raises KeyboardInterrupt within half a\n"
      "second. progress: a bar once the run has taken half a second (False: none; a callable:\n"
      "called with a dict of stage, steps, total, trials, deviation_deg, finished instead).";
  static const std::string tunnel_doc =
      tunnel_signature().text("tunnel", "dict") +
      "\n\n"
      "`multicpg tunnel`: the robot (a Robot's kind or robot file, a name or FILE.toml; its\n"
      "simulation set by the arguments here) walks the 3.0 m x 1.2 m corridor of paper §5 with\n"
      "the `disable`d legs and other `faults` (multicpg.Fault) from the start, on `terrain`,\n"
      "with the body `model` ('paper-sim' or 'real') and `body` parameters as for Robot, and\n"
      "given periods (as for Simulation; None: every leg 4), or (learn=True) after learning in\n"
      "the open field (learning arguments as for learn(), refused without learn=True).\n"
      "max_steps: 1..100000000. Returns the dict of `tunnel --json` plus path (time, x, y,\n"
      "yaw_deg) and, after learning, trace_arrays (and model_arrays, as learn's). video='run.mp4'\n"
      "films the tunnel walk; control_dt, physics_dt and servo_gain as for Robot; hardware,\n"
      "lock_step, observer and progress as for learn(). scale_tunnel=True scales the tunnel to\n"
      "the robot's width (`tunnel --scale-tunnel`).";
  static const std::string options_doc =
      learning_signature().text("_learning_options", "dict") +
      "\n\nThe learning arguments of learn() checked as learn() checks them (multicpg.env).";
  {
    const OwnSignatures own;
    m.def(
        "learn",
        [](const py::args& args, const py::kwargs& kwargs) {
          return mp::learn(mp::learn_signature().read(args, kwargs));
        },
        learn_doc.c_str());
    m.def(
        "tunnel",
        [](const py::args& args, const py::kwargs& kwargs) {
          return mp::tunnel(mp::tunnel_signature().read(args, kwargs));
        },
        tunnel_doc.c_str());
    m.def(
        "_learning_options",
        [](const py::args& args, const py::kwargs& kwargs) {
          return mp::checked_learning_options(mp::learning_signature().read(args, kwargs));
        },
        options_doc.c_str());
  }

  m.def("_run_experiment", &mp::run_experiment, arg("file_or_dict"), arg("is_document"),
        arg("jobs"), arg("out"),
        "Runs an experiment file or document (JSON text) into `out` (multicpg.experiment).");

  py::class_<mp::Annealer>(
      m, "Annealer",
      "The simulated annealing of paper §3 (Table 2), one call per step, with the draws of\n"
      "`multicpg learn --mode paper`: start from C0 = periods (as for Simulation; each working\n"
      "leg's in PERIOD_SET) measured at e_ref (deg, 0..180) with the `disabled` legs kept, then\n"
      "propose() a combination, walk it, decide(deviation). robot: a Robot, a robot name or a\n"
      "robot file; seed, beta, threshold and max_trials as for learn().")
      .def(py::init([](mp::RobotArg robot, mp::PeriodsArg periods, mp::LegsArg disabled,
                       mp::FloatArg e_ref, mp::IntArg seed, mp::FloatArg beta,
                       mp::FloatArg threshold, mp::IntArg max_trials) {
             return std::make_unique<mp::Annealer>(robot, periods, disabled, e_ref, seed, beta,
                                                   threshold, max_trials);
           }),
           arg("robot"), arg("periods"), arg("disabled"), arg("e_ref"), py::kw_only(),
           arg("seed") = 1, arg("beta") = learning::kDefaultBeta,
           arg("threshold") = learning::kDefaultThresholdDeg,
           arg("max_trials") = learning::kDefaultMaxTrials)
      .def("propose", &mp::Annealer::propose,
           "The next combination (one period per leg) to try, or None when the search is over.")
      .def("decide", &mp::Annealer::decide, arg("deviation_deg"),
           "Keeps or rejects the proposed combination given its measured deviation E (deg);\n"
           "returns accepted, probability and stop (running, below threshold, trial cap, ...).")
      .def_property_readonly("stop", &mp::Annealer::stop,
                             "running, below threshold, trial cap or search space exhausted")
      .def_property_readonly("trials", &mp::Annealer::trials, "trials decided")
      .def_property_readonly("accepted", &mp::Annealer::accepted, "the accepted combination C(n)")
      .def_property_readonly("e_ref", &mp::Annealer::e_ref, "its deviation")
      .def_property_readonly("working", &mp::Annealer::working, "legs whose period may change")
      .def_property_readonly("robot", &mp::Annealer::robot, "the Robot it learns for")
      .def_property_readonly("trace", &mp::Annealer::trace, "one dict per decided trial")
      .def("__repr__", &mp::Annealer::repr);
}

}  // namespace multicpg::python
