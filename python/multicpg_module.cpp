// The Python API (issue 11): robots, simulations stepped through sim::Stepper, learning, the
// tunnel, rendering and films, and the annealing steps. Arguments are parsed by the CLI's own
// parsers (apps/), so a bad argument raises ValueError with the CLI's message; results are the
// CLI's JSON as Python objects. Long runs release the GIL, so Python threads run in parallel.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/limits.h"
#include "experiments/experiment_file.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/run_spec.h"
#include "experiments/sweep.h"
#include "experiments/tunnel.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "report/film.h"
#include "report/render.h"
#include "robot/leg_sets.h"
#include "sim/fault_spec.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace py = pybind11;

namespace multicpg::python {
namespace {

// nlohmann::json -> the Python objects json.loads would give.
py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const nlohmann::json& item : j) out.append(to_python(item));
      return out;
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, value] : j.items()) out[py::str(key)] = to_python(value);
      return out;
    }
    default:
      return py::none();
  }
}

template <typename T>
py::array_t<T> array(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// A leg list given as "R1,R3" or ["R1", "R3"]: the CLI's text form.
std::string leg_text(const py::object& legs) {
  if (legs.is_none()) return {};
  if (py::isinstance<py::str>(legs)) return legs.cast<std::string>();
  std::string text;
  for (const py::handle item : legs) {
    if (!text.empty()) text += ',';
    text += py::str(item).cast<std::string>();
  }
  return text;
}

// Periods given as 4, "R1=5,R2=4" or one number per leg.
std::vector<int> parse_periods(const robot::Morphology& morph, const py::object& periods) {
  if (py::isinstance<py::int_>(periods) || py::isinstance<py::str>(periods)) {
    return robot::parse_period_map(morph, py::str(periods).cast<std::string>(),
                                   robot::kDefaultPeriod);
  }
  const auto list = periods.cast<std::vector<int>>();
  if (list.size() != morph.size()) {
    throw BadInput("expected " + std::to_string(morph.size()) + " periods, got " +
                   std::to_string(list.size()));
  }
  for (int p : list) {
    if (!robot::is_gait_period(p)) {
      throw BadInput("period " + std::to_string(p) +
                     " gives no gait (allowed: " + robot::gait_periods_text() + ")");
    }
  }
  return list;
}

// The Python argument that sets a RunSpec key, for messages.
std::string argument_of(const std::string& key) {
  if (key == "start.periods") return "periods";
  if (key == "start.warmup") return "warmup";
  if (key == "faults") return "disable/faults/recoveries";
  if (key.rfind("sim.", 0) == 0) return key.substr(4);
  if (key == "learning.annealing.threshold_deg") return "threshold";
  if (key == "learning.window_steps") return "window";
  if (key == "learning.settle_steps") return "settle";
  return key.substr(key.rfind('.') + 1);
}

// A run described by Python's arguments, checked whole (experiments::validate); a bad value is a
// ValueError naming its argument.
struct RunArgs {
  py::object periods = py::int_(robot::kDefaultPeriod);
  py::object disable = py::none();
  long disable_at = 0;
  std::vector<std::string> faults;
  std::vector<std::string> recoveries;
  long warmup = sim::kControllerWarmup;
};

experiments::RunSpec run_spec(robot::RobotKind kind, const sim::SimOptions& sim_options,
                              const RunArgs& a,
                              std::optional<learning::CompensationOptions> learning) {
  experiments::RunSpec spec;
  spec.robot = kind;
  spec.sim = sim_options;
  const robot::Morphology& morph = experiments::morphology(spec);
  // Each argument parsed with its name in the message.
  const auto named = [](const char* argument, const auto& parse) {
    try {
      return parse();
    } catch (const BadInput& e) {
      throw BadInput(std::string(argument) + ": " + e.what());
    }
  };
  spec.faults = sim::fail_at(
      named("disable", [&] { return robot::parse_leg_set(morph, leg_text(a.disable)); }),
      a.disable_at);
  for (const std::string& f : a.faults) {
    spec.faults.push_back(named("faults", [&] { return sim::parse_fault(morph, f, false); }));
  }
  for (const std::string& f : a.recoveries) {
    spec.faults.push_back(named("recoveries", [&] { return sim::parse_fault(morph, f, true); }));
  }
  sim::sort_timeline(spec.faults);
  if (learning) {
    spec.start = experiments::learning_start(learning->mode);
    spec.learning = std::move(learning);
  } else {
    spec.start = {named("periods", [&] { return parse_periods(morph, a.periods); }), a.warmup};
  }
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    throw BadInput(argument_of(e.key()) + ": " + e.what());
  }
  return spec;
}

// A robot and its simulation model, shared read-only by every Simulation of it.
struct Robot {
  robot::RobotKind kind;
  sim::SimOptions options;
  std::shared_ptr<const sim::SimModel> model;

  const robot::Morphology& morph() const { return model->controller.morphology; }
};

