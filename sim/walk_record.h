// The per-step sensor record of a run (docs/robots.md "Sensors, start, settling": trunk pose and
// yaw, every joint's command, target and actual angle, foot contact per leg).
#pragma once

#include <cstddef>
#include <vector>

#include "sim/sim.h"

namespace multicpg::sim {

// Row k is the state after k controller steps (row 0 = the start).
struct WalkRecord {
  std::size_t legs = 0;
  std::vector<double> time;     // s
  std::vector<double> x, y, z;  // trunk position, m
  std::vector<double> yaw_deg;  // front trunk yaw, (-180, 180]
  // What the yaw sensor reads (sim::sensed_yaw_deg: a drifting or noisy sensor's error included),
  // what the learner, the reflex and every window's measure read.
  std::vector<double> sensed_yaw_deg;
  // Only when joints are recorded, indexed [row * legs * 3 + leg * 3 + joint] (TC, CTr, FTi):
  std::vector<double> command;         // motor command m in [-1, 1] (docs/controller.md)
  std::vector<double> target;          // commanded joint angle, rad
  std::vector<double> actual;          // joint angle, rad
  std::vector<unsigned char> contact;  // [row * legs + leg], 1 = foot touches the ground

  std::size_t rows() const { return time.size(); }
};

// Appends the state as one row of `record` (its `legs` must be set); joint angles, commands and
// contacts only if `joints`.
void append_record(const SimModel& model, const SimState& state, bool joints, WalkRecord& record);

}  // namespace multicpg::sim
