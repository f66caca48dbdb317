// The tunnel of paper §5 (Table 1): a corridor 3.0 m long and 1.2 m wide. The robot starts at
// its entrance with legs disabled and walks with given periods until it reaches the end, touches
// a wall, or runs out of steps.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "experiments/bodies.h"
#include "experiments/run_spec.h"
#include "learning/compensation.h"
#include "learning/steering.h"
#include "sim/sim.h"
#include "sim/stepper.h"
#include "sim/walk.h"

namespace multicpg::experiments {

// Steps allowed to cross the tunnel: 3 m at 0.7 cm/s (444 s). The slow wave gait walks 1.25
// cm/s; a steering reflex that cuts one side's swing slows a learned gait further (measured
// down to about 0.8 cm/s for R1+R3+L2 with slow periods, docs/learning.md).
inline constexpr long kTunnelMaxSteps = 12000;

struct TunnelSpec {
  // How the robot starts at the entrance: its periods, its controller running (as the paper's
  // robot was walking before it entered).
  body::StartSpec start;
  body::FaultTimeline faults;  // legs failed from the entrance on, or later
  long max_steps = kTunnelMaxSteps;
  // The orientation reflex (learning/steering.h) holding the tunnel's axis; none = periods only.
  std::optional<learning::SteeringParams> steering;
};

struct TunnelRun {
  // The trunk reached the far end without touching a wall; empty on a real robot that senses no
  // position (nobody can tell but the operator).
  std::optional<bool> passed;
  bool touched_wall = false;  // some part of the robot touched a wall (the run stops there)
  long steps = 0;
  double forward_m = 0.0;  // trunk displacement along the tunnel (NaN: no position sensed)
  double lateral_m = 0.0;  // and across it, + = left
  // Paper Table 1's angle: atan(lateral / forward) of the trunk's displacement (the paper's R1
  // run: 48 cm right after 53 cm, 42°), + = left.
  double deviation_deg = 0.0;
  double yaw_change_deg = 0.0;  // the heading's change over the walk, as sensed
  sim::WalkRecord record;       // trunk path, every step (the simulation's)
  nlohmann::json hardware;      // a real robot's record (hw::hardware_json); null in simulation
  bool passed_or_false() const { return passed.value_or(false); }
};

// `model` must have the tunnel in its scene (SimOptions::scene.tunnel). `observer` (may be null)
// sees every controller step (e.g. to film it).
TunnelRun run_tunnel(const sim::SimModel& model, const TunnelSpec& spec,
                     sim::Observer* observer = nullptr);

// The tunnel's model for a run: its robot with the corridor in its scene.
sim::SimModel tunnel_model(const RunSpec& spec);

// The tunnel scaled to a robot (`tunnel --scale-tunnel`): its length and width times the robot's
// width (sim::foot_span) over that of the built-in robot of its layout, which the paper's
// tunnel fits.
struct TunnelScale {
  double robot_width_m = 0.0;
  double layout_width_m = 0.0;
  double factor = 1.0;  // robot_width_m / layout_width_m
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(TunnelScale, robot_width_m, layout_width_m, factor)

// The scale of spec's robot; its options' tunnel length and width scaled by it. Throws OptionError
// ("sim.scene.tunnel_length", "sim.scene.tunnel_width") when the scaled tunnel leaves its range.
TunnelScale scale_tunnel(RunSpec& spec);

// Paper §5 for a run description. Without learning options the robot walks spec.start with
// spec.faults through the tunnel of `corridor` (tunnel_model(spec)). With them it first learns in
// the open field (its robot without the corridor) from the run's start, then walks the learned
// controller (its periods and, if the learner used it, its steering reflex) from a warmed start
// through the tunnel, with the legs still failed when the timeline is over. On a real robot
// (spec.hardware, `setup` from hardware_setup) it learns where it stands and walks on into its
// tunnel. `observer` (may be null) sees the tunnel walk, `learning_observer` (may be null) the
// learning run; `hardware` a real robot's every step and its record if a fault stops it. `spec`
// must be valid (validate).
struct TunnelOutcome {
  std::vector<std::size_t> disabled;  // legs failed in the tunnel
  std::vector<int> periods;           // walked: the start's, or learned
  TunnelRun run;
  std::optional<learning::LearningResult> learned;
};
TunnelOutcome run_tunnel(const RunSpec& spec, const sim::SimModel& corridor,
                         long max_steps = kTunnelMaxSteps, sim::Observer* observer = nullptr,
                         sim::Observer* learning_observer = nullptr,
                         const HardwareSetup* setup = nullptr, const Watchers& hardware = {});

}  // namespace multicpg::experiments
