// What a simulation is made with (SimOptions): its time steps, servo gain, scene, controller
// parameters and body, their documented ranges, and how the physics step divides the control step.
#pragma once

#include "common/limits.h"
#include "neural/controller.h"
#include "robot/body_models.h"
#include "robot/body_params.h"
#include "robot/mjcf.h"
#include "robot/morphology.h"

namespace multicpg::sim {

// One controller step of simulated time: 0.037 s, the paper's 27 Hz (paper §4).
inline constexpr double kDefaultControlDt = 0.037;
// Largest default physics step (docs/robots.md "Integrator and time steps").
inline constexpr double kMaxDefaultPhysicsDt = 0.005;
// How close control_dt / physics_dt must be to a whole number (relative).
inline constexpr double kStepRatioTolerance = 1e-6;
// The controller step of the authors' simulation (docs/robots.md "Servos"), at which its servo gain
// K = maxVel / 2 was set.
inline constexpr double kReferenceControlDt = 0.1;

// The largest physics step <= kMaxDefaultPhysicsDt that divides control_dt exactly
// (0.037 s -> 0.037 / 8 = 0.004625 s).
double default_physics_dt(double control_dt);

// Most physics steps per controller step: 10^6 (a 0.037 s step at 37 ns), far beyond any useful
// ratio and well inside an int.
inline constexpr int kMaxSubsteps = 1'000'000;

// Physics steps per controller step. Throws BadInput unless both steps are positive and
// control_dt / physics_dt is a whole number within kStepRatioTolerance, at most kMaxSubsteps.
int physics_substeps(double control_dt, double physics_dt);

// Documented ranges. The controller step: 0.1 ms to 1 s around the paper's
// 37 ms; the physics step: down to 1 us (0 = default); servo gain up to 10^4 1/s (0 = default),
// past which a servo reaches its target within one 5 ms physics step anyway.
inline constexpr Limits<double> kControlDtLimits{1e-4, 1.0};
inline constexpr Limits<double> kPhysicsDtLimits{0.0, 0.1};
inline constexpr double kMinPhysicsDt = 1e-6;
inline constexpr Limits<double> kServoGainLimits{0.0, 1e4};
// The tunnel of the paper is 3 m x 1.2 m (paper §4); any other stays within a room's size.
inline constexpr Limits<double> kTunnelLengthLimits{0.1, 100.0};
inline constexpr Limits<double> kTunnelWidthLimits{0.1, 10.0};

struct SimOptions {
  double control_dt = kDefaultControlDt;  // s
  double physics_dt = 0.0;                // s; 0 = default_physics_dt(control_dt)
  // Servo gain K (1/s). 0 = lpzrobots' K scaled by kReferenceControlDt / control_dt, so a
  // servo closes the same share of its error per controller step as in lpzrobots
  // (14.15 1/s at 0.037 s; docs/robots.md).
  double servo_gain = 0.0;
  robot::Scene scene;
  neural::ControllerParams controller;
  // The physical parameters (robot/body_params.h), and the named model they started from
  // (robot/body_models.h; recorded, the values are what counts).
  robot::BodyModel model = robot::kDefaultBodyModel;
  robot::BodyParams body;

  bool operator==(const SimOptions&) const = default;
};

// The physics step the options give: theirs, or with 0 the default for their control step.
double resolved_physics_dt(const SimOptions& options);

// Throws OptionError (key "control_dt", "controller.cpg.w11", "body.total_mass", ...) for a value
// outside its range, a physics step below kMinPhysicsDt or one that does not divide the control
// step (physics_substeps).
void validate(const SimOptions& options);
// The same, and the body's leg postures name legs of `kind` ("body.leg_postures[0].leg").
void validate(const SimOptions& options, robot::RobotKind kind);

}  // namespace multicpg::sim