std::shared_ptr<Robot> make_robot(const std::string& name, bool tunnel, double control_dt,
                                  std::optional<double> physics_dt,
                                  std::optional<double> servo_gain) {
  auto r = std::make_shared<Robot>();
  r->kind = robot::parse_robot(name);
  sim::SimOptions options;
  options.control_dt = control_dt;
  options.physics_dt = physics_dt.value_or(0.0);
  options.servo_gain = servo_gain.value_or(0.0);
  sim::validate(options);
  r->options = options;
  r->options.scene.tunnel = tunnel;
  r->model = std::make_shared<const sim::SimModel>(sim::make_sim_model(r->kind, r->options));
  return r;
}

// A robot argument: a Robot, or a robot name for a Robot with default options.
std::shared_ptr<Robot> robot_arg(const py::object& robot) {
  if (py::isinstance<py::str>(robot)) {
    return make_robot(robot.cast<std::string>(), false, sim::kDefaultControlDt, {}, {});
  }
  return robot.cast<std::shared_ptr<Robot>>();
}

// Records each step's CPG outputs (x1, x2 per leg) beside the WalkRecord and passes every step
// and event on to a film, when one is running.
class CpgRecorder final : public sim::Observer {
 public:
  void on_step(const sim::SimModel& model, const sim::SimState& state) override {
    if (enabled) append(state);
    if (next != nullptr) next->on_step(model, state);
  }
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const sim::Event& event) override {
    if (next != nullptr) next->on_event(model, state, event);
  }
  void append(const sim::SimState& state) {
    for (const neural::LegState& leg : state.controller.legs) {
      outputs.push_back(leg.cpg.x1);
      outputs.push_back(leg.cpg.x2);
    }
  }

  bool enabled = true;
  std::vector<double> outputs;  // [row * legs * 2 + leg * 2 + neuron]
  sim::Observer* next = nullptr;
};

// What Simulation.state() returns: a complete copy of a run.
struct State {
  std::shared_ptr<const sim::SimModel> model;
  sim::StepperCheckpoint checkpoint;
};

// A run, stepped through sim::Stepper. Methods that walk release the GIL.
class Simulation {
 public:
  Simulation(std::shared_ptr<Robot> robot, const RunArgs& args, bool record)
      : robot_(std::move(robot)), recording_(record) {
    const experiments::RunSpec spec = run_spec(robot_->kind, robot_->options, args, std::nullopt);
    stepper_ = std::make_unique<sim::Stepper>(*robot_->model, spec.start, spec.faults, &recorder_,
                                              recording_ ? &record_ : nullptr);
    recorder_.enabled = recording_;
    if (recording_) recorder_.append(stepper_->state());
  }

  void step(long n) {
    if (n < 0 || n > sim::kMaxSteps) {
      throw BadInput("steps must be in 0.." + std::to_string(sim::kMaxSteps) + ", got " +
                     std::to_string(n));
    }
    const py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    stepper_->steps(n);
  }

