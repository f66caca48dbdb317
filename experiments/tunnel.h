// The tunnel of paper §5 (Table 1): a corridor 3.0 m long and 1.2 m wide. The robot starts at
// its entrance with legs disabled and walks with given periods until it reaches the end, touches
// a wall, or runs out of steps.
#pragma once

#include <functional>
#include <vector>

#include "sim/sim.h"
#include "sim/walk.h"

namespace multicpg::experiments {

// Steps allowed to cross the tunnel: 3 m at 1.25 cm/s, the slow wave gait's speed (222 s).
inline constexpr long kTunnelMaxSteps = 6000;

struct TunnelSpec {
  std::vector<std::size_t> disabled;
  std::vector<int> periods;  // one per leg
  long max_steps = kTunnelMaxSteps;
  // The robot is placed at the entrance with its controller running, as the paper's robot was.
  long controller_warmup = sim::kControllerWarmup;
};

struct TunnelRun {
  bool passed = false;        // the trunk reached the far end without touching a wall
  bool touched_wall = false;  // some part of the robot touched a wall (the run stops there)
  long steps = 0;
  double forward_m = 0.0;  // trunk displacement along the tunnel
  double lateral_m = 0.0;  // and across it, + = left
  // Paper Table 1's angle: atan(lateral / forward) of the trunk's displacement (the paper's R1
  // run: 48 cm right after 53 cm, 42°), + = left.
  double deviation_deg = 0.0;
  sim::WalkRecord record;  // trunk path, every step
};

// `model` must have the tunnel in its scene (SimOptions::scene.tunnel). `on_step` is called
// after every controller step (e.g. to film it).
TunnelRun run_tunnel(const sim::SimModel& model, const TunnelSpec& spec,
                     const std::function<void(const sim::SimState&)>& on_step = {});

}  // namespace multicpg::experiments
