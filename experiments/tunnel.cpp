#include "experiments/tunnel.h"

#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "common/limits.h"
#include "experiments/learning_run.h"
#include "sim/robot_width.h"

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
  sim::Stepper stepper(model, spec.start, spec.faults, observer, &run.record,
                       /*record_joints=*/false);
  const body::Pose2 start = stepper.pose();
  if (spec.steering) {
    stepper.set_before_step(
        [params = *spec.steering,
         reflex = learning::start_steering(stepper.sensed_pose())](sim::Stepper& s) mutable {
          neural::ControllerState& c = s.state().controller;
          c.drive = learning::steer(params, reflex, s.sensed_pose(), c.drive);
        });
  }
  while (run.steps < spec.max_steps) {
    stepper.step();
    ++run.steps;
    if (touches_wall(model.mj.get(), stepper.state().data.get(), walls)) {
      run.touched_wall = true;
      break;
    }
    // The tunnel's end, along the ground (on a slope its walls are tilted with it).
    const sim::Position p = sim::trunk_position(model, stepper.state());
    if (robot::to_ground_frame(model.scene.terrain, {p.x, p.y, p.z})[0] >= length) {
      run.passed = true;
      break;
    }
  }
  const body::Pose2 end = stepper.pose();
  run.forward_m = end.x - start.x;
  run.lateral_m = end.y - start.y;
  run.deviation_deg = std::atan2(run.lateral_m, run.forward_m) * 180.0 / std::numbers::pi;
  return run;
}

sim::SimModel tunnel_model(const RunSpec& spec) {
  RobotSpec corridor = spec.robot;
  corridor.sim.scene.tunnel = true;
  return make_model(corridor);
}

TunnelScale scale_tunnel(RunSpec& spec) {
  TunnelScale scale;
  scale.robot_width_m = sim::foot_span(make_model(spec.robot));
  scale.layout_width_m = sim::foot_span(sim::make_sim_model(spec.robot.kind));
  scale.factor = scale.robot_width_m / scale.layout_width_m;
  robot::Scene& scene = spec.robot.sim.scene;
  scene.tunnel_length *= scale.factor;
  scene.tunnel_width *= scale.factor;
  within("sim", [&] { sim::validate(spec.robot.sim); });
  return scale;
}

TunnelOutcome run_tunnel(const RunSpec& spec, const sim::SimModel& corridor, long max_steps,
                         sim::Observer* observer, sim::Observer* learning_observer) {
  const robot::Morphology& morph = morphology(spec.robot);
  TunnelOutcome out;
  TunnelSpec tunnel;
  tunnel.max_steps = max_steps;
  if (!spec.learning) {
    tunnel.start = spec.start;
    tunnel.faults = spec.faults;
    out.disabled = body::failed_after(morph, spec.faults);
    out.periods = spec.start.periods.empty()
                      ? std::vector<int>(morph.size(), learning::kStartPeriod)
                      : spec.start.periods;
  } else {
    RobotSpec open_robot = spec.robot;
    open_robot.sim.scene.tunnel = false;
    const sim::SimModel open = make_model(open_robot);
    out.learned = run_learning(open, spec, 0, learning_observer).result;
    out.disabled = body::failed_after(morph, spec.faults);
    out.periods = out.learned->periods;
    tunnel.start.periods = out.periods;
    tunnel.faults = body::fail_at(out.disabled, 0);
    if (out.learned->steering) tunnel.steering = spec.learning->steering_params;
  }
  out.run = run_tunnel(corridor, tunnel, observer);
  return out;
}

}  // namespace multicpg::experiments
