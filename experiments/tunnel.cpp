#include "experiments/tunnel.h"

#include <cmath>
#include <numbers>

#include "common/errors.h"

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

TunnelRun run_tunnel(const sim::SimModel& model, const TunnelSpec& spec,
                     const std::function<void(const sim::SimState&)>& on_step) {
  const Walls walls = find_walls(model.mj.get());
  const double length = model.scene.tunnel_length;
  sim::SimState state = sim::start_walk_state(model, spec.periods);
  for (std::size_t leg : spec.disabled) neural::set_disabled(state.controller, leg, true);
  sim::warm_up_controller(model, state, spec.controller_warmup);

  TunnelRun run;
  run.record.legs = model.legs.size();
  sim::append_record(model, state, /*joints=*/false, run.record);
  const sim::Position start = sim::trunk_position(model, state);
  while (run.steps < spec.max_steps) {
    sim::sim_step(model, state);
    ++run.steps;
    sim::append_record(model, state, false, run.record);
    if (on_step) on_step(state);
    if (touches_wall(model.mj.get(), state.data.get(), walls)) {
      run.touched_wall = true;
      break;
    }
    if (sim::trunk_position(model, state).x >= length) {
      run.passed = true;
      break;
    }
  }
  const sim::Position end = sim::trunk_position(model, state);
  run.forward_m = end.x - start.x;
  run.lateral_m = end.y - start.y;
  run.deviation_deg = std::atan2(run.lateral_m, run.forward_m) * 180.0 / std::numbers::pi;
  return run;
}

}  // namespace multicpg::experiments
