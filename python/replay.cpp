#include "python/replay.h"

#include <optional>
#include <string>

#include "common/atomic_file.h"
#include "common/errors.h"
#include "common/sealed_cbor.h"
#include "experiments/run_robot.h"
#include "experiments/run_spec.h"
#include "learning/steering.h"
#include "python/args.h"
#include "python/robots.h"
#include "python/watch.h"
#include "report/replay/page.h"
#include "report/replay/recording.h"
#include "report/replay/rerun.h"
#include "sim/checkpoint.h"
#include "sim/json.h"
#include "sim/sim_body.h"
#include "sim/stepper.h"
#include "sim/walk.h"

// GCC 12 warns that the type macro's default object's std::optional may be uninitialized where
// it inlines from_json (a known false positive with std::optional), as report/replay/rerun.cpp.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "learning/json.h"
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace multicpg::python {
namespace {

using nlohmann::json;

// What Simulation.state().to_bytes() holds (the module's State, python/state.cpp).
constexpr const char* kStateFormat = "multicpg state";
constexpr int kStateVersion = 1;

// The simulation a robot key describes ({"robot", "robot_file", "sim"}: a Robot's pickled form).
experiments::RobotSpec robot_spec(const json& key, std::string_view name) {
  experiments::RobotSpec spec = recorded_robot(key, name);
  spec.sim = key.at("sim").get<sim::SimOptions>();
  return spec;
}

// Shows a run to the recorder only once it is told to (after the stepper took a saved state).
class Gate final : public sim::Observer {
 public:
  explicit Gate(sim::Observer& next) : next_(next) {}
  void on_start(const sim::SimModel& m, const sim::SimState& s) override {
    if (open) next_.on_start(m, s);
  }
  void on_step(const sim::SimModel& m, const sim::SimState& s) override {
    if (open) next_.on_step(m, s);
  }
  void on_event(const sim::SimModel& m, const sim::SimState& s, const body::Event& e) override {
    if (open) next_.on_event(m, s, e);
  }
  bool open = false;

 private:
  sim::Observer& next_;
};

// Writes `html` to `out` (when given) atomically.
void write_page(const std::string& html, py::handle out) {
  if (out.is_none()) return;
  const std::string file = path(out, "path");
  named("path", [&] {
    report::check_replay_path(file);
    write_file_atomic(file, html);
    return 0;
  });
}

// The next `steps` steps of the simulation saved in `state` (State.to_bytes()), walked on a copy
// as the Simulation walks them (its steering reflex with the default parameters), recorded;
// returns the page and the trunk's pose (x, y, yaw) at the end, which multicpg.replay compares
// with the Simulation's after it walked the same steps.
py::tuple replay_simulation(py::handle state_bytes, py::handle steps_arg, py::handle out,
                            py::handle title_arg) {
  const long steps = whole(steps_arg, "steps", report::kReplayStepLimits);
  const std::string title = text(title_arg, "title");
  const std::string bytes = state_bytes.cast<py::bytes>();
  const json document = named("sim", [&] { return unseal_cbor(bytes); });
  if (!document.is_object() || document.value("format", "") != kStateFormat ||
      document.value("version", 0) != kStateVersion) {
    value_error("sim", "not a multicpg.Simulation of this version");
  }
  const experiments::RobotSpec walked = robot_spec(document.at("robot"), "sim");
  std::string html;
  body::Pose2 end;
  // Ctrl-C stops the walk between two steps (KeyboardInterrupt); nothing is written then.
  Watch watch(py::bool_(false), "replay", steps);
  {
    const py::gil_scoped_release release;
    const sim::SimModel model = experiments::make_model(walked);
    const sim::StepperCheckpoint checkpoint =
        sim::checkpoint_from_json(model, document.at("checkpoint"));
    report::ReplayRecorder recorder(checkpoint.walked);
    Gate gate(recorder);
    sim::Observers watched({&gate, &watch});
    sim::Stepper stepper(model, body::StartSpec{{}, 0}, body::FaultTimeline{}, &watched);
    stepper.restore(checkpoint);
    std::optional<learning::SteeringState> steering;
    if (!document.at("steering").is_null()) {
      steering = document.at("steering").get<learning::SteeringState>();
      stepper.set_before_step([&steering](sim::Stepper& s) {
        sim::SimBody body(s);
        learning::steer_body(learning::SteeringParams{}, *steering, body);
      });
    }
    gate.open = true;
    recorder.on_start(model, stepper.state());
    stepper.steps(steps);
    html = report::replay_html(recorder.recording(), title);
    end = stepper.pose();
  }
  write_page(html, out);
  return py::make_tuple(py::str(html), py::make_tuple(end.x, end.y, end.yaw_deg));
}

// The run of a learn() result (its JSON text), made again with the simulation of `robot` (a
// Robot's pickled key, or None for the default one) and recorded.
py::str replay_result(py::handle result, py::handle robot_key, py::handle out,
                      py::handle title_arg) {
  const std::string result_text = text(result, "result");
  std::optional<std::string> title;
  if (!title_arg.is_none()) title = text(title_arg, "title");
  sim::SimOptions options;
  if (!robot_key.is_none()) {
    options = robot_spec(json::parse(text(robot_key, "robot")), "robot").sim;
  }
  std::string html;
  Watch watch(py::bool_(false), "replay", 0);  // Ctrl-C stops the run; no page is written then
  {
    const py::gil_scoped_release release;
    const json saved = json::parse(result_text);
    const report::RerunReplay replay = named(
        "result", [&] { return report::rerun_learning(saved, "the result", options, &watch); });
    html = report::replay_html(replay.recording, title.value_or(replay.title));
  }
  write_page(html, out);
  return py::str(html);
}

}  // namespace

void register_replay(py::module_& m) {
  using py::arg;
  m.def("_replay_simulation", &replay_simulation, arg("state"), arg("steps"), arg("out"),
        arg("title"),
        "The page of the next `steps` steps of a Simulation's State bytes, and the pose they end "
        "in (multicpg.replay).");
  m.def("_replay_result", &replay_result, arg("result"), arg("robot"), arg("out"), arg("title"),
        "The page of a learn() result (JSON text) made again with a Robot's pickled key's "
        "simulation (multicpg.replay).");
}

}  // namespace multicpg::python
