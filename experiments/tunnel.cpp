#include "experiments/tunnel.h"

#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "experiments/learning_run.h"

namespace multicpg::experiments {
namespace {

// Ids of the two wall geoms (robot/mjcf.h names them).
struct Walls {
  int left = -1;
  int right = -1;
  bool is_wall(int geom) const { return geom == left || geom == right; }
};

Walls find_walls(const mjModel* m) {
  Walls w{mj_name2id(m, mjOBJ_GEOM, "wall_left"), mj_name2id(m, mjOBJ_GEOM, "wall_right")};
  if (w.left < 0 || w.right < 0) {
    throw BadInput("the tunnel run needs a model built with the tunnel in its scene");
  }
  return w;
}

bool touches_wall(const mjModel* m, const mjData* d, const Walls& walls) {
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const bool wall1 = walls.is_wall(c.geom1);
    const bool wall2 = walls.is_wall(c.geom2);
    // Robot geoms hang off body 1 and its children; the world (ground, walls) is body 0.
    if (wall1 != wall2 && m->geom_bodyid[wall1 ? c.geom2 : c.geom1] != 0) return true;
  }
  return false;
}

}  // namespace

TunnelRun run_tunnel(const sim::SimModel& model, const TunnelSpec& spec, sim::Observer* observer) {
  const Walls walls = find_walls(model.mj.get());
  const double length = model.scene.tunnel_length;
  TunnelRun run;
  sim::Stepper stepper(model, {spec.periods, spec.controller_warmup},
                       sim::fail_at(spec.disabled, 0), observer, &run.record,
                       /*record_joints=*/false);
  const sim::Pose2 start = stepper.pose();
  if (spec.steering) {
    stepper.set_before_step([params = *spec.steering,
                             reflex = learning::start_steering(start)](sim::Stepper& s) mutable {
      neural::ControllerState& c = s.state().controller;
      c.drive = learning::steer(params, reflex, s.pose(), c.drive);
    });
  }
  while (run.steps < spec.max_steps) {
    stepper.step();
    ++run.steps;
    if (touches_wall(model.mj.get(), stepper.state().data.get(), walls)) {
      run.touched_wall = true;
      break;
    }
    if (stepper.pose().x >= length) {
      run.passed = true;
      break;
    }
  }
  const sim::Pose2 end = stepper.pose();
  run.forward_m = end.x - start.x;
  run.lateral_m = end.y - start.y;
  run.deviation_deg = std::atan2(run.lateral_m, run.forward_m) * 180.0 / std::numbers::pi;
  return run;
}

LearnedTunnelRun run_tunnel_after_learning(const sim::SimModel& open, const sim::SimModel& corridor,
                                           const learning::CompensationOptions& options,
                                           long max_steps, sim::Observer* observer,
                                           sim::Observer* learning_observer) {
  LearnedTunnelRun out;
  out.learning = run_learning(open, options, /*record=*/false, 0, learning_observer).result;
  TunnelSpec spec;
  // The legs still failed when the timeline is over walk the tunnel failed.
  std::vector<bool> failed(corridor.legs.size(), false);
  for (const sim::Fault& f : learning::fault_timeline(options)) {
    for (std::size_t leg : f.legs) failed[leg] = !f.recover;
  }
  for (std::size_t leg = 0; leg < failed.size(); ++leg) {
    if (failed[leg]) spec.disabled.push_back(leg);
  }
  spec.periods = out.learning.periods;
  spec.max_steps = max_steps;
  if (out.learning.steering) spec.steering = options.steering_params;
  out.tunnel = run_tunnel(corridor, spec, observer);
  return out;
}

}  // namespace multicpg::experiments
