// How wide a compiled robot stands: what scales the paper's tunnel (3 m x 1.2 m for AMOSII,
// paper §5) to another robot (experiments/tunnel.h).
#pragma once

#include "sim/sim.h"

namespace multicpg::sim {

// The lateral span of the robot's feet in its start pose (reset_to_start), m: the largest
// distance across the heading (+x at the start) between two foot geoms' centres.
double foot_span(const SimModel& model);

}  // namespace multicpg::sim
