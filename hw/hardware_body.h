// A real robot as the learner's walker (body::Body): each control step computes the
// controller as the simulation does (neural::controller_step, the joint windows of the robot's
// leg map), clamps the joint targets to the hardware file's limits, sends them over the serial
// bus, and reads back the yaw (and joint angles and foot contacts where the hardware reports
// them), paced at the control rate in real time, or in lock-step with an emulator. Bus errors,
// a silent yaw sensor or a signal stop the robot in its safe posture (or torque off) within the
// step they are detected in (docs/hardware.md "Safety").
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "body/body.h"
#include "body/events.h"
#include "body/start.h"
#include "common/enum_names.h"
#include "hw/bus.h"
#include "hw/hardware_file.h"
#include "hw/loop_timing.h"
#include "neural/controller.h"

namespace multicpg::hw {

// What the controller drives: its model and each leg's joint windows (the angles commands -1..1
// span; robot/joint_map.h), as the simulation of the same robot has them.
struct BodyMap {
  neural::ControllerModel controller;
  std::vector<std::array<robot::AngleRange, robot::kJointsPerLeg>> windows;
  double control_dt = 0.0;  // s: the control period (27 Hz: 0.037 s)
};

enum class Pacing {
  real_time,  // one step per control period on the monotonic clock
  lock_step,  // each step as soon as the last one's answers came (rehearsal with the emulator)
};
// Each pacing's name in a run's record ("pacing").
inline constexpr auto kPacingNames =
    enum_names<Pacing>({{Pacing::real_time, "real_time"}, {Pacing::lock_step, "lock_step"}});

// One control step as it happened (the per-step record, docs/hardware.md "Outputs").
struct StepRow {
  long step = 0;
  double time_s = 0.0;  // monotonic, when the command went out
  body::Pose2 pose;     // x, y NaN when the position is not sensed
  std::vector<std::array<double, robot::kJointsPerLeg>> targets;  // rad, clamped
  Feedback feedback;
  int errors = 0;  // link errors of this step
};

// Sees every step (to stream it to a file) and every event of the run (its faults as they come,
// the learner's detections, trials and episodes).
class StepSink {
 public:
  virtual ~StepSink() = default;
  virtual void row(const StepRow& row) = 0;
  virtual void event(const body::Event& /*event*/) {}
};

// How a run on hardware stopped.
struct StopRecord {
  std::string cause;          // what stopped the run
  std::string message;        // the one line: the cause, the step and what the robot was commanded
  bool fault = false;         // a fault (or a signal) stopped it, not the end of the run
  long step = 0;              // steps walked
  double detected_s = 0.0;    // monotonic: when the cause was seen
  double commanded_s = 0.0;   // monotonic: when the stop's command went out (0: it could not)
  std::string command_error;  // why the stop's command could not be sent
};

// A run stopped by a fault: the robot was commanded to its stop action. RuntimeFailure, so the
// command exits 1 with its one line.
class HardwareStop : public RuntimeFailure {
 public:
  explicit HardwareStop(const StopRecord& record) : RuntimeFailure(record.message) {}
};

class HardwareBody final : public body::Body {
 public:
  // Opens the ports and runs the start-up check (every servo or the board answers, the yaw
  // arrives) before anything moves; then starts the controller as every body does (body/start.h:
  // `start`'s periods, the faults due at step 0, the warm-up). `faults` must hold leg faults only
  // (the controller's; require_hardware_faults). Throws RuntimeFailure naming what failed the
  // check.
  HardwareBody(const HardwareFile& file, BodyMap body, const body::StartSpec& start,
               body::FaultTimeline faults, Pacing pacing, StepSink* sink = nullptr);
  HardwareBody(const HardwareBody&) = delete;
  HardwareBody& operator=(const HardwareBody&) = delete;
  // Commands the stop action if no stop did yet.
  ~HardwareBody() override;

  // One control step. Throws HardwareStop after commanding the stop when a fault is detected,
  // Interrupted (after the same) on SIGINT or SIGTERM.
  void step() override;
  void steps(long n);
  // The orientation sensor's yaw; x and y are the trunk's position only when the yaw line reports
  // it (POSE lines), NaN otherwise: never made up.
  body::Senses senses() const override {
    return {pose_.yaw_deg, pose_.has_position() ? std::optional<body::Position2>({pose_.x, pose_.y})
                                                : std::nullopt};
  }
  long step_count() const override { return walked_; }
  neural::ControllerState& controller() override { return controller_; }
  const neural::ControllerModel& controller_model() const override { return body_.controller; }
  const body::FaultSchedule& faults() const override { return faults_; }
  void emit(const body::Event& event) override;

  // Commands the stop action (the safe posture, or torque off) once; later calls do nothing.
  void stop(const std::string& cause, bool fault = false);
  const std::optional<StopRecord>& stopped() const { return stopped_; }
  bool senses_position() const { return file_.senses_position(); }
  LoopTiming timing() const { return clock_.timing(); }
  // Link errors by kind: the servos' bus, then the yaw line.
  LinkErrors bus_errors() const { return bus_->errors(); }
  LinkErrors yaw_errors() const;
  long clamped_targets() const { return clamped_; }
  // The learner's events (detection, trials, episodes), as they came.
  const std::vector<body::Event>& events() const { return events_; }

 private:
  void start_check();
  JointCounts counts(const std::vector<std::array<double, robot::kJointsPerLeg>>& angles);
  [[noreturn]] void fail(const std::string& cause);
  bool read_yaw(std::vector<StepError>& errors, const Feedback& feedback);

  const HardwareFile& file_;
  BodyMap body_;
  neural::ControllerState controller_;
  body::FaultSchedule faults_;
  std::unique_ptr<Bus> bus_;
  std::unique_ptr<YawLine> yaw_;
  LoopClock clock_;
  StepSink* sink_;
  body::Pose2 pose_;
  long walked_ = 0;
  long clamped_ = 0;
  int bad_steps_ = 0;            // bus: steps in a row with an error
  int silent_steps_ = 0;         // yaw: steps in a row without a reading
  LinkErrors board_yaw_errors_;  // an AMOSII yaw input that read no heading
  std::vector<body::Event> events_;
  std::optional<StopRecord> stopped_;
};

// Throws BadInput unless every fault of `faults` can be enacted on hardware: the paper's leg
// fault (the controller holds the leg's posture); the others are a real robot's physics or
// sensors.
void require_hardware_faults(const robot::Morphology& morph, const body::FaultTimeline& faults);

}  // namespace multicpg::hw