  void set_periods(const py::object& periods) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::vector<int> p = parse_periods(robot_->morph(), periods);
    neural::set_periods(robot_->model->controller, stepper_->state().controller, p);
  }

  void set_failed(const py::object& legs, bool failed) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::vector<std::size_t> list = robot::parse_leg_set(robot_->morph(), leg_text(legs));
    if (list.empty()) throw BadInput("name at least one leg, e.g. \"R1\" or [\"R1\", \"R3\"]");
    stepper_->apply_now(sim::Fault{0, list, !failed});
  }

  void synchronise(bool on) {
    const std::lock_guard<std::mutex> lock(mutex_);
    neural::set_synchronised(stepper_->state().controller, on);
  }

  State state() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return {robot_->model, stepper_->checkpoint()};
  }

  void restore(const State& s) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (s.model != robot_->model) {
      throw BadInput("restore: the state comes from a simulation of another Robot");
    }
    stepper_->restore(s.checkpoint);
    record_ = sim::WalkRecord{};
    recorder_.outputs.clear();
    if (recording_) {
      record_.legs = robot_->morph().size();
      sim::append_record(*robot_->model, stepper_->state(), true, record_);
      recorder_.append(stepper_->state());
    }
  }

  py::dict record() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    require_record("record");
    const auto rows = static_cast<py::ssize_t>(record_.rows());
    const auto legs = static_cast<py::ssize_t>(record_.legs);
    const auto joints = static_cast<py::ssize_t>(robot::kJointsPerLeg);
    std::vector<double> position;
    for (std::size_t i = 0; i < record_.rows(); ++i) {
      position.insert(position.end(), {record_.x[i], record_.y[i], record_.z[i]});
    }
    py::array_t<bool> contact_array({rows, legs});
    std::copy(record_.contact.begin(), record_.contact.end(), contact_array.mutable_data());
    py::dict out;
    out["time"] = array(record_.time, {rows});
    out["position"] = array(position, {rows, 3});
    out["yaw_deg"] = array(record_.yaw_deg, {rows});
    out["command"] = array(record_.command, {rows, legs, joints});
    out["target"] = array(record_.target, {rows, legs, joints});
    out["actual"] = array(record_.actual, {rows, legs, joints});
    out["contact"] = contact_array;
    out["cpg"] = array(recorder_.outputs, {rows, legs, 2});
    return out;
  }

  py::dict measure(long settle, long window) {
    const std::lock_guard<std::mutex> lock(mutex_);
    require_record("measure");
    const long steps = static_cast<long>(record_.rows()) - 1 - settle;
    if (settle < 0 || steps <= 0) {
      throw BadInput("settle must be in 0.." + std::to_string(record_.rows() - 2) + ", got " +
                     std::to_string(settle));
    }
    if (window <= 0) throw BadInput("window must be positive, got " + std::to_string(window));
    sim::WalkResult result;
    result.record = std::move(record_);
    sim::measure_walk(*robot_->model, settle, steps, window, result);
    record_ = std::move(result.record);
    py::list windows;
    for (const sim::WindowMeasure& m : result.windows) {
      windows.append(py::dict(py::arg("yaw_deg") = m.yaw_deg, py::arg("path_deg") = m.path_deg));
    }
    return py::dict(
        py::arg("duration_s") = result.duration_s, py::arg("distance_m") = result.distance_m,
        py::arg("forward_m") = result.forward_m, py::arg("lateral_m") = result.lateral_m,
        py::arg("speed_m_s") = result.speed_m_s,
        py::arg("window_deviations_deg") = result.window_deviations_deg,
        py::arg("windows") = windows, py::arg("final_yaw_deg") = result.final_yaw_deg);
  }

  py::tuple pose() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const sim::Pose2 p = stepper_->pose();
    return py::make_tuple(p.x, p.y, p.yaw_deg);
  }

  std::vector<int> periods() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<int> out;
    for (const neural::LegState& leg : stepper_->state().controller.legs) {
      out.push_back(leg.cpg.period);
    }
    return out;
  }

  std::vector<std::string> failed() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    for (std::size_t leg : stepper_->faults().failed_legs()) {
      out.push_back(robot_->morph().legs[leg].name);
    }
    return out;
  }

  long step_count() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return stepper_->step_count();
  }
  double time() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return stepper_->state().data->time;
  }
  const std::shared_ptr<Robot>& robot() const { return robot_; }

  py::array_t<std::uint8_t> render(int width, int height, const std::string& caption) {
    report::Image image;
    {
      const py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!renderer_ || renderer_->width() != width || renderer_->height() != height) {
        renderer_.reset();
        renderer_ = std::make_unique<report::Renderer>(robot_->model->mj.get(), width, height);
      }
      image = report::film_frame(*renderer_, *robot_->model, stepper_->state(),
                                 report::CameraSpec{}, caption);
    }
    py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(image.height),
                                   static_cast<py::ssize_t>(image.width), py::ssize_t{3}});
    std::copy(image.rgb.begin(), image.rgb.end(), out.mutable_data());
    return out;
  }

  int film(const std::string& out, long steps, int speed, int width, int height) {
    if (steps < 0 || steps > sim::kMaxSteps) {
      throw BadInput("steps must be in 0.." + std::to_string(sim::kMaxSteps) + ", got " +
                     std::to_string(steps));
    }
    const py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    report::FilmSpec spec;
    spec.out = out;
    spec.width = width;
    spec.height = height;
    spec.speed = speed;
    report::Film film(*robot_->model, spec);
    report::FilmObserver observer(film);
    recorder_.next = &observer;
    try {
      stepper_->steps(steps);
    } catch (...) {
      recorder_.next = nullptr;
      throw;
    }
    recorder_.next = nullptr;
    if (film.format() == report::FilmFormat::picture) {
      film.picture(stepper_->state(), observer.caption());
      return 1;
    }
    film.finish();
    return film.frames();
  }

 private:
  void require_record(const char* what) const {
    if (!recording_) {
      throw BadInput(std::string(what) + ": this Simulation was made with record=False");
    }
  }

  std::shared_ptr<Robot> robot_;
  bool recording_;
  sim::WalkRecord record_;
  CpgRecorder recorder_;
  std::unique_ptr<sim::Stepper> stepper_;
  std::unique_ptr<report::Renderer> renderer_;
  // Python threads may share a Simulation: its methods take turns (step() without the GIL).
  mutable std::mutex mutex_;
};

// Calls a Python function at the end of every learning trial (with the GIL held).
class TrialCallback final : public sim::Observer {
 public:
  TrialCallback(py::object callback, const robot::Morphology& morph)
      : callback_(std::move(callback)), morph_(morph) {}
  void on_event(const sim::SimModel& /*model*/, const sim::SimState& /*state*/,
                const sim::Event& e) override {
    if (e.kind != sim::EventKind::trial_end || callback_.is_none()) return;
    const py::gil_scoped_acquire acquire;
    const py::object periods = to_python(robot::period_map_json(morph_, e.periods));
    callback_(py::dict(py::arg("episode") = e.episode, py::arg("trial") = e.trial,
                       py::arg("step") = e.step, py::arg("periods") = periods,
                       py::arg("deviation_deg") = e.deviation_deg,
                       py::arg("accepted") = e.accepted));
  }

