// What a run needs of a body that walks, whatever it is (docs/development.md "Layout"): the
// simulation (sim::SimBody, MuJoCo) and a real robot over a serial bus (hw::HardwareBody) both
// are one. Learning (learning/compensation.h), the walk, the tunnel and the learner's course walk
// (learning/course_walk.h) read a body only through this, so a run is written once for every
// body, and a third body (another simulator, another robot) is one class.
#pragma once

#include <optional>

#include "body/deviation.h"
#include "body/events.h"
#include "neural/controller.h"

namespace multicpg::body {

// A point in the ground plane, m.
struct Position2 {
  double x = 0.0;
  double y = 0.0;
};

// What a body senses, as it senses it: the orientation sensor's yaw (a drifting or noisy sensor's
// error included) and, where the body senses it, the trunk's position (odometry; in simulation the
// trunk's true position). Never a made-up value: a robot with an orientation sensor only has no
// position (docs/hardware.md "What the learner reads").
struct Senses {
  double yaw_deg = 0.0;  // (-180, 180], + = left
  std::optional<Position2> position;
  // As a Pose2 for the course geometry (body/deviation.h): x and y NaN without a position.
  Pose2 pose() const;
};

class Body {
 public:
  virtual ~Body() = default;
  // One controller step and what it drives (the physics, or the servos).
  virtual void step() = 0;
  virtual Senses senses() const = 0;
  // Controller steps taken since the start (the warm-up excluded).
  virtual long step_count() const = 0;
  virtual neural::ControllerState& controller() = 0;
  virtual const neural::ControllerModel& controller_model() const = 0;
  // The run's faults (docs/faults.md "When faults strike"): the body applies them before the
  // steps they name, counted from its start, and a learner reads from it what came.
  virtual const FaultSchedule& faults() const = 0;
  // Shows what the learner is doing to whoever watches (a film, the viewer, Python, a record).
  virtual void emit(const Event& /*event*/) {}

  Pose2 pose() const { return senses().pose(); }
};

}  // namespace multicpg::body
