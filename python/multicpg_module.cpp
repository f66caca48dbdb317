// The Python API: robots, simulations stepped through sim::Stepper, learning, the tunnel,
// rendering and films, and the annealing steps. Every argument is checked here before it reaches
// the libraries (python/args.h): a wrong type raises TypeError, a wrong value ValueError, each
// naming the Python parameter; a failed run raises RuntimeError. Results are the CLI's JSON as
// Python objects. Long runs release the GIL, so Python threads run in parallel. MuJoCo's fatal
// errors become RuntimeError here instead of ending the interpreter (sim/mujoco_guard.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <iomanip>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/limits.h"
#include "common/provenance.h"
#include "common/sealed_cbor.h"
#include "experiments/experiment_file.h"
#include "experiments/learning_run.h"
#include "experiments/run_json.h"
#include "experiments/run_spec.h"
#include "experiments/runner.h"
#include "experiments/sweep.h"
#include "experiments/tunnel.h"
#include "learning/annealing.h"
#include "learning/compensation.h"
#include "learning/json.h"
#include "learning/learners.h"
#include "learning/steering.h"
#include "python/args.h"
#include "python/replay.h"
#include "report/film.h"
#include "report/render.h"
#include "robot/body_json.h"
#include "robot/body_models.h"
#include "robot/leg_sets.h"
#include "robot/terrain.h"
#include "sim/checkpoint.h"
#include "sim/json.h"
#include "sim/mujoco_guard.h"
#include "sim/robot_file.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace py = pybind11;