 private:
  py::object callback_;
  const robot::Morphology& morph_;
};

// The trace of a learning run as arrays: trial, periods [trials, legs], deviation_deg, accepted,
// acceptance_probability.
py::dict trace_arrays(const std::vector<learning::TrialRecord>& trace, std::size_t legs) {
  std::vector<int> trial;
  std::vector<int> periods;
  std::vector<double> deviation;
  std::vector<double> probability;
  py::array_t<bool> accepted(static_cast<py::ssize_t>(trace.size()));
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const learning::TrialRecord& t = trace[i];
    trial.push_back(t.trial);
    periods.insert(periods.end(), t.periods.begin(), t.periods.end());
    deviation.push_back(t.deviation_deg);
    probability.push_back(t.acceptance_probability);
    accepted.mutable_at(static_cast<py::ssize_t>(i)) = t.accepted;
  }
  const auto n = static_cast<py::ssize_t>(trace.size());
  py::dict out;
  out["trial"] = array(trial, {n});
  out["periods"] = array(periods, {n, static_cast<py::ssize_t>(legs)});
  out["deviation_deg"] = array(deviation, {n});
  out["accepted"] = accepted;
  out["acceptance_probability"] = array(probability, {n});
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

py::dict learn(const py::object& robot_object, const RunArgs& args,
               const learning::CompensationOptions& options, bool record,
               const py::object& observer) {
  const std::shared_ptr<Robot> robot = robot_arg(robot_object);
  const robot::Morphology& morph = robot->morph();
  experiments::RunSpec spec = run_spec(robot->kind, robot->options, args, options);
  spec.record.steps = record;
  TrialCallback callback(observer, morph);
  experiments::LearningRun run;
  {
    const py::gil_scoped_release release;
    run = experiments::run_learning(*robot->model, spec, 0, &callback);
  }
  py::dict out = to_python(experiments::learn_json(spec, run.result));
  out["trace_arrays"] = trace_arrays(run.result.trace, morph.size());
  if (record) out["path"] = path_arrays(run.record);
  return out;
}

py::dict tunnel(const experiments::RunSpec& spec, long max_steps, const std::string& video,
                const py::object& observer) {
  const robot::Morphology& morph = experiments::morphology(spec);
  if (!video.empty() && report::film_format(video) != report::FilmFormat::video) {
    throw BadInput("video must name an .mp4 file");
  }
  require_in("max_steps", max_steps, sim::kRunStepsLimits);
  TrialCallback callback(observer, morph);
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
      film_observer.emplace(*film, "tunnel 3.0 m x 1.2 m");
    }
    out = experiments::run_tunnel(spec, corridor, max_steps,
                                  film_observer ? &*film_observer : nullptr, &callback);
    if (film) film->finish();
  }
  py::dict result = to_python(experiments::tunnel_json(spec, out));
  if (out.learned) result["trace_arrays"] = trace_arrays(out.learned->trace, morph.size());
  result["path"] = path_arrays(out.run.record);
  return result;
}

// The annealing search of learning/annealing.h, one call per step, for agents written in
// Python: the same draws as learning::compensate, so the same seed gives the same trace.
class Annealer {
 public:
  Annealer(const std::shared_ptr<Robot>& robot, const std::vector<int>& periods,
           const py::object& disabled, double e_ref, std::uint64_t seed, double beta,
           double threshold, int max_trials)
      : morph_(robot->morph()) {
    params_.beta = beta;
    params_.threshold_deg = threshold;
    params_.max_trials = max_trials;
    state_ = learning::start_annealing(
        params_, periods, robot::parse_leg_set(morph_, leg_text(disabled)), e_ref, seed);
  }

  std::optional<std::vector<int>> propose() {
    if (state_.stop != learning::StopReason::running) return std::nullopt;
    const std::optional<learning::Candidate> c = learning::propose(params_, state_);
    if (!c) return std::nullopt;
    return c->periods;
  }

  py::dict decide(double deviation_deg) {
    if (!state_.pending) throw BadInput("decide: no proposed combination (call propose first)");
    const learning::Decision d = learning::decide(params_, state_, deviation_deg);
    return py::dict(py::arg("accepted") = d.accepted, py::arg("probability") = d.probability,
                    py::arg("stop") = std::string(learning::to_string(d.stop)));
  }

  std::string stop() const { return std::string(learning::to_string(state_.stop)); }
  int trials() const { return state_.trials; }
  std::vector<int> accepted() const { return state_.accepted; }
  double e_ref() const { return state_.e_ref; }
  std::vector<std::string> working() const {
    std::vector<std::string> out;
    for (std::size_t leg : state_.working) out.push_back(morph_.legs[leg].name);
    return out;
  }
  py::list trace() const {
    py::list out;
    for (const learning::TrialRecord& t : state_.trace) {
      out.append(
          py::dict(py::arg("trial") = t.trial, py::arg("periods") = t.periods,
                   py::arg("deviation_deg") = t.deviation_deg, py::arg("accepted") = t.accepted,
                   py::arg("acceptance_probability") = t.acceptance_probability,
                   py::arg("legs_changed") = t.legs_changed, py::arg("redraws") = t.redraws));
    }
    return out;
  }

