// What each fault kind (body/faults.h) does to the physics and the sensors, and how a recovery
// undoes it exactly (docs/faults.md):
// - leg: nothing here; the controller holds the leg's posture (neural::set_disabled);
// - locked: the joint's servo gives no torque and the joint's limits close on its lock angle, so
//   MuJoCo's limit constraint holds it as a seized gear would;
// - passive: the joint's servo gives no torque;
// - weak: the servo's torque bound times the factor;
// - short: the tibia's capsule shortened (its mass and inertia with it) and the foot moved in;
// - slip: the foot's friction with the ground times the factor;
// - drift, noise: the yaw the learner and the steering reflex read (sensed_yaw_deg) drifts and
//   jitters; the true yaw does not.
#pragma once

#include "body/events.h"
#include "sim/sim.h"

namespace multicpg::sim {

// Applies the effect of a fault or recovery that has just come: state.faults.schedule has taken
// it (so it is valid, and the faults in force are those after it).
void apply_fault_effect(const SimModel& model, SimState& state, const body::Fault& fault);

// One controller step of the yaw sensor's error: its drift grows, a new noise draw (call after
// each sim_step).
void advance_sensor(const SimModel& model, SimState& state);

// The yaw the sensor reads: the true yaw (trunk_yaw_deg) with the drift and noise of the sensor
// faults in force, wrapped to (-180, 180].
double sensed_yaw_deg(const SimModel& model, const SimState& state);

}  // namespace multicpg::sim
