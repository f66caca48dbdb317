#include "experiments/tunnel.h"

#include <cmath>
#include <numbers>

#include "common/errors.h"
#include "common/limits.h"
#include "experiments/body_runs.h"
#include "experiments/learning_run.h"
#include "sim/robot_width.h"

namespace multicpg::experiments {
namespace {

// The tunnel walk's measures as Table 1 gives them.
void measure(const TunnelWalk& w, TunnelRun& run) {
  run.passed = w.passed;
  run.touched_wall = w.touched_wall;
  run.steps = w.steps;
  run.forward_m = w.forward_m;
  run.lateral_m = w.lateral_m;
  run.deviation_deg = std::atan2(run.lateral_m, run.forward_m) * 180.0 / std::numbers::pi;
  run.yaw_change_deg = w.yaw_change_deg;
}

}  // namespace

TunnelRun run_tunnel(const sim::SimModel& model, const TunnelSpec& spec, sim::Observer* observer) {
  if (mj_name2id(model.mj.get(), mjOBJ_GEOM, "wall_left") < 0) {
    throw BadInput("the tunnel run needs a model built with the tunnel in its scene");
  }
  TunnelRun run;
  sim::Stepper stepper(model, spec.start, spec.faults, observer, &run.record,
                       /*record_joints=*/false);
  const std::unique_ptr<RunBody> body = simulated_body(stepper);
  measure(walk_tunnel(*body, model.scene.tunnel_length, spec.max_steps, spec.steering), run);
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
                         sim::Observer* observer, sim::Observer* learning_observer,
                         const HardwareSetup* setup, const Watchers& hardware) {
  const robot::Morphology& morph = morphology(spec.robot);
  TunnelOutcome out;
  out.disabled = body::failed_after(morph, spec.faults);
  if (spec.hardware) {
    // A real robot learns where it stands and walks on into its tunnel, the reflex (if it
    // learned with one) holding the line it enters on.
    sim::Observers both({observer, learning_observer});
    Watchers watchers = hardware;
    watchers.observer = observer != nullptr || learning_observer != nullptr ? &both : nullptr;
    const learning::LearnerData data = learner_data(spec);
    const std::unique_ptr<RunBody> robot = open_body(spec, corridor, setup, watchers);
    guarded(*robot, spec, hardware.stopped, [&] {
      std::optional<learning::SteeringParams> steering;
      if (spec.learning) {
        out.learned = learn_body(robot->body(), *spec.learning, data, 0).result;
        if (out.learned->steering) steering = spec.learning->steering_params;
      }
      for (const neural::LegState& leg : robot->body().controller().legs) {
        out.periods.push_back(leg.cpg.period);
      }
      measure(walk_tunnel(*robot, spec.robot.sim.scene.tunnel_length, max_steps, steering),
              out.run);
      robot->finish("the tunnel walk ended");
      return 0;
    });
    out.run.hardware = robot->hardware();
    return out;
  }
  TunnelSpec tunnel;
  tunnel.max_steps = max_steps;
  if (!spec.learning) {
    tunnel.start = spec.start;
    tunnel.faults = spec.faults;
    out.periods = spec.start.periods.empty()
                      ? std::vector<int>(morph.size(), learning::kStartPeriod)
                      : spec.start.periods;
  } else {
    RobotSpec open_robot = spec.robot;
    open_robot.sim.scene.tunnel = false;
    const sim::SimModel open = make_model(open_robot);
    out.learned = run_learning(open, spec, 0, learning_observer).result;
    out.periods = out.learned->periods;
    tunnel.start.periods = out.periods;
    tunnel.faults = body::fail_at(out.disabled, 0);
    if (out.learned->steering) tunnel.steering = spec.learning->steering_params;
  }
  out.run = run_tunnel(corridor, tunnel, observer);
  return out;
}

}  // namespace multicpg::experiments
