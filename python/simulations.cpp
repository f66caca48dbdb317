// multicpg.Simulation: a run stepped through sim::Stepper, as `multicpg walk` steps one, with
// its record, its state (python/state.h), rendering and films.
#include "python/simulations.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "learning/compensation.h"
#include "learning/steering.h"
#include "python/args.h"
#include "python/run_args.h"
#include "python/state.h"
#include "python/typed.h"
#include "python/values.h"
#include "python/watch.h"
#include "report/film.h"
#include "report/render.h"
#include "robot/leg_sets.h"
#include "sim/sim_body.h"
#include "sim/walk.h"

namespace multicpg::python {
namespace {

// A trunk coordinate: well past any walk (the fastest gait covers about 5 cm/s).
constexpr Limits<double> kCoordinateLimits{-1e6, 1e6};
// A yaw angle as poses give it, with room for unwrapped ones.
constexpr Limits<double> kAngleLimits{-1e6, 1e6};

// Records each step's CPG outputs (x1, x2 per leg) beside the WalkRecord and passes every step
// and event on to a film, when one is running.
class CpgRecorder final : public sim::Observer {
 public:
  void on_step(const sim::SimModel& model, const sim::SimState& state) override {
    if (enabled) append(state);
    if (next != nullptr) next->on_step(model, state);
  }
  void on_event(const sim::SimModel& model, const sim::SimState& state,
                const body::Event& event) override {
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

class Simulation {
 public:
  Simulation(std::shared_ptr<Robot> robot, const experiments::RunSpec& spec, bool record)
      : robot_(std::move(robot)), recording_(record) {
    stepper_ = std::make_unique<sim::Stepper>(*robot_->model, spec.start, spec.faults, &recorder_,
                                              recording_ ? &record_ : nullptr);
    start();
  }
  // A simulation continuing from `state` (copies and unpickled simulations).
  Simulation(const State& state, bool record) : robot_(state.robot), recording_(record) {
    stepper_ = std::make_unique<sim::Stepper>(*robot_->model, body::StartSpec{{}, 0},
                                              body::FaultTimeline{}, &recorder_,
                                              recording_ ? &record_ : nullptr);
    start();
    restore_locked(state);
  }
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // A copy that continues as this one would, with its record so far.
  std::unique_ptr<Simulation> copy() const {
    const auto lock = lock_with_gil();
    auto out = std::make_unique<Simulation>(state_locked(), recording_);
    out->record_ = record_;
    out->recorder_.outputs = recorder_.outputs;
    return out;
  }

  void step(IntArg n_arg, ProgressArg progress) {
    const long n = whole(n_arg, "n", body::kStepLimits);
    Watch watch(progress, "step", n);
    {
      const py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      require_room(n, "n");
      watched_steps(n, watch);
    }
    watch.finish();
  }

  void set_periods(PeriodsArg value) {
    const auto lock = lock_with_gil();
    const std::vector<int> p = periods_keeping(current_periods(), value);
    neural::set_periods(robot_->model->controller, stepper_->state().controller, p);
  }

  void set_failed(py::handle value, bool failed) {
    const robot::LegSet list = legs(robot_->morph(), value, "legs");
    if (list.empty()) value_error("legs", "name at least one leg, e.g. \"R1\" or [\"R1\", \"R3\"]");
    const auto lock = lock_with_gil();
    named("legs", [&] {
      stepper_->apply_now(body::Fault{0, list, !failed});
      return 0;
    });
  }

  void synchronise(BoolArg on) {
    const bool synchronised = flag(on, "on");
    const auto lock = lock_with_gil();
    neural::set_synchronised(stepper_->state().controller, synchronised);
  }

  // The orientation reflex of robust mode (learning/steering.h): on holds the course the trunk
  // has now; off stops it and gives both sides their full swing again.
  void steer(BoolArg on) {
    const bool steering = flag(on, "on");
    const auto lock = lock_with_gil();
    if (steering) {
      steering_ = learning::start_steering(stepper_->sensed_pose());
    } else {
      steering_.reset();
      neural::DriveInputs& drive = stepper_->state().controller.drive;
      const neural::DriveInputs forward;
      drive.turn_left = forward.turn_left;
      drive.turn_right = forward.turn_right;
    }
  }

  bool steering() const {
    const auto lock = lock_with_gil();
    return steering_.has_value();
  }

  // Walks one window of `steps` and measures it as the learner does (learning/compensation.h):
  // yaw change, path angle (against the reflex's course when it steers) and the reflex's mean
  // swing cut.
  py::dict walk_window(IntArg steps_arg) {
    const long steps = whole(steps_arg, "steps", learning::kWindowStepsLimits);
    body::WindowMeasure m;
    Watch watch(py::bool_(false), "walk_window", steps);
    {
      const py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      require_room(steps, "steps");
      // What the robot senses, as the learner measures (learning/course_walk.h).
      const body::Pose2 from = stepper_->sensed_pose();
      cut_sum_ = 0.0;
      watched_steps(steps, watch);
      m = body::measure_window(from, stepper_->sensed_pose(), learning::course_yaw_deg(steering_));
      m.steering_effort = cut_sum_ / static_cast<double>(steps);
    }
    return py::dict(py::arg("yaw_deg") = m.yaw_deg, py::arg("path_deg") = m.path_deg,
                    py::arg("forward_m") = m.forward_m, py::arg("lateral_m") = m.lateral_m,
                    py::arg("steering_effort") = m.steering_effort);
  }

  State state() const {
    const auto lock = lock_with_gil();
    return state_locked();
  }

  void restore(StateArg value) {
    if (!py::isinstance<State>(value)) type_error("state", "a multicpg.State", value);
    const State& s = value.cast<const State&>();
    if (s.robot->spec != robot_->spec) {
      value_error("state", "it comes from a simulation of " + robot_repr(*s.robot) +
                               ", this one walks " + robot_repr(*robot_));
    }
    const auto lock = lock_with_gil();
    restore_locked(s);
  }

  py::dict record() const {
    const auto lock = lock_with_gil();
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

  py::dict measure(IntArg settle_arg, IntArg window_arg) {
    const auto lock = lock_with_gil();
    require_record("measure");
    const long walked = static_cast<long>(record_.rows()) - 1;
    if (walked < 1) value_error("settle", "the record has no step yet: step() first");
    const long settle = whole(settle_arg, "settle", Limits<long>{0, walked - 1});
    const long window = whole(window_arg, "window", learning::kWindowStepsLimits);
    sim::WalkResult result;
    result.record = std::move(record_);
    sim::measure_walk(*robot_->model, settle, walked - settle, window, result);
    record_ = std::move(result.record);
    py::list windows;
    for (const body::WindowMeasure& m : result.windows) {
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
    const auto lock = lock_with_gil();
    const body::Pose2 p = stepper_->pose();
    return py::make_tuple(p.x, p.y, p.yaw_deg);
  }

  std::vector<int> periods() const {
    const auto lock = lock_with_gil();
    return current_periods();
  }

  std::vector<std::string> failed() const {
    const auto lock = lock_with_gil();
    std::vector<std::string> out;
    for (std::size_t leg : stepper_->faults().failed_legs()) {
      out.push_back(robot_->morph().legs[leg].name);
    }
    return out;
  }

  long step_count() const {
    const auto lock = lock_with_gil();
    return stepper_->step_count();
  }
  double time() const {
    const auto lock = lock_with_gil();
    return stepper_->state().data->time;
  }
  bool recording() const { return recording_; }
  const std::shared_ptr<Robot>& robot() const { return robot_; }

  py::array_t<std::uint8_t> render(IntArg width_arg, IntArg height_arg, StrArg caption_arg) {
    const int width = whole(width_arg, "width", report::kFrameSideLimits);
    const int height = whole(height_arg, "height", report::kFrameSideLimits);
    const std::string caption = text(caption_arg, "caption");
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

  int film(PathArg out_arg, IntArg steps_arg, IntArg speed_arg, IntArg width_arg,
           py::handle height_arg) {
    report::FilmSpec spec;
    spec.out = path(out_arg, "out");
    named("out", [&] { return report::film_format(spec.out); });
    const long steps = whole(steps_arg, "steps", body::kStepLimits);
    spec.speed = whole(speed_arg, "speed", report::kFilmSpeedLimits);
    spec.width = whole(width_arg, "width", report::kFrameSideLimits);
    spec.height = whole(height_arg, "height", report::kFrameSideLimits);
    Watch watch(py::bool_(false), "film", steps);
    const py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    require_room(steps, "steps");
    report::Film film(*robot_->model, spec);
    report::FilmObserver observer(film);
    sim::Observers both({&observer, &watch});
    watched_steps(steps, both);
    if (film.format() == report::FilmFormat::picture) {
      film.picture(stepper_->state(), observer.caption());
      return 1;
    }
    film.finish();
    return film.frames();
  }

  std::string repr() const {
    const auto lock = lock_with_gil();
    const robot::Morphology& morph = robot_->morph();
    const std::vector<int> periods = current_periods();
    const robot::LegSet failed = stepper_->faults().failed_legs();
    std::string out = "<multicpg.Simulation of " + robot_repr(*robot_) + " at step " +
                      std::to_string(stepper_->step_count()) + ":";
    // A failed leg's period marked x, as the CLI's trace marks a disabled leg.
    for (std::size_t leg = 0; leg < periods.size(); ++leg) {
      const bool off = std::find(failed.begin(), failed.end(), leg) != failed.end();
      out += " " + morph.legs[leg].name + "=" + std::to_string(periods[leg]) + (off ? "x" : "");
    }
    if (steering_) out += ", steering";
    return out + ">";
  }

 private:
  void start() {
    recorder_.enabled = recording_;
    if (recording_) recorder_.append(stepper_->state());
    stepper_->set_before_step([this](sim::Stepper& s) {
      if (!steering_) return;
      sim::SimBody body(s);
      cut_sum_ += learning::steer_body(steering_params_, *steering_, body);
    });
  }

  // Steps with `observer` told every step (after the recorder), so it may stop the run
  // between two steps.
  void watched_steps(long n, sim::Observer& observer) {
    recorder_.next = &observer;
    try {
      stepper_->steps(n);
    } catch (...) {
      recorder_.next = nullptr;
      throw;
    }
    recorder_.next = nullptr;
  }

  // The lock, taken with the GIL held: a stepping thread holds the lock and takes the GIL
  // every kPollInterval (python/watch.h), so waiting for the lock must let the GIL go.
  std::unique_lock<std::mutex> lock_with_gil() const {
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) {
      const py::gil_scoped_release release;
      lock.lock();
    }
    return lock;
  }

  State state_locked() const {
    return {robot_, std::make_shared<const sim::StepperCheckpoint>(stepper_->checkpoint()),
            steering_};
  }

  void restore_locked(const State& s) {
    stepper_->restore(*s.checkpoint);
    steering_ = s.steering;
    record_ = sim::WalkRecord{};
    recorder_.outputs.clear();
    if (recording_) {
      record_.legs = robot_->morph().size();
      sim::append_record(*robot_->model, stepper_->state(), true, record_);
      recorder_.append(stepper_->state());
    }
  }

  std::vector<int> current_periods() const {
    std::vector<int> out;
    for (const neural::LegState& leg : stepper_->state().controller.legs) {
      out.push_back(leg.cpg.period);
    }
    return out;
  }

  // New periods for set_periods: legs a dict or "LEG=P" text does not name keep theirs.
  std::vector<int> periods_keeping(const std::vector<int>& now, py::handle value) const {
    const robot::Morphology& morph = robot_->morph();
    // A leg is named when two different fallbacks give it the same period.
    const int other = robot::kGaitPeriods.front() == robot::kDefaultPeriod
                          ? robot::kGaitPeriods.back()
                          : robot::kGaitPeriods.front();
    std::vector<int> a = python::periods(morph, value, "periods", robot::kDefaultPeriod);
    const std::vector<int> b = python::periods(morph, value, "periods", other);
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (a[i] != b[i]) a[i] = now[i];
    }
    return a;
  }

  // A run walks at most body::kMaxSteps steps in all, as the CLI's runs.
  void require_room(long n, const char* name) const {
    if (n > body::kMaxSteps - stepper_->step_count()) {
      value_error(name, "the run has walked " + std::to_string(stepper_->step_count()) +
                            " steps; with " + std::to_string(n) + " more it would pass the " +
                            body::kStepLimits.text() + " a run may walk");
    }
  }

  void require_record(const char* what) const {
    if (!recording_) {
      throw py::value_error(
          std::string(what) +
          "(): this Simulation was made with record=False, so it keeps no record");
    }
  }

  std::shared_ptr<Robot> robot_;
  bool recording_;
  sim::WalkRecord record_;
  CpgRecorder recorder_;
  std::unique_ptr<sim::Stepper> stepper_;
  std::optional<learning::SteeringState> steering_;
  learning::SteeringParams steering_params_;
  double cut_sum_ = 0.0;  // the reflex's swing cuts since the window began
  std::unique_ptr<report::Renderer> renderer_;
  // Python threads may share a Simulation: its methods take turns (step() without the GIL).
  mutable std::mutex mutex_;
};

const Signature& simulation_signature() {
  // Never destroyed: its Python objects must not outlive the interpreter.
  static const auto* s =
      new Signature("Simulation", {{"robot", py::str("hexapod")}},
                    join({{{"periods", py::int_(robot::kDefaultPeriod)}, {"terrain", py::none()}},
                          fault_params(),
                          {{"warmup", py::int_(body::kControllerWarmup)},
                           {"record", py::bool_(true)},
                           {"seed", py::int_(1)}}}));
  return *s;
}

std::unique_ptr<Simulation> make_simulation(const Keywords& k) {
  const std::shared_ptr<Robot> robot = with_terrain(robot_arg(k["robot"]), k["terrain"]);
  const robot::Morphology& morph = robot->morph();
  body::StartSpec start{periods(morph, k["periods"], "periods"),
                        whole(k["warmup"], "warmup", body::kStepLimits), seed(k["seed"], "seed")};
  const experiments::RunSpec spec =
      run_spec(*robot, std::move(start), fault_timeline(morph, k), std::nullopt);
  return std::make_unique<Simulation>(robot, spec, flag(k["record"], "record"));
}

// (x, y, yaw_deg), as Simulation.pose() gives it.
body::Pose2 pose_arg(py::handle value, std::string_view name) {
  if (PyUnicode_Check(value.ptr()) || PySequence_Check(value.ptr()) == 0 ||
      PySequence_Size(value.ptr()) != 3) {
    PyErr_Clear();
    type_error(name, "a pose (x, y, yaw_deg)", value);
  }
  const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
  return {real(s[0], std::string(name) + "[0]", kCoordinateLimits),
          real(s[1], std::string(name) + "[1]", kCoordinateLimits),
          real(s[2], std::string(name) + "[2]", kAngleLimits)};
}

}  // namespace

void register_simulations(py::module_& m) {
  namespace mp = multicpg::python;
  using py::arg;
  static const std::string init_doc = simulation_signature().text("__init__", "None");
  py::class_<Simulation> simulation(
      m, "Simulation",
      "A simulated robot walking under its controller, stepped by the one stepping loop\n"
      "(sim::Stepper) as `multicpg walk` is.\n\n"
      "robot: a Robot, a robot name or a robot file FILE.toml; terrain: a multicpg.Terrain or\n"
      "its text (None: the robot's). periods: an int (every leg), a dict {'R1': 5} (legs not\n"
      "named: 4), one per leg in leg order, or 'R1=5,R2=4'; unequal periods free the clients.\n"
      "disable/disable_at: legs that fail at a step (a list of names or 'R1,R3').\n"
      "faults/recoveries: a list of multicpg.Fault / multicpg.Recovery or 'LEGS@STEP' text.\n"
      "warmup: controller steps before the robot moves (0 = cold; at most 100000000).\n"
      "seed (0..4294967295): the run's random stream (a noisy yaw sensor's draws).\n"
      "record=False keeps no per-step record. Same arguments, same trajectory, bit for bit.\n"
      "copy.deepcopy and pickle work (a pickled Simulation's record restarts at its state).");
  {
    const OwnSignatures own;
    simulation.def(py::init([](const py::args& args, const py::kwargs& kwargs) {
                     return make_simulation(simulation_signature().read(args, kwargs));
                   }),
                   init_doc.c_str());
  }
  simulation
      .def("step", &mp::Simulation::step, arg("n") = 1, py::kw_only(), arg("progress") = true,
           "Walks n controller steps (faults applied on schedule). Releases the GIL; Ctrl-C\n"
           "stops it between two steps (KeyboardInterrupt; the simulation stays usable). A bar\n"
           "shows progress once a call has run half a second; progress=False shows none, a\n"
           "callable gets a dict (stage, steps, total, ...) instead. A run walks at most\n"
           "100000000 steps in all.")
      .def("set_periods", &mp::Simulation::set_periods, arg("periods"),
           "Sets CPG periods (an int, {'R1': 5}, one per leg, or 'R1=5,L1=6'; legs a dict or\n"
           "text does not name keep theirs) and resets every CPG.")
      .def(
          "fail", [](mp::Simulation& s, mp::LegsArg legs) { s.set_failed(legs, true); },
          arg("legs"), "These legs fail from the next step on (a name, a list, or 'R1,R3').")
      .def(
          "recover", [](mp::Simulation& s, mp::LegsArg legs) { s.set_failed(legs, false); },
          arg("legs"), "These failed legs work again from the next step on.")
      .def("synchronise", &mp::Simulation::synchronise, arg("on"),
           "True: every client CPG follows the master (R1); False: every CPG runs free.")
      .def("steer", &mp::Simulation::steer, arg("on"),
           "True: the orientation reflex of robust mode holds the course the trunk has now\n"
           "(learning/steering.h); False: it stops, both sides swing fully again.")
      .def_property_readonly("steering", &mp::Simulation::steering, "whether the reflex steers")
      .def(
          "walk_window", &mp::Simulation::walk_window,
          arg("steps") = multicpg::learning::kDefaultWindowSteps,
          "Walks one window and measures it as the learner does: yaw_deg (change), path_deg\n"
          "(against the reflex's course when it steers), forward_m, lateral_m and steering_effort\n"
          "(the reflex's mean swing cut, 0..1). Releases the GIL.")
      .def("state", &mp::Simulation::state,
           "A complete copy of the run (a multicpg.State): physics, controller, steps, faults.")
      .def("restore", &mp::Simulation::restore, arg("state"),
           "Continues from `state` (of a Simulation of an equal Robot) exactly as that run did;\n"
           "the record starts again at the restored state.")
      .def("record", &mp::Simulation::record,
           "Every step as NumPy arrays (row 0 = the start, T rows): time [T] s, position [T,3]\n"
           "m, yaw_deg [T], command/target/actual [T,legs,3] (motor command in [-1,1], joint\n"
           "target and angle in rad; joints TC, CTr, FTi), contact [T,legs] bool, cpg [T,legs,2]\n"
           "(each CPG's outputs x1, x2).")
      .def("measure", &mp::Simulation::measure, arg("settle") = 0,
           arg("window") = sim::kDefaultWindow,
           "What `multicpg walk --json` reports of the record from row `settle` on: distance_m,\n"
           "forward_m, lateral_m, speed_m_s, window_deviations_deg, windows (yaw and path angle).")
      .def("pose", &mp::Simulation::pose, "(x m, y m, yaw deg) of the trunk now.")
      .def_property_readonly("periods", &mp::Simulation::periods, "each leg's CPG period")
      .def_property_readonly("failed", &mp::Simulation::failed, "legs failed now")
      .def_property_readonly("step_count", &mp::Simulation::step_count,
                             "controller steps walked (warm-up excluded)")
      .def_property_readonly("time", &mp::Simulation::time, "simulated time, s")
      .def_property_readonly("recording", &mp::Simulation::recording,
                             "whether it keeps a per-step record")
      .def_property_readonly("robot", &mp::Simulation::robot, "the Robot walking")
      .def("__repr__", &mp::Simulation::repr)
      .def("__copy__", &mp::Simulation::copy, "A Simulation that continues as this one would.")
      .def(
          "__deepcopy__", [](const mp::Simulation& s, py::object) { return s.copy(); }, arg("memo"),
          "A Simulation that continues as this one would, with its record.")
      .def(py::pickle([](const mp::Simulation& s)
                          -> py::object { return py::make_tuple(s.state(), s.recording()); },
                      [](const py::object& state) {
                        const py::tuple t = mp::pickled_tuple(state, 2, "Simulation");
                        if (!py::isinstance<mp::State>(t[0])) {
                          throw py::value_error("Simulation: not a pickled multicpg.Simulation");
                        }
                        return std::make_unique<mp::Simulation>(t[0].cast<const mp::State&>(),
                                                                mp::flag(t[1], "record"));
                      }));

  m.def(
      "render",
      [](mp::SimulationArg sim, mp::IntArg width, mp::IntArg height, mp::StrArg caption) {
        if (!py::isinstance<mp::Simulation>(sim))
          mp::type_error("sim", "a multicpg.Simulation", sim);
        return sim.cast<mp::Simulation&>().render(width, height, caption);
      },
      arg("sim"), arg("width") = report::kDefaultFrameWidth,
      arg("height") = report::kDefaultFrameHeight, arg("caption") = "",
      "The simulation now as an H x W x 3 uint8 RGB array, drawn as films are (camera following\n"
      "the trunk, failed legs red, step and periods in the corner, and `caption` under them);\n"
      "width and height 16..4096 px. Headless:\n"
      "EGL or OSMesa (MUJOCO_GL=egl|osmesa).");
  m.def(
      "film",
      [](mp::SimulationArg sim, mp::PathArg out, mp::IntArg steps, mp::IntArg speed,
         mp::IntArg width, mp::IntArg height) {
        if (!py::isinstance<mp::Simulation>(sim))
          mp::type_error("sim", "a multicpg.Simulation", sim);
        return sim.cast<mp::Simulation&>().film(out, steps, speed, width, height);
      },
      arg("sim"), arg("out"), arg("steps"), py::kw_only(), arg("speed") = 1,
      arg("width") = report::kDefaultFrameWidth, arg("height") = report::kDefaultFrameHeight,
      "Walks `steps` more steps filming every `speed`-th (1..1000) into `out` (.mp4; .png: the\n"
      "last step only). Returns the number of frames written.");

  m.def(
      "measure_window",
      [](mp::PoseArg start, mp::PoseArg end) {
        const body::WindowMeasure w =
            body::measure_window(mp::pose_arg(start, "start"), mp::pose_arg(end, "end"));
        return py::dict(arg("yaw_deg") = w.yaw_deg, arg("path_deg") = w.path_deg,
                        arg("forward_m") = w.forward_m, arg("lateral_m") = w.lateral_m);
      },
      arg("start"), arg("end"),
      "Yaw change (wrapped, + = left) and path angle of a window between two poses (x, y, yaw).");
}

}  // namespace multicpg::python
