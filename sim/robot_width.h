// How wide a compiled robot stands: what scales the paper's tunnel (3 m x 1.2 m for AMOSII,
// paper §5) to another robot (experiments/tunnel.h), and how far it reaches sideways as it walks.
#pragma once

#include "sim/sim.h"

namespace multicpg::sim {

// The lateral span of the robot's feet in its start pose (reset_to_start), m: the largest
// distance across the heading (+x at the start) between two foot geoms' centres.
double foot_span(const SimModel& model);

// How far the robot reaches sideways now (world y, m): the lowest and highest y of its collision
// geoms' outlines (a bounding box for meshes), what can touch a tunnel wall.
struct LateralReach {
  double low;
  double high;
};
LateralReach lateral_reach(const SimModel& model, const SimState& state);

}  // namespace multicpg::sim