namespace multicpg::python {
namespace {

using Json = nlohmann::json;

// A window's deviation E, 0..180 deg: the size of a wrapped yaw change (docs/learning.md
// "Deviation").
constexpr Limits<double> kDeviationLimits{0.0, 180.0};
// A trunk coordinate: well past any walk (the fastest gait covers about 5 cm/s).
constexpr Limits<double> kCoordinateLimits{-1e6, 1e6};
// A yaw angle as poses give it, with room for unwrapped ones.
constexpr Limits<double> kAngleLimits{-1e6, 1e6};

// nlohmann::json -> the Python objects json.loads would give.
py::object to_python(const Json& j) {
  switch (j.type()) {
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return py::str(j.get<std::string>());
    case Json::value_t::array: {
      py::list out;
      for (const Json& item : j) out.append(to_python(item));
      return out;
    }
    case Json::value_t::object: {
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

// ---- Robots -------------------------------------------------------------------------------

// A robot and its simulation model, shared read-only by every Simulation of it. Two robots are
// equal when they are made of the same kind, robot file and options (`key`), whichever object
// holds them.
struct Robot {
  robot::RobotKind kind;                                  // with a robot file, its layout
  std::shared_ptr<const experiments::RunRobotFile> file;  // null: the built-in robot
  sim::SimOptions options;
  std::string key;  // {"robot": name, "robot_file": its record, "sim": options} as JSON text
  std::shared_ptr<const sim::SimModel> model;

  const robot::Morphology& morph() const { return model->controller.morphology; }
};

// Equal robots share one compiled model while any of them lives (a compile takes tens of ms,
// and unpickled states each need their robot's).
std::shared_ptr<const sim::SimModel> shared_model(robot::RobotKind kind,
                                                  const experiments::RunRobotFile* file,
                                                  const sim::SimOptions& options,
                                                  const std::string& key) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const sim::SimModel>> models;
  const std::lock_guard<std::mutex> lock(mutex);
  if (std::shared_ptr<const sim::SimModel> model = models[key].lock()) return model;
  auto model = std::make_shared<const sim::SimModel>(file ? sim::make_sim_model(file->file, options)
                                                          : sim::make_sim_model(kind, options));
  models[key] = model;
  return model;
}

// The Python parameter a simulation option is set by.
std::string sim_argument(const std::string& key) {
  if (key == "scene.tunnel") return "tunnel";
  if (key.rfind("scene.terrain", 0) == 0) return "terrain";
  if (key.rfind("body.", 0) == 0) {
    const std::string rest = key.substr(5);
    const std::size_t end = rest.find_first_of(".[");
    return "body['" + rest.substr(0, end) + "']";
  }
  return key;
}

// A terrain argument: a multicpg.Terrain, or its text ("slope:5", robot/terrain.h).
robot::Terrain terrain_arg(py::handle value, std::string_view name) {
  if (py::isinstance<robot::Terrain>(value)) return value.cast<robot::Terrain>();
  if (!PyUnicode_Check(value.ptr())) {
    type_error(name, "a multicpg.Terrain or its text (\"flat\", \"slope:5\", \"rough:0.01\")",
               value);
  }
  return named(name, [&] { return robot::parse_terrain(value.cast<std::string>()); });
}

// The body: a named model's parameters (robot/body_models.h) with the keys of `body` (a dict of
// parameter name to value, robot/body_params.h) set.
void set_body(sim::SimOptions& options, py::handle model, py::handle body) {
  const std::string model_name = text(model, "model");
  options.model = named("model", [&] { return robot::parse_body_model(model_name); });
  options.body = robot::body_params(options.model);
  if (body.is_none()) return;
  if (!PyDict_Check(body.ptr())) type_error("body", "a dict of body parameters", body);
  Json params = options.body;
  for (const auto& [key_value, value] : py::reinterpret_borrow<py::dict>(body)) {
    const std::string key = text(key_value, "body's keys");
    const std::string where = "body['" + key + "']";
    if (!params.contains(key) || key == "leg_postures") {
      std::string known;
      for (const auto& item : params.items()) {
        if (item.key() != "leg_postures") known += (known.empty() ? "" : ", ") + item.key();
      }
      value_error(where, "is not a body parameter (known: " + known + ")");
    }
    if (key == "disabled_posture") {
      if (PyUnicode_Check(value.ptr()) || PySequence_Check(value.ptr()) == 0) {
        type_error(where, "three numbers: TC, CTr, FTi (-1..1)", value);
      }
      const auto triple = py::reinterpret_borrow<py::sequence>(value);
      if (triple.size() != 3) value_error(where, "takes three values: TC, CTr, FTi (-1..1)");
      params[key] = {{"tc", real(triple[0], where + "[0]", robot::kPostureLimits)},
                     {"ctr", real(triple[1], where + "[1]", robot::kPostureLimits)},
                     {"fti", real(triple[2], where + "[2]", robot::kPostureLimits)}};
    } else {
      params[key] = real(value, where, Limits<double>{-1e9, 1e9});
    }
  }
  options.body = params.get<robot::BodyParams>();
}

std::shared_ptr<Robot> robot_of(robot::RobotKind kind, const sim::SimOptions& options,
                                std::shared_ptr<const experiments::RunRobotFile> file = nullptr) {
  try {
    sim::validate(options, kind);
    if (file) {
      experiments::RunSpec walk;
      walk.robot = kind;
      walk.robot_file = file;
      walk.sim = options;
      experiments::validate(walk);
    }
  } catch (const OptionError& e) {
    value_error(sim_argument(e.key().starts_with("sim.") ? e.key().substr(4) : e.key()), e.what());
  }
  auto r = std::make_shared<Robot>();
  r->kind = kind;
  r->file = std::move(file);
  r->options = options;
  Json key{{"robot", std::string(robot::to_string(kind))}, {"sim", options}};
  if (r->file) key["robot_file"] = r->file->record;
  r->key = key.dump();
  r->model = shared_model(kind, r->file.get(), options, r->key);
  return r;
}

// Robot.from_file: a robot file (docs/robots.md "Your robot: robot files"); a bad one is a
// ValueError with the CLI's one line (the file, the key, what is wrong).
std::shared_ptr<const experiments::RunRobotFile> load_robot_file(const std::string& path) {
  try {
    return experiments::load_run_robot_file(path);
  } catch (const BadInput& e) {
    throw py::value_error(e.what());
  }
}

// The simulation options of Robot's keyword arguments.
sim::SimOptions sim_options(py::handle tunnel, py::handle control_dt, py::handle physics_dt,
                            py::handle servo_gain, py::handle terrain, py::handle model,
                            py::handle body) {
  sim::SimOptions options;
  options.scene.tunnel = flag(tunnel, "tunnel");
  options.scene.terrain = terrain_arg(terrain, "terrain");
  set_body(options, model, body);
  options.control_dt = real(control_dt, "control_dt", sim::kControlDtLimits);
  if (!physics_dt.is_none()) {
    options.physics_dt = real(physics_dt, "physics_dt", sim::kPhysicsDtLimits);
  }
  if (!servo_gain.is_none()) {
    options.servo_gain = real(servo_gain, "servo_gain", sim::kServoGainLimits);
  }
  return options;
}

std::shared_ptr<Robot> make_robot(py::handle name, py::handle tunnel, py::handle control_dt,
                                  py::handle physics_dt, py::handle servo_gain, py::handle terrain,
                                  py::handle model, py::handle body) {
  const std::string robot_name = text(name, "name");
  const robot::RobotKind kind = named("name", [&] { return robot::parse_robot(robot_name); });
  return robot_of(kind,
                  sim_options(tunnel, control_dt, physics_dt, servo_gain, terrain, model, body));
}

// A robot read back from its key (a pickled Robot or State).
std::shared_ptr<Robot> robot_from_key(const Json& key, std::string_view name) {
  try {
    const sim::SimOptions options = key.at("sim").get<sim::SimOptions>();
    if (key.contains("robot_file")) {
      // The file must still hold the robot that was pickled.
      const auto recorded = key.at("robot_file").get<experiments::RobotFileRecord>();
      auto file = load_robot_file(recorded.path);
      if (file->record != recorded) {
        value_error(name, "'" + recorded.path + "' has changed since the robot was pickled");
      }
      return robot_of(file->file.layout, options, file);
    }
    const robot::RobotKind kind =
        named(name, [&] { return robot::parse_robot(key.at("robot").get<std::string>()); });
    return robot_of(kind, options);
  } catch (const Json::exception& e) {
    value_error(name, std::string("not a multicpg robot: ") + e.what());
  }
}

// A robot argument: a Robot, or a robot name for a Robot with default options.
std::shared_ptr<Robot> robot_arg(py::handle robot, std::string_view name = "robot") {
  if (py::isinstance<Robot>(robot)) return robot.cast<std::shared_ptr<Robot>>();
  if (!PyUnicode_Check(robot.ptr())) {
    type_error(name,
               "a multicpg.Robot, a robot name (hexapod, quadruped, octopod) or a robot file "
               "FILE.toml",
               robot);
  }
  const std::string text = robot.cast<std::string>();
  if (sim::is_robot_file(text)) {
    auto file = load_robot_file(text);
    return robot_of(file->file.layout, sim::SimOptions{}, file);
  }
  const robot::RobotKind kind = named(name, [&] { return robot::parse_robot(text); });
  return robot_of(kind, sim::SimOptions{});
}

std::string robot_repr(const Robot& r) {
  const sim::SimOptions defaults;
  if (r.file) return "multicpg.Robot.from_file('" + r.file->record.path + "')";
  std::string out = "multicpg.Robot('" + r.morph().name + "'";
  if (r.options.scene.tunnel) out += ", tunnel=True";
  if (r.options.control_dt != defaults.control_dt) {
    out += ", control_dt=" + py::repr(py::float_(r.options.control_dt)).cast<std::string>();
  }
  if (r.options.physics_dt != defaults.physics_dt) {
    out += ", physics_dt=" + py::repr(py::float_(r.options.physics_dt)).cast<std::string>();
  }
  if (r.options.servo_gain != defaults.servo_gain) {
    out += ", servo_gain=" + py::repr(py::float_(r.options.servo_gain)).cast<std::string>();
  }
  if (r.options.scene.terrain != robot::Terrain{}) {
    out += ", terrain='" + robot::terrain_text(r.options.scene.terrain) + "'";
  }
  if (r.options.model != defaults.model) {
    out += ", model='" + std::string(robot::to_string(r.options.model)) + "'";
  }
  if (Json(r.options.body) != Json(robot::body_params(r.options.model))) out += ", body=...";
  return out + ")";
}

// ---- Run descriptions ---------------------------------------------------------------------

// The Python argument that sets a RunSpec key, for messages.
std::string argument_of(const std::string& key) {
  if (key == "start.periods") return "periods";
  if (key == "start.warmup") return "warmup";
  if (key == "faults") return "disable/faults/recoveries";
  if (key.rfind("sim.", 0) == 0) return sim_argument(key.substr(4));
  if (key == "learning.annealing.threshold_deg") return "threshold";
  if (key == "learning.window_steps") return "window";
  if (key == "learning.settle_steps") return "settle";
  if (key == "learning.learn_periods") return "period_learning";
  return key.substr(key.rfind('.') + 1);
}

// What fails when: `disable` at `disable_at`, then `faults` and `recoveries`, in step order.
struct FaultArgs {
  py::object disable = py::none();
  py::object disable_at = py::int_(0);
  py::object faults = py::none();
  py::object recoveries = py::none();
};

sim::FaultTimeline fault_timeline(const robot::Morphology& morph, const FaultArgs& a) {
  const long at = whole(a.disable_at, "disable_at", sim::kStepLimits);
  sim::FaultTimeline timeline = sim::fail_at(legs(morph, a.disable, "disable"), at);
  for (sim::Fault& f : faults(morph, a.faults, "faults", false)) timeline.push_back(std::move(f));
  for (sim::Fault& f : faults(morph, a.recoveries, "recoveries", true)) {
    timeline.push_back(std::move(f));
  }
  sim::sort_timeline(timeline);
  return timeline;
}

// A run checked whole (experiments::validate); a bad value is a ValueError naming its argument.
experiments::RunSpec run_spec(const Robot& robot, sim::StartSpec start, sim::FaultTimeline faults,
                              std::optional<learning::CompensationOptions> learning) {
  experiments::RunSpec spec;
  spec.robot = robot.kind;
  spec.robot_file = robot.file;
  spec.sim = robot.options;
  spec.faults = std::move(faults);
  if (learning) {
    spec.start = experiments::learning_start(learning->mode);
    spec.learning = std::move(learning);
  } else {
    spec.start = std::move(start);
  }
  try {
    experiments::validate(spec);
  } catch (const OptionError& e) {
    value_error(argument_of(e.key()), e.what());
  }
  return spec;
}

// The learning options of learn() and tunnel(), one keyword argument each.
struct LearningArgs {
  py::object mode, steering, hold_windows, monitor_windows, period_learning, beta, threshold,
      window, settle, max_trials, seed;
};

learning::CompensationOptions learning_options(const LearningArgs& a) {
  learning::CompensationOptions o;
  const std::string mode = text(a.mode, "mode");
  o.mode = named("mode", [&] { return learning::parse_mode(mode); });
  const std::string steering = text(a.steering, "steering");
  const learning::Steering steer =
      named("steering", [&] { return learning::parse_steering(steering); });
  o.hold_windows = whole(a.hold_windows, "hold_windows", learning::kHoldWindowsLimits);
  o.monitor_windows = whole(a.monitor_windows, "monitor_windows", learning::kMonitorWindowsLimits);
  o.learn_periods = flag(a.period_learning, "period_learning");
  const learning::CompensationOptions defaults;
  const bool robust_only = steer != learning::Steering::reflex ||
                           o.hold_windows != defaults.hold_windows ||
                           o.monitor_windows != defaults.monitor_windows || !o.learn_periods;
  if (o.mode == learning::Mode::paper && robust_only) {
    value_error("mode",
                "steering, hold_windows, monitor_windows and period_learning are "
                "robust-mode arguments");
  }
  o.steering = o.mode == learning::Mode::paper ? learning::Steering::off : steer;
  o.annealing.beta = real(a.beta, "beta", learning::kBetaLimits);
  o.annealing.threshold_deg = real(a.threshold, "threshold", learning::kThresholdLimits);
  o.window_steps = whole(a.window, "window", learning::kWindowStepsLimits);
  if (!a.settle.is_none()) o.settle_steps = whole(a.settle, "settle", learning::kSettleStepsLimits);
  o.annealing.max_trials = whole(a.max_trials, "max_trials", learning::kMaxTrialsLimits);
  o.seed = seed(a.seed, "seed");
  return o;
}

// ---- Simulations --------------------------------------------------------------------------

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

// What Simulation.state() returns: a complete copy of a run, immutable (restore copies it).
struct State {
  std::shared_ptr<Robot> robot;
  std::shared_ptr<const sim::StepperCheckpoint> checkpoint;
  std::optional<learning::SteeringState> steering;  // the reflex, when it steers
};

constexpr const char* kStateFormat = "multicpg state";
constexpr int kStateVersion = 1;

// A State as bytes: sealed CBOR (common/sealed_cbor.h) of its robot's key, its checkpoint
// (sim/checkpoint.h) and the reflex.
py::bytes state_bytes(const State& s) {
  const Json document{{"format", kStateFormat},
                      {"version", kStateVersion},
                      {"robot", Json::parse(s.robot->key)},
                      {"checkpoint", sim::checkpoint_json(*s.robot->model, *s.checkpoint)},
                      {"steering", s.steering ? Json(*s.steering) : Json()}};
  std::string bytes;
  {
    const py::gil_scoped_release release;
    bytes = seal_cbor(document);
  }
  return py::bytes(bytes);
}

State state_from_bytes(py::handle data, std::string_view name) {
  if (!PyBytes_Check(data.ptr()) && !PyByteArray_Check(data.ptr()) &&
      !PyMemoryView_Check(data.ptr())) {
    type_error(name, "the bytes of a multicpg.State", data);
  }
  const py::bytes copy = PyBytes_Check(data.ptr())
                             ? py::reinterpret_borrow<py::bytes>(data)
                             : py::reinterpret_steal<py::bytes>(PyBytes_FromObject(data.ptr()));
  const std::string bytes = copy;
  Json document;
  document = named(name, [&] { return unseal_cbor(bytes); });
  try {
    if (!document.is_object() || document.value("format", "") != kStateFormat ||
        document.at("version").get<int>() != kStateVersion) {
      value_error(name, "not a multicpg.State of this version");
    }
    State s;
    s.robot = robot_from_key(document.at("robot"), name);
    const Json& checkpoint = document.at("checkpoint");
    s.checkpoint = std::make_shared<const sim::StepperCheckpoint>(
        named(name, [&] { return sim::checkpoint_from_json(*s.robot->model, checkpoint); }));
    if (!document.at("steering").is_null()) {
      s.steering = document.at("steering").get<learning::SteeringState>();
    }
    return s;
  } catch (const Json::exception& e) {
    value_error(name, std::string("the state is damaged: ") + e.what());
  }
}

// A run, stepped through sim::Stepper. Methods that walk release the GIL.
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
    stepper_ =
        std::make_unique<sim::Stepper>(*robot_->model, sim::StartSpec{{}, 0}, sim::FaultTimeline{},
                                       &recorder_, recording_ ? &record_ : nullptr);
    start();
    restore_locked(state);
  }
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // A copy that continues as this one would, with its record so far.
  std::unique_ptr<Simulation> copy() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto out = std::make_unique<Simulation>(state_locked(), recording_);
    out->record_ = record_;
    out->recorder_.outputs = recorder_.outputs;
    return out;
  }