 private:
  const robot::Morphology& morph_;
  learning::AnnealingParams params_;
  learning::AnnealingState state_;
};

}  // namespace
// Runs an experiment as `multicpg run` does (issue 10): an experiment file, or its document as
// JSON text, into `out` on `jobs` threads (0: every core); the Python side reads out/runs.csv.
void run_experiment(const std::string& source, bool is_document, int jobs, const std::string& out) {
  const experiments::Sweep sweep = is_document
                                       ? experiments::resolve_sweep(nlohmann::json::parse(source))
                                       : experiments::load_experiment_file(source);
  if (sweep.landscape) {
    throw BadInput("experiment(): a landscape has no tidy table; run it with `multicpg run`");
  }
  experiments::SweepRunOptions options;
  options.out = out;
  if (jobs != 0) {
    require_in("jobs", jobs, experiments::kJobsLimits);
    options.jobs = jobs;
  }
  options.progress = false;
  const py::gil_scoped_release release;
  experiments::run_sweep(sweep, options);
}

}  // namespace multicpg::python

namespace mp = multicpg::python;

PYBIND11_MODULE(_multicpg, m) {
  using multicpg::BadInput;
  using multicpg::RuntimeFailure;
  m.doc() = "multicpg: multiple chaotic CPGs driving MuJoCo robots, and their learning.";
  // Bad input is the caller's mistake (CLI exit 2), a failed run is not (CLI exit 1).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const multicpg::OptionError& e) {
      PyErr_SetString(PyExc_ValueError, (e.key() + " " + e.what()).c_str());
    } catch (const BadInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const RuntimeFailure& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  // The CLI's defaults, for Python code that walks the same runs (multicpg.env).
  m.attr("DEFAULT_THRESHOLD_DEG") = multicpg::learning::kDefaultThresholdDeg;
  m.attr("DEFAULT_WINDOW_STEPS") = multicpg::learning::kDefaultWindowSteps;
  m.attr("DEFAULT_MAX_TRIALS") = multicpg::learning::kDefaultMaxTrials;
  m.attr("DEFAULT_BETA") = multicpg::learning::kDefaultBeta;
  m.attr("DETECTION_WINDOWS") = multicpg::learning::kDefaultDetectionWindows;

  py::class_<mp::Robot, std::shared_ptr<mp::Robot>>(
      m, "Robot",
      "A robot (hexapod, quadruped or octopod) and its MuJoCo model, shared read-only by every\n"
      "Simulation of it. tunnel=True adds the 3.0 m x 1.2 m corridor of paper §5. control_dt,\n"
      "physics_dt and servo_gain are the CLI's --control-dt, --physics-dt, --servo-gain.")
      .def(py::init(&mp::make_robot), py::arg("name") = "hexapod", py::kw_only(),
           py::arg("tunnel") = false, py::arg("control_dt") = multicpg::sim::kDefaultControlDt,
           py::arg("physics_dt") = py::none(), py::arg("servo_gain") = py::none())
      .def_property_readonly(
          "name", [](const mp::Robot& r) { return r.morph().name; }, "robot name")
      .def_property_readonly(
          "legs",
          [](const mp::Robot& r) {
            std::vector<std::string> out;
            for (const auto& leg : r.morph().legs) out.push_back(leg.name);
            return out;
          },
          "leg names R1..Rn, L1..Ln (the order of every per-leg array)")
      .def_property_readonly(
          "joints",
          [](const mp::Robot&) {
            std::vector<std::string> out;
            for (auto j : multicpg::robot::kJoints) out.emplace_back(multicpg::robot::to_string(j));
            return out;
          },
          "joint names of a leg: TC, CTr, FTi (the order of the joint axis)")
      .def_property_readonly(
          "joint_names",
          [](const mp::Robot& r) {
            std::vector<std::string> out;
            for (const auto& leg : r.morph().legs) {
              for (auto j : multicpg::robot::kJoints) {
                out.push_back(leg.name + "_" + std::string(multicpg::robot::to_string(j)));
              }
            }
            return out;
          },
          "every joint's MJCF name, R1_TC, R1_CTr, R1_FTi, R2_TC, ...")
      .def_property_readonly(
          "control_dt", [](const mp::Robot& r) { return r.model->control_dt; },
          "simulated seconds per controller step")
      .def_property_readonly(
          "physics_dt", [](const mp::Robot& r) { return r.model->physics_dt; },
          "MuJoCo time step, s")
      .def_property_readonly(
          "default_settle_steps",
          [](const mp::Robot& r) {
            return multicpg::learning::default_settle_steps(r.model->controller);
          },
          "unmeasured steps after a period change in paper mode (337 for the hexapod)")
      .def(
          "mjcf", [](const mp::Robot& r) { return multicpg::sim::model_xml(r.kind, r.options); },
          "The MJCF text of the model (what `multicpg model` prints).")
      .def("__repr__",
           [](const mp::Robot& r) { return "multicpg.Robot('" + r.morph().name + "')"; });

  py::class_<mp::State>(m, "State",
                        "A complete copy of a Simulation (Simulation.state()); restore it into a\n"
                        "Simulation of the same Robot to continue exactly from there.");

  py::class_<mp::Simulation>(
      m, "Simulation",
      "A simulated robot walking under its controller, stepped by the one stepping loop\n"
      "(sim::Stepper) as `multicpg walk` is.\n\n"
      "robot: a Robot or a robot name. periods: 4, 'R1=5,R2=4' or one per leg (unequal periods\n"
      "free the clients). disable/disable_at: legs that fail at a step (names, 'R1,R3' or a\n"
      "list). faults/recoveries: 'LEGS@STEP' strings like --fault/--recover. warmup:\n"
      "controller steps before the robot moves (0 = cold). record=False keeps no per-step record.\n"
      "Same arguments, same trajectory, bit for bit.")
      .def(
          py::init([](const py::object& robot, const py::object& periods, const py::object& disable,
                      long disable_at, const std::vector<std::string>& faults,
                      const std::vector<std::string>& recoveries, long warmup, bool record) {
            const mp::RunArgs args{periods, disable, disable_at, faults, recoveries, warmup};
            return std::make_unique<mp::Simulation>(mp::robot_arg(robot), args, record);
          }),
          py::arg("robot") = "hexapod", py::kw_only(), py::arg("periods") = 4,
          py::arg("disable") = py::none(), py::arg("disable_at") = 0,
          py::arg("faults") = std::vector<std::string>{},
          py::arg("recoveries") = std::vector<std::string>{},
          py::arg("warmup") = multicpg::sim::kControllerWarmup, py::arg("record") = true)
      .def("step", &mp::Simulation::step, py::arg("n") = 1,
           "Walks n controller steps (faults applied on schedule). Releases the GIL.")
      .def("set_periods", &mp::Simulation::set_periods, py::arg("periods"),
           "Sets the legs' CPG periods (4, 'R1=5,...' or one per leg) and resets every CPG.")
      .def(
          "fail", [](mp::Simulation& s, const py::object& legs) { s.set_failed(legs, true); },
          py::arg("legs"), "These legs fail from the next step on ('R1,R3' or a list).")
      .def(
          "recover", [](mp::Simulation& s, const py::object& legs) { s.set_failed(legs, false); },
          py::arg("legs"), "These failed legs work again from the next step on.")
      .def("synchronise", &mp::Simulation::synchronise, py::arg("on"),
           "True: every client CPG follows the master (R1); False: every CPG runs free.")
      .def("state", &mp::Simulation::state,
           "A complete copy of the run: physics (mjData), controller, step and faults.")
      .def("restore", &mp::Simulation::restore, py::arg("state"),
           "Continues from `state` (of a Simulation of the same Robot) exactly as that run did;\n"
           "the record starts again at the restored state.")
      .def("record", &mp::Simulation::record,
           "Every step as NumPy arrays (row 0 = the start, T rows): time [T] s, position [T,3]\n"
           "m, yaw_deg [T], command/target/actual [T,legs,3] (motor command in [-1,1], joint\n"
           "target and angle in rad; joints TC, CTr, FTi), contact [T,legs] bool, cpg [T,legs,2]\n"
           "(each CPG's outputs x1, x2).")
      .def("measure", &mp::Simulation::measure, py::arg("settle") = 0,
           py::arg("window") = multicpg::sim::kDefaultWindow,
           "What `multicpg walk --json` reports of the record from row `settle` on: distance_m,\n"
           "forward_m, lateral_m, speed_m_s, window_deviations_deg, windows (yaw and path angle).")
      .def("pose", &mp::Simulation::pose, "(x m, y m, yaw deg) of the trunk now.")
      .def_property_readonly("periods", &mp::Simulation::periods, "each leg's CPG period")
      .def_property_readonly("failed", &mp::Simulation::failed, "legs failed now")
      .def_property_readonly("step_count", &mp::Simulation::step_count,
                             "controller steps walked (warm-up excluded)")
      .def_property_readonly("time", &mp::Simulation::time, "simulated time, s")
      .def_property_readonly("robot", &mp::Simulation::robot, "the Robot walking");

  m.def(
      "render",
      [](mp::Simulation& s, int width, int height, const std::string& caption) {
        return s.render(width, height, caption);
      },
      py::arg("sim"), py::arg("width") = multicpg::report::kDefaultFrameWidth,
      py::arg("height") = multicpg::report::kDefaultFrameHeight, py::arg("caption") = "",
      "The simulation now as an H x W x 3 uint8 RGB array, drawn as films are (camera following\n"
      "the trunk, failed legs red, step and periods in the corner). Headless: EGL or OSMesa\n"
      "(MUJOCO_GL=egl|osmesa).");
  m.def(
      "film",
      [](mp::Simulation& s, const std::string& out, long steps, int speed, int width, int height) {
        return s.film(out, steps, speed, width, height);
      },
      py::arg("sim"), py::arg("out"), py::arg("steps"), py::kw_only(), py::arg("speed") = 1,
      py::arg("width") = multicpg::report::kDefaultFrameWidth,
      py::arg("height") = multicpg::report::kDefaultFrameHeight,
      "Walks `steps` more steps filming every `speed`-th into `out` (.mp4; .png: the last step\n"
      "only). Returns the number of frames written.");

  m.def(
      "measure_window",
      [](const std::tuple<double, double, double>& start,
         const std::tuple<double, double, double>& end) {
        const auto [x0, y0, yaw0] = start;
        const auto [x1, y1, yaw1] = end;
        const multicpg::sim::WindowMeasure w =
            multicpg::sim::measure_window({x0, y0, yaw0}, {x1, y1, yaw1});
        return py::dict(py::arg("yaw_deg") = w.yaw_deg, py::arg("path_deg") = w.path_deg,
                        py::arg("forward_m") = w.forward_m, py::arg("lateral_m") = w.lateral_m);
      },
      py::arg("start"), py::arg("end"),
      "Yaw change (wrapped, + = left) and path angle of a window between two poses (x, y, yaw).");

  const auto learning_options = [](const std::string& mode, const std::string& steering,
                                   int hold_windows, long monitor_windows, bool period_learning,
                                   double beta, double threshold, long window,
                                   std::optional<long> settle, int max_trials, std::uint64_t seed) {
    // Python's keyword arguments, one per option (the CLI binds its flags the same way).
    multicpg::learning::CompensationOptions o;
    o.mode = multicpg::learning::parse_mode(mode);
    const bool robust_only = steering != "reflex" || hold_windows != o.hold_windows ||
                             monitor_windows != o.monitor_windows || !period_learning;
    if (o.mode == multicpg::learning::Mode::paper && robust_only) {
      throw multicpg::BadInput(
          "steering, hold_windows, monitor_windows and period_learning are robust-mode "
          "arguments");
    }
    o.steering = o.mode == multicpg::learning::Mode::paper
                     ? multicpg::learning::Steering::off
                     : multicpg::learning::parse_steering(steering);
    o.hold_windows = hold_windows;
    o.monitor_windows = monitor_windows;
    o.learn_periods = period_learning;
    o.annealing.beta = beta;
    o.annealing.threshold_deg = threshold;
    o.window_steps = window;
    o.settle_steps = settle;
    o.annealing.max_trials = max_trials;
    o.seed = seed;
    return o;
  };

  m.def(
      "learn",
      [learning_options](const py::object& robot, const py::object& disable, long disable_at,
                         const std::vector<std::string>& faults,
                         const std::vector<std::string>& recoveries, const std::string& mode,
                         const std::string& steering, int hold_windows, long monitor_windows,
                         bool period_learning, double beta, double threshold, long window,
                         std::optional<long> settle, int max_trials, std::uint64_t seed,
                         bool record, const py::object& observer) {
        mp::RunArgs args;
        args.disable = disable;
        args.disable_at = disable_at;
        args.faults = faults;
        args.recoveries = recoveries;
        return mp::learn(
            robot, args,
            learning_options(mode, steering, hold_windows, monitor_windows, period_learning, beta,
                             threshold, window, settle, max_trials, seed),
            record, observer);
      },
      py::arg("robot") = "hexapod", py::kw_only(), py::arg("disable") = py::none(),
      py::arg("disable_at") = 0, py::arg("faults") = std::vector<std::string>{},
      py::arg("recoveries") = std::vector<std::string>{}, py::arg("mode") = "robust",
      py::arg("steering") = "reflex",
      py::arg("hold_windows") = multicpg::learning::kDefaultHoldWindows,
      py::arg("monitor_windows") = multicpg::learning::kDefaultMonitorWindows,
      py::arg("period_learning") = true, py::arg("beta") = multicpg::learning::kDefaultBeta,
      py::arg("threshold") = multicpg::learning::kDefaultThresholdDeg,
      py::arg("window") = multicpg::learning::kDefaultWindowSteps, py::arg("settle") = py::none(),
      py::arg("max_trials") = multicpg::learning::kDefaultMaxTrials, py::arg("seed") = 1,
      py::arg("record") = false, py::arg("observer") = py::none(),
      "`multicpg learn`: legs fail and the robot learns periods that walk straight again.\n"
      "Arguments are the CLI's flags (period_learning=False is --no-period-learning). Returns the\n"
      "dict of `learn --json`, plus trace_arrays (trial, periods [trials,legs], deviation_deg,\n"
      "accepted, acceptance_probability) and, with record=True, path (time, x, y, yaw_deg).\n"
      "observer(trial) is called after every trial with episode, trial, step, periods,\n"
      "deviation_deg and accepted. Releases the GIL while it walks.");

  m.def("_run_experiment", &mp::run_experiment, py::arg("source"), py::arg("is_document"),
        py::arg("jobs"), py::arg("out"),
        "Runs an experiment file or document (JSON text) into `out` (multicpg.experiment).");

  m.def(
      "tunnel",
      [learning_options](const py::object& disable, const py::object& periods, bool learn,
                         long max_steps, const std::string& video, const std::string& mode,
                         const std::string& steering, int hold_windows, long monitor_windows,
                         bool period_learning, double beta, double threshold, long window,
                         std::optional<long> settle, int max_trials, std::uint64_t seed,
                         double control_dt, std::optional<double> physics_dt,
                         std::optional<double> servo_gain, const py::object& observer) {
        if (learn && !periods.is_none()) {
          throw multicpg::BadInput("periods and learn exclude each other: learn finds them");
        }
        multicpg::sim::SimOptions sim;
        sim.control_dt = control_dt;
        sim.physics_dt = physics_dt.value_or(0.0);
        sim.servo_gain = servo_gain.value_or(0.0);
        mp::RunArgs args;
        args.disable = disable;
        if (!periods.is_none()) args.periods = periods;
        std::optional<multicpg::learning::CompensationOptions> options;
        if (learn) {
          options = learning_options(mode, steering, hold_windows, monitor_windows, period_learning,
                                     beta, threshold, window, settle, max_trials, seed);
        }
        return mp::tunnel(mp::run_spec(multicpg::robot::RobotKind::hexapod, sim, args, options),
                          max_steps, video, observer);
      },
      py::kw_only(), py::arg("disable") = py::none(), py::arg("periods") = py::none(),
      py::arg("learn") = false, py::arg("max_steps") = multicpg::experiments::kTunnelMaxSteps,
      py::arg("video") = "", py::arg("mode") = "robust", py::arg("steering") = "reflex",
      py::arg("hold_windows") = multicpg::learning::kDefaultHoldWindows,
      py::arg("monitor_windows") = multicpg::learning::kDefaultMonitorWindows,
      py::arg("period_learning") = true, py::arg("beta") = multicpg::learning::kDefaultBeta,
      py::arg("threshold") = multicpg::learning::kDefaultThresholdDeg,
      py::arg("window") = multicpg::learning::kDefaultWindowSteps, py::arg("settle") = py::none(),
      py::arg("max_trials") = multicpg::learning::kDefaultMaxTrials, py::arg("seed") = 1,
      py::arg("control_dt") = multicpg::sim::kDefaultControlDt, py::arg("physics_dt") = py::none(),
      py::arg("servo_gain") = py::none(), py::arg("observer") = py::none(),
      "`multicpg tunnel`: the hexapod walks the 3.0 m x 1.2 m corridor of paper §5 with the\n"
      "given periods, or (learn=True) after learning in the open field. Returns the dict of\n"
      "`tunnel --json` plus path (time, x, y, yaw_deg) and, after learning, trace_arrays.\n"
      "video='run.mp4' films the tunnel walk; observer as for learn().");

  py::class_<mp::Annealer>(
      m, "Annealer",
      "The simulated annealing of paper §3 (Table 2), one call per step, with the draws of\n"
      "`multicpg learn --mode paper`: start from C0 = periods measured at e_ref, then\n"
      "propose() a combination, walk it, decide(deviation).")
      .def(py::init([](const py::object& robot, const std::vector<int>& periods,
                       const py::object& disabled, double e_ref, std::uint64_t seed, double beta,
                       double threshold, int max_trials) {
             return std::make_unique<mp::Annealer>(mp::robot_arg(robot), periods, disabled, e_ref,
                                                   seed, beta, threshold, max_trials);
           }),
           py::arg("robot"), py::arg("periods"), py::arg("disabled"), py::arg("e_ref"),
           py::kw_only(), py::arg("seed") = 1, py::arg("beta") = multicpg::learning::kDefaultBeta,
           py::arg("threshold") = multicpg::learning::kDefaultThresholdDeg,
           py::arg("max_trials") = multicpg::learning::kDefaultMaxTrials)
      .def("propose", &mp::Annealer::propose,
           "The next combination (one period per leg) to try, or None when the search is over.")
      .def("decide", &mp::Annealer::decide, py::arg("deviation_deg"),
           "Keeps or rejects the proposed combination given its measured deviation E (deg);\n"
           "returns accepted, probability and stop (running, below threshold, trial cap, ...).")
      .def_property_readonly("stop", &mp::Annealer::stop,
                             "running, below threshold, trial cap or search space exhausted")
      .def_property_readonly("trials", &mp::Annealer::trials, "trials decided")
      .def_property_readonly("accepted", &mp::Annealer::accepted, "the accepted combination C(n)")
      .def_property_readonly("e_ref", &mp::Annealer::e_ref, "its deviation")
      .def_property_readonly("working", &mp::Annealer::working, "legs whose period may change")
      .def_property_readonly("trace", &mp::Annealer::trace, "one dict per decided trial");
}
