// The one stepping loop: a simulated robot started as it should be, its faults applied
// on schedule, every step recorded and shown to an observer. walk, the tunnel, learning, films,
// the viewer and the Python API all step through it, so they agree on how a run starts and what
// happened when.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "body/deviation.h"
#include "body/events.h"
#include "body/start.h"
#include "common/limits.h"
#include "sim/sim.h"
#include "sim/walk_record.h"

namespace multicpg::sim {

// Sees every step and every event of a run; the default does nothing.
class Observer {
 public:
  virtual ~Observer() = default;
  // The start state, after the warm-up (row 0 of a record), before the first step.
  virtual void on_start(const SimModel& /*model*/, const SimState& /*state*/) {}
  virtual void on_step(const SimModel& /*model*/, const SimState& /*state*/) {}
  virtual void on_event(const SimModel& /*model*/, const SimState& /*state*/,
                        const body::Event& /*event*/) {}
};

// Several observers as one, told in order (null ones are skipped).
class Observers final : public Observer {
 public:
  explicit Observers(std::vector<Observer*> all) : all_(std::move(all)) {}
  void on_start(const SimModel& model, const SimState& state) override {
    for (Observer* o : all_)
      if (o != nullptr) o->on_start(model, state);
  }
  void on_step(const SimModel& model, const SimState& state) override {
    for (Observer* o : all_)
      if (o != nullptr) o->on_step(model, state);
  }
  void on_event(const SimModel& model, const SimState& state, const body::Event& event) override {
    for (Observer* o : all_)
      if (o != nullptr) o->on_event(model, state, event);
  }

 private:
  std::vector<Observer*> all_;
};

// The state a run starts from before its warm-up: make_sim_state, its controller
// body::start_controller's (a period outside 1-9 throws BadInput).
SimState start_walk_state(const SimModel& model, const std::vector<int>& periods);

// Everything a Stepper's run is between two steps (the Python API's state()/restore()).
struct StepperCheckpoint {
  SimState state;  // with its faults
  long walked = 0;
};

class Stepper {
 public:
  // Makes the start state: make_sim_state, `start.periods`, the faults due at step 0, then the
  // warm-up (so a leg failed from the start is already still while the controller warms up).
  // `observer` and `record` may be null and must outlive the stepper.
  Stepper(const SimModel& model, const body::StartSpec& start, body::FaultTimeline faults = {},
          Observer* observer = nullptr, WalkRecord* record = nullptr, bool record_joints = true);
  // Goes on from `checkpoint` (of a stepper of the same model), as restore() on a new stepper
  // but without making and warming up a start state first; nothing recorded.
  static Stepper resume(const SimModel& model, const StepperCheckpoint& checkpoint,
                        Observer* observer = nullptr);

  // Applies the faults due before this step, then one controller step with its physics
  // (sim_step), records it and shows it to the observer. Throws Interrupted when SIGINT or
  // SIGTERM asked the process to stop (common/interrupt.h): every run stops within a step.
  void step();
  void steps(long n);
  // Tells the observer (the learner's detections, trials and episodes).
  void emit(body::Event event);
  // A fault (or recovery) now, before the next step (its step is set to it), told to the
  // observer like a scheduled one. Throws BadInput (sim::validate's message) when it cannot
  // happen now (a leg that has already failed, a recovery of what is not struck, failing every
  // leg). Scheduled faults still come as planned.
  void apply_now(body::Fault fault);
  // A deep copy of the run (copy_sim_state, its faults with it), and back: after restore
  // the stepper continues exactly as it did from the checkpoint. The checkpoint must come from a
  // stepper of the same model; the record (if any) is not rewound.
  StepperCheckpoint checkpoint() const;
  void restore(const StepperCheckpoint& checkpoint);
  // Called before every step, after the faults: sets the controller's drive inputs from the
  // sensors (the steering reflex of learning/steering.h). Empty = forward walking as it is.
  void set_before_step(std::function<void(Stepper&)> hook) { before_step_ = std::move(hook); }

  const SimModel& model() const { return model_; }
  SimState& state() { return state_; }
  const SimState& state() const { return state_; }
  long step_count() const {
    return walked_;
  }  // controller steps since the start (warm-up excluded)
  // The trunk's true pose.
  body::Pose2 pose() const;
  // The pose as the robot senses it: the true position (odometry) and the yaw its sensor reads
  // (sim::sensed_yaw_deg: a drifting or noisy sensor's error included). What the learner and the
  // steering reflex see.
  body::Pose2 sensed_pose() const;
  // The run's faults: the timeline, what has come, what is in force, the legs failed now.
  const body::FaultSchedule& faults() const { return state_.faults.schedule; }

 private:
  struct Resumed {};
  Stepper(const SimModel& model, const StepperCheckpoint& checkpoint, Observer* observer, Resumed);
  void apply_due_faults();
  // Applies the physics of the faults that came from `first` on and shows them to the observer.
  void take_faults(std::size_t first);

  const SimModel& model_;
  SimState state_;
  std::function<void(Stepper&)> before_step_;
  Observer* observer_;
  WalkRecord* record_;
  bool record_joints_;
  long walked_ = 0;
};

}  // namespace multicpg::sim