  void step(py::handle n_arg) {
    const long n = whole(n_arg, "n", sim::kStepLimits);
    const py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    require_room(n, "n");
    stepper_->steps(n);
  }

  void set_periods(py::handle value) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::vector<int> p = periods_keeping(current_periods(), value);
    neural::set_periods(robot_->model->controller, stepper_->state().controller, p);
  }

  void set_failed(py::handle value, bool failed) {
    const robot::LegSet list = legs(robot_->morph(), value, "legs");
    if (list.empty()) value_error("legs", "name at least one leg, e.g. \"R1\" or [\"R1\", \"R3\"]");
    const std::lock_guard<std::mutex> lock(mutex_);
    named("legs", [&] {
      stepper_->apply_now(sim::Fault{0, list, !failed});
      return 0;
    });
  }

  void synchronise(py::handle on) {
    const bool synchronised = flag(on, "on");
    const std::lock_guard<std::mutex> lock(mutex_);
    neural::set_synchronised(stepper_->state().controller, synchronised);
  }

  // The orientation reflex of robust mode (learning/steering.h): on holds the course the trunk
  // has now; off stops it and gives both sides their full swing again.
  void steer(py::handle on) {
    const bool steering = flag(on, "on");
    const std::lock_guard<std::mutex> lock(mutex_);
    if (steering) {
      steering_ = learning::start_steering(stepper_->pose());
    } else {
      steering_.reset();
      neural::DriveInputs& drive = stepper_->state().controller.drive;
      const neural::DriveInputs forward;
      drive.turn_left = forward.turn_left;
      drive.turn_right = forward.turn_right;
    }
  }

