// walk, learn and tunnel on a real robot (docs/hardware.md "Running it"): a run description
// (experiments::RunSpec) made to run through a hardware file, with what it records: the learner's
// result or, when the robot was stopped, its trace so far; the loop's timing and the link's errors.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "body/deviation.h"
#include "experiments/run_spec.h"
#include "hw/hardware_body.h"
#include "hw/hardware_file.h"
#include "learning/compensation.h"
#include "sim/sim.h"

namespace multicpg::hw {

// --hardware FILE.toml and --lock-step.
struct HardwareFlags {
  std::string file;
  bool lock_step = false;
  bool given() const { return !file.empty(); }
};

// The controller and joint windows of `model`'s robot (what the simulation drives).
BodyMap body_map(const sim::SimModel& model);

// What a run needs to drive its robot through a hardware file, checked before anything opens a
// port: the file read for the run's leg layout, faults the hardware can enact, a learning mode its
// senses allow. Throws BadInput (one line: file and key, or the flag) otherwise.
struct HardwareSetup {
  HardwareFile file;
  BodyMap body;
  Pacing pacing = Pacing::real_time;
};
HardwareSetup hardware_setup(const experiments::RunSpec& spec, const HardwareFlags& flags);

// What the run recorded of the hardware: the file (path, name, checksum, protocol), the pacing,
// the loop's timing, the link errors by kind, the targets clamped, and how it stopped.
nlohmann::json hardware_json(const HardwareSetup& setup, const HardwareBody& walker);

// Every step to a CSV: step, time, yaw (and position when sensed), each joint's target and, where
// the hardware reports them, its angle and each foot's contact.
class StepCsv final : public StepSink {
 public:
  StepCsv(std::ostream& out, const HardwareFile& file, const robot::Morphology& morph);
  void row(const StepRow& row) override;

 private:
  std::ostream& out_;
  const HardwareFile& file_;
};

// What a run on hardware left when a stop (a fault, a signal) ended it: the record so far
// ("status": "stopped", the cause, the learner's trials as they were decided, the hardware).
using StoppedSink = std::function<void(const nlohmann::json& record)>;

// learn: learning::compensate on the robot. On a stop, `stopped` gets the record so far before the
// HardwareStop (or Interrupted) goes on.
struct HardwareLearning {
  learning::LearningResult result;
  nlohmann::json hardware;
};
HardwareLearning learn_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                                   const StoppedSink& stopped, StepSink* steps = nullptr);

// walk: `settle` steps, then `steps` measured in windows of `window` steps (the yaw change; the
// path angle only where the position is sensed).
struct HardwareWalk {
  long steps = 0;
  std::vector<body::WindowMeasure> windows;
  double final_yaw_deg = 0.0;
  nlohmann::json hardware;
};
HardwareWalk walk_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                              long settle, long steps, long window, const StoppedSink& stopped,
                              StepSink* sink = nullptr);

// tunnel: with learning options, learning first (as learn), then the learned controller walks on
// for the tunnel: `max_steps`, or until the trunk is `length_m` along its start heading where the
// position is sensed. Without position nobody can tell whether it passed: `passed` is empty.
struct HardwareTunnel {
  std::optional<learning::LearningResult> learned;
  std::vector<int> periods;
  long steps = 0;
  double yaw_change_deg = 0.0;
  std::optional<double> forward_m;
  std::optional<double> lateral_m;
  std::optional<double> deviation_deg;  // Table 1's angle, from the position
  std::optional<bool> passed;
  nlohmann::json hardware;
};
HardwareTunnel tunnel_on_hardware(const experiments::RunSpec& spec, const HardwareSetup& setup,
                                  long max_steps, double length_m, const StoppedSink& stopped);

}  // namespace multicpg::hw
