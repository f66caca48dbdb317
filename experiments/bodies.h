// The body a run walks (body/body.h), as its RunSpec says: the simulation of its robot, or the real
// robot of its hardware file (docs/hardware.md). Every run (walk, learn, tunnel; experiments/
// body_runs.h) opens its body here and is then written once for both. Checks that a run on a real
// robot needs are all made here, before a port opens.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "body/body.h"
#include "experiments/run_spec.h"
#include "hw/hardware_body.h"
#include "hw/hardware_file.h"
#include "sim/sim.h"
#include "sim/sim_body.h"
#include "sim/stepper.h"

namespace multicpg::experiments {

// What the controller of `robot` drives, from its description alone (no MuJoCo model compiled):
// the controller of its layout and options, each joint's window (the built-in robot's joint
// limits, or its robot file's) and the control period.
hw::BodyMap body_map(const RobotSpec& robot);

// What a run on a real robot needs, checked before a port opens: its hardware file read for the
// run's leg layout, faults the hardware can enact, a learning mode its senses allow.
struct HardwareSetup {
  hw::HardwareFile file;
  hw::BodyMap map;
  hw::Pacing pacing = hw::Pacing::real_time;
};
// Throws OptionError ("hardware.file", "faults", "learning.mode") naming what is wrong. `spec`
// must have hardware.
HardwareSetup hardware_setup(const RunSpec& spec);

// A run on a real robot seen by the simulation's observers (the 3D replay, --plot, a film): each
// step's joint targets and sensed trunk pose posed on the robot's model, by kinematics alone (no
// physics: the feet's contacts are not known, the trunk's height and tilt are the start's; a robot
// that senses no position walks in place). Its faults come as the run's timeline brings them.
class HardwareView final : public hw::StepSink {
 public:
  // `model`: the robot's simulation (make_model of the run's robot); `observer` sees the run.
  HardwareView(const sim::SimModel& model, const body::StartSpec& start, body::FaultTimeline faults,
               sim::Observer& observer);
  HardwareView(const HardwareView&) = delete;
  HardwareView& operator=(const HardwareView&) = delete;
  void row(const hw::StepRow& row) override;
  void event(const body::Event& event) override;

 private:
  const sim::SimModel& model_;
  sim::Observer& observer_;
  sim::SimState state_;
  bool started_ = false;
};

// A body opened for one run.
class RunBody {
 public:
  virtual ~RunBody() = default;
  virtual body::Body& body() = 0;
  // Where the trunk is along the ground of the simulation's scene (sim::trunk_position), and
  // whether the robot touches the tunnel's walls; nothing for a real robot (only what it senses).
  virtual std::optional<double> along_ground_m() const { return std::nullopt; }
  virtual bool touches_wall() const { return false; }
  // The heading of the tunnel's axis: the simulated scene's (its x axis, 0 deg); nothing for a
  // real robot, whose tunnel runs along the heading it starts the tunnel with.
  virtual std::optional<double> corridor_heading_deg() const { return std::nullopt; }
  // The hardware record (hw::hardware_json) of a real robot; null for the simulation.
  virtual nlohmann::json hardware() const { return nullptr; }
  // A run that ended well: a real robot stops in its safe posture, naming why; throws
  // hw::HardwareStop when that stop could not be sent (its port failed after the last step).
  virtual void finish(const std::string& /*why*/) {}
  // A run a fault or a signal ended: a real robot is stopped (if it was not yet); the record of
  // the run so far keeps what the body saw.
  virtual void stopped(const std::exception& /*cause*/) {}
  virtual bool is_hardware() const { return false; }
  // The simulation's state at the end (moved out); empty for a real robot.
  virtual sim::SimState final_state() { return {}; }
  // What a real robot that a fault or a signal stopped leaves (docs/hardware.md "Outputs"):
  // "status": "stopped", the cause, the robot, the steps walked, the learner's trials as they were
  // decided and every event, the run's learning options and the hardware record. Null for the
  // simulation.
  virtual nlohmann::json stopped_record(const RunSpec& /*spec*/) const { return nullptr; }
};

// Where the record of a real robot's stopped run goes (RunBody::stopped_record).
using StoppedSink = std::function<void(const nlohmann::json& record)>;

// What watches a run: the simulation's observer and per-step record, or a real robot's step sink
// and (through HardwareView) the same observer.
struct Watchers {
  sim::Observer* observer = nullptr;  // every step and event (films, replays, plots, Python)
  sim::WalkRecord* record = nullptr;  // the simulation's every step
  bool record_joints = true;
  hw::StepSink* steps = nullptr;  // a real robot's every step (hardware.csv)
  StoppedSink stopped;            // a real robot's record when a fault or a signal stops it
};

// Runs `run` (on `body`); when it throws (a fault, a signal), a real robot is stopped and its
// record so far goes to `stopped` before the exception goes on.
template <class Run>
auto guarded(RunBody& body, const RunSpec& spec, const StoppedSink& stopped, Run&& run) {
  try {
    return run();
  } catch (const std::exception& e) {
    body.stopped(e);
    if (stopped && body.is_hardware()) stopped(body.stopped_record(spec));
    throw;
  }
}

// Opens spec's body: a Stepper on `model` (spec.robot's simulation, its scene as the run needs)
// started with spec.start and spec.faults; or, with spec.hardware, the robot of `setup` (from
// hardware_setup), `model` then only posing its steps for the observer. Throws RuntimeFailure
// when a real robot fails its start-up check.
std::unique_ptr<RunBody> open_body(const RunSpec& spec, const sim::SimModel& model,
                                   const HardwareSetup* setup, const Watchers& watchers);

// The simulated body of a stepper, for callers that step it themselves.
std::unique_ptr<RunBody> simulated_body(sim::Stepper& stepper);

}  // namespace multicpg::experiments