  bool steering() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return steering_.has_value();
  }

  // Walks one window of `steps` and measures it as the learner does (learning/compensation.h):
  // yaw change, path angle (against the reflex's course when it steers) and the reflex's mean
  // swing cut.
  py::dict walk_window(py::handle steps_arg) {
    const long steps = whole(steps_arg, "steps", learning::kWindowStepsLimits);
    sim::WindowMeasure m;
    {
      const py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      require_room(steps, "steps");
      const sim::Pose2 from = stepper_->pose();
      cut_sum_ = 0.0;
      stepper_->steps(steps);
      m = sim::measure_window(from, stepper_->pose(), learning::course_yaw_deg(steering_));
      m.steering_effort = cut_sum_ / static_cast<double>(steps);
    }
    return py::dict(py::arg("yaw_deg") = m.yaw_deg, py::arg("path_deg") = m.path_deg,
                    py::arg("forward_m") = m.forward_m, py::arg("lateral_m") = m.lateral_m,
                    py::arg("steering_effort") = m.steering_effort);
  }

  State state() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return state_locked();
  }

  void restore(py::handle value) {
    if (!py::isinstance<State>(value)) type_error("state", "a multicpg.State", value);
    const State& s = value.cast<const State&>();
    if (s.robot->key != robot_->key) {
      value_error("state", "it comes from a simulation of " + robot_repr(*s.robot) +
                               ", this one walks " + robot_repr(*robot_));
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    restore_locked(s);
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

  py::dict measure(py::handle settle_arg, py::handle window_arg) {
    const std::lock_guard<std::mutex> lock(mutex_);
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
    return current_periods();
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
  bool recording() const { return recording_; }
  const std::shared_ptr<Robot>& robot() const { return robot_; }

  py::array_t<std::uint8_t> render(py::handle width_arg, py::handle height_arg,
                                   py::handle caption_arg) {
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

  int film(py::handle out_arg, py::handle steps_arg, py::handle speed_arg, py::handle width_arg,
           py::handle height_arg) {
    report::FilmSpec spec;
    spec.out = path(out_arg, "out");
    named("out", [&] { return report::film_format(spec.out); });
    const long steps = whole(steps_arg, "steps", sim::kStepLimits);
    spec.speed = whole(speed_arg, "speed", report::kFilmSpeedLimits);
    spec.width = whole(width_arg, "width", report::kFrameSideLimits);
    spec.height = whole(height_arg, "height", report::kFrameSideLimits);
    const py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    require_room(steps, "steps");
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
  void start() {
    recorder_.enabled = recording_;
    if (recording_) recorder_.append(stepper_->state());
    stepper_->set_before_step([this](sim::Stepper& s) {
      if (!steering_) return;
      neural::ControllerState& c = s.state().controller;
      c.drive = learning::steer(steering_params_, *steering_, s.pose(), c.drive);
      cut_sum_ += std::abs(steering_->last_cut);
    });
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

  // A run walks at most sim::kMaxSteps steps in all, as the CLI's runs.
  void require_room(long n, const char* name) const {
    if (n > sim::kMaxSteps - stepper_->step_count()) {
      value_error(name, "the run has walked " + std::to_string(stepper_->step_count()) +
                            " steps; with " + std::to_string(n) + " more it would pass the " +
                            sim::kStepLimits.text() + " a run may walk");
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

std::unique_ptr<Simulation> make_simulation(py::handle robot_value, py::handle periods_value,
                                            const FaultArgs& fault_args, py::handle warmup,
                                            py::handle record, py::handle seed_value) {
  const std::shared_ptr<Robot> robot = robot_arg(robot_value);
  const robot::Morphology& morph = robot->morph();
  sim::StartSpec start{periods(morph, periods_value, "periods"),
                       whole(warmup, "warmup", sim::kStepLimits), seed(seed_value, "seed")};
  const experiments::RunSpec spec =
      run_spec(*robot, std::move(start), fault_timeline(morph, fault_args), std::nullopt);
  return std::make_unique<Simulation>(robot, spec, flag(record, "record"));
}

// ---- Learning and the tunnel --------------------------------------------------------------

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
// and one array per detail of the learner (the annealing's acceptance_probability, ...; NaN
// where a trial has none).
py::dict trace_arrays(std::string_view learner, const std::vector<learning::TrialRecord>& trace,
                      std::size_t legs) {
  std::vector<int> trial;
  std::vector<int> periods;
  std::vector<double> deviation;
  py::array_t<bool> accepted(static_cast<py::ssize_t>(trace.size()));
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const learning::TrialRecord& t = trace[i];
    trial.push_back(t.trial);
    periods.insert(periods.end(), t.periods.begin(), t.periods.end());
    deviation.push_back(t.deviation_deg);
    accepted.mutable_at(static_cast<py::ssize_t>(i)) = t.accepted;
  }
  const auto n = static_cast<py::ssize_t>(trace.size());
  py::dict out;
  out["trial"] = array(trial, {n});
  out["periods"] = array(periods, {n, static_cast<py::ssize_t>(legs)});
  out["deviation_deg"] = array(deviation, {n});
  out["accepted"] = accepted;
  for (const std::string& key : learning::detail_columns(learner, trace)) {
    std::vector<double> values;
    for (const learning::TrialRecord& t : trace) values.push_back(learning::detail_number(t, key));
    out[py::str(key)] = array(values, {n});
  }
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

py::dict learn(py::handle robot_value, const FaultArgs& fault_args, const LearningArgs& learning,
               py::handle record_value, py::handle observer_value) {
  const std::shared_ptr<Robot> robot = robot_arg(robot_value);
  const robot::Morphology& morph = robot->morph();
  const sim::FaultTimeline timeline = fault_timeline(morph, fault_args);
  experiments::RunSpec spec = run_spec(*robot, {}, timeline, learning_options(learning));
  spec.record.steps = flag(record_value, "record");
  TrialCallback callback(callable_or_none(observer_value, "observer"), morph);
  experiments::LearningRun run;
  {
    const py::gil_scoped_release release;
    run = experiments::run_learning(*robot->model, spec, 0, &callback);
  }
  py::dict out = to_python(experiments::learn_json(spec, run.result));
  out["trace_arrays"] = trace_arrays(spec.learning->learner.name, run.result.trace, morph.size());
  if (spec.record.steps) out["path"] = path_arrays(run.record);
  return out;
}

py::dict tunnel(const experiments::RunSpec& spec, long max_steps, const std::string& video,
                const py::object& observer, const std::optional<experiments::TunnelScale>& scale) {
  const robot::Morphology& morph = experiments::morphology(spec);
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
      std::ostringstream label;
      label << std::fixed << std::setprecision(1) << "tunnel " << corridor.scene.tunnel_length
            << " m x " << corridor.scene.tunnel_width << " m";
      film_observer.emplace(*film, label.str());
    }
    out = experiments::run_tunnel(spec, corridor, max_steps,
                                  film_observer ? &*film_observer : nullptr, &callback);
    if (film) film->finish();
  }
  py::dict result = to_python(experiments::tunnel_json(spec, out, scale));
  if (out.learned)
    result["trace_arrays"] =
        trace_arrays(spec.learning->learner.name, out.learned->trace, morph.size());
  result["path"] = path_arrays(out.run.record);
  return result;
}

// ---- The annealing, one step at a time ----------------------------------------------------

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

  py::dict decide(py::handle deviation) {
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
// into `out` on `jobs` threads (None: every core); the Python side reads out/runs.csv.
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
  const py::gil_scoped_release release;
  experiments::run_sweep(sweep, options);
}

// (x, y, yaw_deg), as Simulation.pose() gives it.
sim::Pose2 pose_arg(py::handle value, std::string_view name) {
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

std::string fault_repr(const FaultArg& f) {
  py::list names;
  for (const std::string& leg : f.legs) names.append(leg);
  std::string out = std::string(f.recover ? "multicpg.Recovery" : "multicpg.Fault") + "(";
  if (!f.legs.empty()) out += "legs=" + py::repr(names).cast<std::string>() + ", ";
  out += "step=" + std::to_string(f.step);
  if (f.kind != kLegFault) out += ", kind='" + f.kind + "'";
  if (f.joint) out += ", joint='" + *f.joint + "'";
  if (f.value) out += ", value=" + py::repr(py::float_(*f.value)).cast<std::string>();
  return out + ")";
}

py::tuple fault_state(const FaultArg& f) {
  return py::make_tuple(
      f.legs.empty() ? py::object(py::none()) : py::object(py::tuple(py::cast(f.legs))), f.step,
      f.kind, f.joint ? py::object(py::str(*f.joint)) : py::none(),
      f.value ? py::object(py::float_(*f.value)) : py::none());
}

// The tuple a pickled object of `what` holds.
py::tuple pickled_tuple(const py::object& state, std::size_t size, const std::string& what) {
  if (!py::isinstance<py::tuple>(state) || py::len(state) != size) {
    throw py::value_error(what + ": not a pickled multicpg." + what);
  }
  return py::reinterpret_borrow<py::tuple>(state);
}

// A Recovery is a Fault whose legs work again.
struct RecoveryArg : FaultArg {};

}  // namespace
}  // namespace multicpg::python

namespace mp = multicpg::python;

PYBIND11_MODULE(_multicpg, m) {
  namespace learning = multicpg::learning;
  namespace sim = multicpg::sim;
  namespace report = multicpg::report;
  using py::arg;
  m.doc() = "multicpg: multiple chaotic CPGs driving MuJoCo robots, and their learning.";
  mp::register_replay(m);
  // One bad call must not end the interpreter: MuJoCo's fatal errors become RuntimeError.
  sim::recover_mujoco_errors();
  // Bad input is the caller's mistake (CLI exit 2), a failed run is not (CLI exit 1).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const multicpg::OptionError& e) {
      PyErr_SetString(PyExc_ValueError, (e.key() + " " + e.what()).c_str());
    } catch (const multicpg::BadInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const multicpg::RuntimeFailure& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.attr("__version__") = MULTICPG_VERSION;
  m.def(
      "build_info",
      [] {
        const nlohmann::json p = multicpg::provenance(mj_versionString());
        return py::dict(arg("version") = MULTICPG_VERSION,
                        arg("git_commit") = p.at("git_commit").get<std::string>(),
                        arg("mujoco_version") = p.at("mujoco_version").get<std::string>(),
                        arg("compiler") = std::string(__VERSION__),
                        arg("pybind11_version") = std::to_string(PYBIND11_VERSION_MAJOR) + "." +
                                                  std::to_string(PYBIND11_VERSION_MINOR) + "." +
                                                  std::to_string(PYBIND11_VERSION_PATCH));
      },
      "What this module is: version (the project's), git_commit it was built from ('+dirty'\n"
      "with uncommitted changes, 'unknown' outside a git checkout), mujoco_version, compiler\n"
      "and pybind11_version.");

  // The CLI's defaults and limits, for Python code that walks the same runs (multicpg.env).
  m.attr("DEFAULT_THRESHOLD_DEG") = learning::kDefaultThresholdDeg;
  m.attr("DEFAULT_WINDOW_STEPS") = learning::kDefaultWindowSteps;
  m.attr("DEFAULT_MAX_TRIALS") = learning::kDefaultMaxTrials;
  m.attr("DEFAULT_BETA") = learning::kDefaultBeta;
  m.attr("DEFAULT_HOLD_WINDOWS") = learning::kDefaultHoldWindows;
  m.attr("DETECTION_WINDOWS") = learning::kDefaultDetectionWindows;
  m.attr("STEERING_MAX_EFFORT") = learning::SteeringParams{}.max_effort;
  m.attr("PERIOD_SET") = py::tuple(py::cast(learning::AnnealingParams{}.period_set));
  m.attr("GAIT_PERIODS") = py::tuple(py::cast(std::vector<int>(
      multicpg::robot::kGaitPeriods.begin(), multicpg::robot::kGaitPeriods.end())));
  m.attr("MAX_STEPS") = sim::kMaxSteps;
  m.attr("FRAME_SIDE_LIMITS") =
      py::make_tuple(report::kFrameSideLimits.lo, report::kFrameSideLimits.hi);

  py::class_<mp::FaultArg>(
      m, "Fault",
      "What breaks before controller step `step` of a run (paper §4; docs/faults.md).\n"
      "kind: 'leg' (the whole leg holds its disabled posture, the paper's fault), 'locked' (a\n"
      "joint stuck at the angle it had, or at `value` rad), 'passive' (a joint's motor off),\n"
      "'weak' (the torque limit times `value` in (0, 1]), 'short' (the tibia shortened to\n"
      "`value` of its length), 'slip' (the foot's friction times `value`), 'drift' (the yaw\n"
      "sensor drifts `value` deg/s) or 'noise' (the yaw sensor's noise, `value` deg).\n"
      "legs: leg names, as a list or 'R1,R3' (None for the sensor's kinds); joint: 'TC', 'CTr'\n"
      "or 'FTi' for one joint of each leg (locked and passive need one). Legs are checked\n"
      "against the robot when a run uses the fault. A Fault is immutable, comparable, hashable\n"
      "and picklable; str() gives the CLI's text, e.g. 'R2.CTr:locked@600'.")
      .def(py::init([](py::object legs, py::object step, py::object kind, py::object joint,
                       py::object value) {
             return mp::make_fault(legs, step, kind, joint, value, false);
           }),
           arg("legs") = py::none(), arg("step") = 0, py::kw_only(), arg("kind") = mp::kLegFault,
           arg("joint") = py::none(), arg("value") = py::none())
      .def_property_readonly(
          "kind", [](const mp::FaultArg& f) { return f.kind; },
          "what breaks: leg, locked, passive, weak, short, slip, drift or noise")
      .def_property_readonly(
          "legs", [](const mp::FaultArg& f) { return py::tuple(py::cast(f.legs)); },
          "the legs, as named (empty for the yaw sensor)")
      .def_property_readonly(
          "joint", [](const mp::FaultArg& f) { return f.joint; },
          "the joint of each leg, or None for whole legs")
      .def_property_readonly(
          "value", [](const mp::FaultArg& f) { return f.value; },
          "the kind's value (factor, fraction, angle, deg/s or deg), or None")
      .def_property_readonly(
          "step", [](const mp::FaultArg& f) { return f.step; },
          "the controller step it comes before")
      .def_property_readonly(
          "recover", [](const mp::FaultArg& f) { return f.recover; },
          "True for a Recovery: what broke works again")
      .def("__eq__",
           [](const mp::FaultArg& a, py::object b) -> py::object {
             if (!py::isinstance<mp::FaultArg>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             const auto& f = b.cast<const mp::FaultArg&>();
             return py::bool_(a.kind == f.kind && a.legs == f.legs && a.step == f.step &&
                              a.recover == f.recover && a.joint == f.joint && a.value == f.value);
           })
      .def("__hash__",
           [](const mp::FaultArg& f) {
             return py::hash(py::make_tuple(mp::fault_state(f), f.recover));
           })
      .def("__repr__", &mp::fault_repr)
      .def("__str__", &mp::fault_text)
      .def(py::pickle([](const mp::FaultArg& f) -> py::object { return mp::fault_state(f); },
                      [](const py::object& state) {
                        const py::tuple t = mp::pickled_tuple(state, 5, "Fault");
                        return mp::make_fault(t[0], t[1], t[2], t[3], t[4], false);
                      }));
  py::class_<mp::RecoveryArg, mp::FaultArg>(
      m, "Recovery",
      "What broke works again before controller step `step` (paper §2.3: when every leg works\n"
      "again the clients resynchronise). Arguments as for Fault; a value may be left out.")
      .def(py::init([](py::object legs, py::object step, py::object kind, py::object joint,
                       py::object value) {
             mp::RecoveryArg r;
             static_cast<mp::FaultArg&>(r) = mp::make_fault(legs, step, kind, joint, value, true);
             return r;
           }),
           arg("legs") = py::none(), arg("step") = 0, py::kw_only(), arg("kind") = mp::kLegFault,
           arg("joint") = py::none(), arg("value") = py::none())
      .def(py::pickle([](const mp::RecoveryArg& f) -> py::object { return mp::fault_state(f); },
                      [](const py::object& state) {
                        const py::tuple t = mp::pickled_tuple(state, 5, "Recovery");
                        mp::RecoveryArg r;
                        static_cast<mp::FaultArg&>(r) =
                            mp::make_fault(t[0], t[1], t[2], t[3], t[4], true);
                        return r;
                      }));

  py::class_<multicpg::robot::Terrain>(
      m, "Terrain",
      "The ground (robot/terrain.h, docs/faults.md): Terrain('slope:5') reads the CLI's text;\n"
      "Terrain.flat(), .slope(deg, heading_deg=0), .rough(height_m, seed=1) and\n"
      ".steps(height_m, depth_m) make one. Immutable, comparable, hashable and picklable;\n"
      "str() gives its text. Robot(terrain=...) takes one or its text.")
      .def(py::init([](py::object text) { return mp::terrain_arg(text, "text"); }),
           arg("text") = "flat")
      .def_static(
          "flat", [] { return multicpg::robot::Terrain{}; }, "level ground")
      .def_static(
          "slope",
          [](py::object deg, py::object heading) {
            multicpg::robot::Slope t;
            t.slope_deg = mp::real(deg, "deg", multicpg::robot::kSlopeLimits);
            t.heading_deg = mp::real(heading, "heading_deg", multicpg::robot::kHeadingLimits);
            return multicpg::robot::Terrain{t};
          },
          arg("deg"), arg("heading_deg") = 0.0,
          "a plane rising `deg` (0..30) towards `heading_deg` (+ = left of the start heading)")
      .def_static(
          "rough",
          [](py::object height, py::object seed) {
            multicpg::robot::Rough t;
            t.height_m = mp::real(height, "height_m", multicpg::robot::kBumpLimits);
            t.seed = mp::seed(seed, "seed");
            return multicpg::robot::Terrain{t};
          },
          arg("height_m"), arg("seed") = 1,
          "random bumps up to `height_m` (0.001..0.05 m), the same for the same seed")
      .def_static(
          "steps",
          [](py::object height, py::object depth) {
            multicpg::robot::Steps t;
            t.height_m = mp::real(height, "height_m", multicpg::robot::kBumpLimits);
            t.depth_m = mp::real(depth, "depth_m", multicpg::robot::kStepDepthLimits);
            return multicpg::robot::Terrain{t};
          },
          arg("height_m"), arg("depth_m"), "stairs of `height_m` rises and `depth_m` treads")
      .def_property_readonly(
          "kind",
          [](const multicpg::robot::Terrain& t) {
            return std::string(multicpg::robot::terrain_name(t));
          },
          "flat, slope, rough or steps")
      .def("__eq__",
           [](const multicpg::robot::Terrain& a, py::object b) -> py::object {
             if (!py::isinstance<multicpg::robot::Terrain>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(a == b.cast<multicpg::robot::Terrain>());
           })
      .def("__hash__",
           [](const multicpg::robot::Terrain& t) {
             return py::hash(py::str(multicpg::robot::terrain_text(t)));
           })
      .def("__str__",
           [](const multicpg::robot::Terrain& t) { return multicpg::robot::terrain_text(t); })
      .def("__repr__",
           [](const multicpg::robot::Terrain& t) {
             return "multicpg.Terrain('" + multicpg::robot::terrain_text(t) + "')";
           })
      .def(py::pickle(
          [](const multicpg::robot::Terrain& t) {
            return py::object(py::str(multicpg::robot::terrain_text(t)));
          },
          [](const py::object& text) { return mp::terrain_arg(text, "Terrain"); }));

  py::class_<mp::Robot, std::shared_ptr<mp::Robot>>(
      m, "Robot",
      "A robot (hexapod, quadruped or octopod) and its MuJoCo model, shared read-only by every\n"
      "Simulation of it. tunnel=True adds the 3.0 m x 1.2 m corridor of paper §5. control_dt\n"
      "(s per controller step), physics_dt (MuJoCo's step; None: the largest <= 5 ms that divides\n"
      "control_dt) and servo_gain (1/s; None: lpzrobots', scaled to control_dt) are the\n"
      "CLI's --control-dt, --physics-dt, --servo-gain. Robots are equal (and hash equal) when "
      "made\n"
      "of the same name and options; a State of one restores into a Simulation of any equal one.")
      .def(py::init([](py::object name, py::object tunnel, py::object control_dt,
                       py::object physics_dt, py::object servo_gain, py::object terrain,
                       py::object model, py::object body) {
             return mp::make_robot(name, tunnel, control_dt, physics_dt, servo_gain, terrain, model,
                                   body);
           }),
           arg("name") = "hexapod", py::kw_only(), arg("tunnel") = false,
           arg("control_dt") = sim::kDefaultControlDt, arg("physics_dt") = py::none(),
           arg("servo_gain") = py::none(), arg("terrain") = "flat",
           arg("model") =
               std::string(multicpg::robot::to_string(multicpg::robot::kDefaultBodyModel)),
           arg("body") = py::none())
      .def_static(
          "from_file",
          [](const std::string& path) {
            auto file = mp::load_robot_file(path);
            return mp::robot_of(file->file.layout, {}, file);
          },
          arg("path"),
          "The robot of a robot file (a TOML leg map over an MJCF, docs/robots.md \"Your robot:\n"
          "robot files\"), usable wherever a Robot is; its name is its layout's. Raises "
          "ValueError\n"
          "(one line: the file, the key, what is wrong) for a bad file.")
      .def_property_readonly(
          "file",
          [](const mp::Robot& r) -> py::object {
            if (!r.file) return py::none();
            return py::str(r.file->record.path);
          },
          "the robot file it was read from, or None for a built-in robot")
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
          "tunnel", [](const mp::Robot& r) { return r.options.scene.tunnel; },
          "whether the corridor of paper §5 is in the scene")
      .def_property_readonly(
          "terrain", [](const mp::Robot& r) { return r.options.scene.terrain; }, "the ground")
      .def_property_readonly(
          "model",
          [](const mp::Robot& r) {
            return std::string(multicpg::robot::to_string(r.options.model));
          },
          "the body model its parameters started from: 'paper-sim' or 'real' (docs/fidelity.md)")
      .def_property_readonly(
          "body",
          [](const mp::Robot& r) {
            const nlohmann::json params = r.options.body;
            return py::module_::import("json").attr("loads")(params.dump());
          },
          "the body's parameters (robot/body_params.h), as a dict")
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
          "settle_steps",
          [](const mp::Robot& r, py::object periods) {
            return multicpg::learning::locked_settle_steps(
                r.model->controller, mp::periods(r.morph(), periods, "periods"));
          },
          arg("periods"),
          "Unmeasured steps robust mode walks after setting these periods: the slowest CPG's\n"
          "lock plus the longest delay line (863 for a hexapod with a leg at 4).")
      .def(
          "mjcf", [](const mp::Robot& r) { return r.model->xml; },
          "The MJCF text of the model (what `multicpg model` prints).")
      .def("__eq__",
           [](const mp::Robot& a, py::object b) -> py::object {
             if (!py::isinstance<mp::Robot>(b))
               return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(a.key == b.cast<const mp::Robot&>().key);
           })
      .def("__hash__", [](const mp::Robot& r) { return py::hash(py::str(r.key)); })
      .def("__repr__", [](const mp::Robot& r) { return mp::robot_repr(r); })
      .def("__copy__", [](py::object self) { return self; })
      .def("__deepcopy__", [](py::object self, py::object) { return self; })
      .def(py::pickle([](const mp::Robot& r) -> py::object { return py::str(r.key); },
                      [](const py::object& key) {
                        const std::string text = mp::text(key, "Robot");
                        const nlohmann::json j =
                            nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
                        if (j.is_discarded())
                          mp::value_error("Robot", "not a pickled multicpg.Robot");
                        return mp::robot_from_key(j, "Robot");
                      }));

  py::class_<mp::State>(
      m, "State",
      "A complete copy of a Simulation at one step (Simulation.state()): MuJoCo's state, the\n"
      "controller, step counters, the fault schedule and the steering reflex. Restore it into a\n"
      "Simulation of an equal Robot to continue bit for bit from there. Immutable; picklable\n"
      "(to_bytes(), from_bytes()), so runs can be checkpointed and sent to other processes; a\n"
      "damaged or forged one raises ValueError.")
      .def_property_readonly(
          "robot", [](const mp::State& s) { return s.robot; }, "the Robot it walks")
      .def_property_readonly(
          "step_count", [](const mp::State& s) { return s.checkpoint->walked; },
          "controller steps walked (warm-up excluded)")
      .def_property_readonly(
          "time", [](const mp::State& s) { return s.checkpoint->state.data->time; },
          "simulated time, s")
      .def("to_bytes", &mp::state_bytes,
           "The state as bytes (sealed CBOR with a checksum; what pickle stores).")
      .def_static(
          "from_bytes", [](py::object data) { return mp::state_from_bytes(data, "data"); },
          arg("data"), "The State to_bytes() gave. Raises ValueError for damaged or foreign bytes.")
      .def("__copy__", [](py::object self) { return self; })
      .def("__deepcopy__", [](py::object self, py::object) { return self; })
      .def("__repr__",
           [](const mp::State& s) {
             return "<multicpg.State of " + mp::robot_repr(*s.robot) + " at step " +
                    std::to_string(s.checkpoint->walked) + ">";
           })
      .def(py::pickle([](const mp::State& s) -> py::object { return mp::state_bytes(s); },
                      [](const py::object& data) { return mp::state_from_bytes(data, "state"); }));

  py::class_<mp::Simulation>(
      m, "Simulation",
      "A simulated robot walking under its controller, stepped by the one stepping loop\n"
      "(sim::Stepper) as `multicpg walk` is.\n\n"
      "robot: a Robot or a robot name. periods: an int (every leg), a dict {'R1': 5} (legs not\n"
      "named: 4), one per leg in leg order, or 'R1=5,R2=4'; unequal periods free the clients.\n"
      "disable/disable_at: legs that fail at a step (a list of names or 'R1,R3').\n"
      "faults/recoveries: a list of multicpg.Fault / multicpg.Recovery or 'LEGS@STEP' text.\n"
      "warmup: controller steps before the robot moves (0 = cold; at most 100000000).\n"
      "seed (0..4294967295): the run's random stream (a noisy yaw sensor's draws).\n"
      "record=False keeps no per-step record. Same arguments, same trajectory, bit for bit.\n"
      "copy.deepcopy and pickle work (a pickled Simulation's record restarts at its state).")
      .def(py::init([](py::object robot, py::object periods, py::object disable,
                       py::object disable_at, py::object faults, py::object recoveries,
                       py::object warmup, py::object record, py::object seed) {
             return mp::make_simulation(robot, periods,
                                        mp::FaultArgs{disable, disable_at, faults, recoveries},
                                        warmup, record, seed);
           }),
           arg("robot") = "hexapod", py::kw_only(),
           arg("periods") = multicpg::robot::kDefaultPeriod, arg("disable") = py::none(),
           arg("disable_at") = 0, arg("faults") = py::none(), arg("recoveries") = py::none(),
           arg("warmup") = sim::kControllerWarmup, arg("record") = true, arg("seed") = 1)
      .def("step", &mp::Simulation::step, arg("n") = 1,
           "Walks n controller steps (faults applied on schedule). Releases the GIL. A run walks\n"
           "at most 100000000 steps in all.")
      .def("set_periods", &mp::Simulation::set_periods, arg("periods"),
           "Sets CPG periods (an int, {'R1': 5}, one per leg, or 'R1=5,L1=6'; legs a dict or\n"
           "text does not name keep theirs) and resets every CPG.")
      .def(
          "fail", [](mp::Simulation& s, py::object legs) { s.set_failed(legs, true); }, arg("legs"),
          "These legs fail from the next step on (a name, a list, or 'R1,R3').")
      .def(
          "recover", [](mp::Simulation& s, py::object legs) { s.set_failed(legs, false); },
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
      [](py::object sim, py::object width, py::object height, py::object caption) {
        if (!py::isinstance<mp::Simulation>(sim))
          mp::type_error("sim", "a multicpg.Simulation", sim);
        return sim.cast<mp::Simulation&>().render(width, height, caption);
      },
      arg("sim"), arg("width") = report::kDefaultFrameWidth,
      arg("height") = report::kDefaultFrameHeight, arg("caption") = "",
      "The simulation now as an H x W x 3 uint8 RGB array, drawn as films are (camera following\n"
      "the trunk, failed legs red, step and periods in the corner); sides 16..4096 px. Headless:\n"
      "EGL or OSMesa (MUJOCO_GL=egl|osmesa).");
  m.def(
      "film",
      [](py::object sim, py::object out, py::object steps, py::object speed, py::object width,
         py::object height) {
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
      [](py::object start, py::object end) {
        const sim::WindowMeasure w =
            sim::measure_window(mp::pose_arg(start, "start"), mp::pose_arg(end, "end"));
        return py::dict(arg("yaw_deg") = w.yaw_deg, arg("path_deg") = w.path_deg,
                        arg("forward_m") = w.forward_m, arg("lateral_m") = w.lateral_m);
      },
      arg("start"), arg("end"),
      "Yaw change (wrapped, + = left) and path angle of a window between two poses (x, y, yaw).");

  const auto learning_args = [](py::object mode, py::object steering, py::object hold_windows,
                                py::object monitor_windows, py::object period_learning,
                                py::object beta, py::object threshold, py::object window,
                                py::object settle, py::object max_trials, py::object seed) {
    return mp::LearningArgs{mode, steering,  hold_windows, monitor_windows, period_learning,
                            beta, threshold, window,       settle,          max_trials,
                            seed};
  };

  m.def(
      "learn",
      [learning_args](py::object robot, py::object disable, py::object disable_at,
                      py::object faults, py::object recoveries, py::object mode,
                      py::object steering, py::object hold_windows, py::object monitor_windows,
                      py::object period_learning, py::object beta, py::object threshold,
                      py::object window, py::object settle, py::object max_trials, py::object seed,
                      py::object record, py::object observer) {
        return mp::learn(
            robot, mp::FaultArgs{disable, disable_at, faults, recoveries},
            learning_args(mode, steering, hold_windows, monitor_windows, period_learning, beta,
                          threshold, window, settle, max_trials, seed),
            record, observer);
      },
      arg("robot") = "hexapod", py::kw_only(), arg("disable") = py::none(), arg("disable_at") = 0,
      arg("faults") = py::none(), arg("recoveries") = py::none(), arg("mode") = "robust",
      arg("steering") = "reflex", arg("hold_windows") = learning::kDefaultHoldWindows,
      arg("monitor_windows") = learning::kDefaultMonitorWindows, arg("period_learning") = true,
      arg("beta") = learning::kDefaultBeta, arg("threshold") = learning::kDefaultThresholdDeg,
      arg("window") = learning::kDefaultWindowSteps, arg("settle") = py::none(),
      arg("max_trials") = learning::kDefaultMaxTrials, arg("seed") = 1, arg("record") = false,
      arg("observer") = py::none(),
      "`multicpg learn`: legs fail and the robot learns periods that walk straight again.\n"
      "disable/disable_at/faults/recoveries as for Simulation. mode: 'paper' (paper §3) or\n"
      "'robust'; steering ('reflex' or 'off'), hold_windows, monitor_windows and\n"
      "period_learning are robust-mode arguments. beta (0..100), threshold (deg, 0.001..180),\n"
      "window (steps), settle (steps; None: the mode's), max_trials (1..100000), seed\n"
      "(0..4294967295). Returns the dict of `learn --json`, plus trace_arrays (trial, periods\n"
      "[trials,legs], deviation_deg, accepted, acceptance_probability) and, with record=True,\n"
      "path (time, x, y, yaw_deg). observer(trial) is called after every trial with episode,\n"
      "trial, step, periods, deviation_deg and accepted. Releases the GIL while it walks.");

  m.def("_run_experiment", &mp::run_experiment, arg("file_or_dict"), arg("is_document"),
        arg("jobs"), arg("out"),
        "Runs an experiment file or document (JSON text) into `out` (multicpg.experiment).");

  m.def(
      "tunnel",
      [learning_args](py::object robot_value, py::object disable, py::object periods,
                      py::object learn, py::object max_steps, py::object video, py::object mode,
                      py::object steering, py::object hold_windows, py::object monitor_windows,
                      py::object period_learning, py::object beta, py::object threshold,
                      py::object window, py::object settle, py::object max_trials, py::object seed,
                      py::object control_dt, py::object physics_dt, py::object servo_gain,
                      py::object observer, py::object faults, py::object terrain, py::object model,
                      py::object body, py::object scale_tunnel) {
        const bool learns = mp::flag(learn, "learn");
        if (learns && !periods.is_none()) {
          throw py::value_error(
              "periods: periods and learn=True exclude each other: learning "
              "finds the periods");
        }
        // The robot's kind or file; the tunnel's arguments set its simulation.
        const std::shared_ptr<mp::Robot> base = mp::robot_arg(robot_value);
        const std::shared_ptr<mp::Robot> robot =
            mp::robot_of(base->kind,
                         mp::sim_options(py::bool_(false), control_dt, physics_dt, servo_gain,
                                         terrain, model, body),
                         base->file);
        const multicpg::robot::Morphology& morph = robot->morph();
        const long steps = mp::whole(max_steps, "max_steps", sim::kRunStepsLimits);
        std::string film;
        if (!video.is_none()) film = mp::path(video, "video");
        if (!film.empty() && mp::named("video", [&] { return report::film_format(film); }) !=
                                 report::FilmFormat::video) {
          mp::value_error("video", "must name an .mp4 file");
        }
        sim::StartSpec start;
        if (!periods.is_none()) start.periods = mp::periods(morph, periods, "periods");
        std::optional<multicpg::learning::CompensationOptions> options;
        if (learns) {
          options = mp::learning_options(
              learning_args(mode, steering, hold_windows, monitor_windows, period_learning, beta,
                            threshold, window, settle, max_trials, seed));
        }
        const sim::FaultTimeline timeline =
            mp::fault_timeline(morph, mp::FaultArgs{disable, py::int_(0), faults, py::none()});
        const py::object callback = mp::callable_or_none(observer, "observer");
        multicpg::experiments::RunSpec spec = mp::run_spec(*robot, start, timeline, options);
        std::optional<multicpg::experiments::TunnelScale> scale;
        if (mp::flag(scale_tunnel, "scale_tunnel")) {
          try {
            scale = multicpg::experiments::scale_tunnel(spec);
          } catch (const multicpg::OptionError& e) {
            mp::value_error("scale_tunnel", e.key() + " " + e.what());
          }
        }
        return mp::tunnel(spec, steps, film, callback, scale);
      },
      py::kw_only(), arg("robot") = "hexapod", arg("disable") = py::none(),
      arg("periods") = py::none(), arg("learn") = false,
      arg("max_steps") = multicpg::experiments::kTunnelMaxSteps, arg("video") = py::none(),
      arg("mode") = "robust", arg("steering") = "reflex",
      arg("hold_windows") = learning::kDefaultHoldWindows,
      arg("monitor_windows") = learning::kDefaultMonitorWindows, arg("period_learning") = true,
      arg("beta") = learning::kDefaultBeta, arg("threshold") = learning::kDefaultThresholdDeg,
      arg("window") = learning::kDefaultWindowSteps, arg("settle") = py::none(),
      arg("max_trials") = learning::kDefaultMaxTrials, arg("seed") = 1,
      arg("control_dt") = sim::kDefaultControlDt, arg("physics_dt") = py::none(),
      arg("servo_gain") = py::none(), arg("observer") = py::none(), arg("faults") = py::none(),
      arg("terrain") = "flat",
      arg("model") = std::string(multicpg::robot::to_string(multicpg::robot::kDefaultBodyModel)),
      arg("body") = py::none(), arg("scale_tunnel") = false,
      "`multicpg tunnel`: the robot (a Robot's kind or robot file, a name or FILE.toml; its\n"
      "simulation set by the arguments here) walks the 3.0 m x 1.2 m corridor of paper §5 with "
      "the\n"
      "`disable`d legs and other `faults` (multicpg.Fault) from the start, on `terrain`, with\n"
      "the body `model` ('paper-sim' or 'real') and `body` parameters as for Robot, and\n"
      "given periods (as for Simulation; None: every leg 4), or (learn=True) after learning in\n"
      "the open field (learning arguments as for learn()). max_steps: 1..100000000. Returns the\n"
      "dict of `tunnel --json` plus path (time, x, y, yaw_deg) and, after learning,\n"
      "trace_arrays. video='run.mp4' films the tunnel walk; observer as for learn().\n"
      "scale_tunnel=True scales the tunnel to the robot's width (`tunnel --scale-tunnel`).");

  py::class_<mp::Annealer>(
      m, "Annealer",
      "The simulated annealing of paper §3 (Table 2), one call per step, with the draws of\n"
      "`multicpg learn --mode paper`: start from C0 = periods (as for Simulation; each working\n"
      "leg's in PERIOD_SET) measured at e_ref (deg, 0..180) with the `disabled` legs kept, then\n"
      "propose() a combination, walk it, decide(deviation).")
      .def(py::init([](py::object robot, py::object periods, py::object disabled, py::object e_ref,
                       py::object seed, py::object beta, py::object threshold,
                       py::object max_trials) {
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
      .def_property_readonly("trace", &mp::Annealer::trace, "one dict per decided trial");

  m.def(
      "_test_mujoco_error",
      [](const std::string& message) {
        const char* text = message.c_str();
        sim::mujoco_call([text] { mju_error(text); });
      },
      arg("message"),
      "Raises MuJoCo's fatal error inside a guarded call (a test of sim/mujoco_guard.h): it\n"
      "must come back as RuntimeError, the module usable.");
}
