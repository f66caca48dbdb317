// A 400-step hexapod trial (SPEC §6 window) in MuJoCo, against bare mj_step on the same model
// for the same simulated time: what the controller, servo law, sensing and checks cost.
//
// The bare run replays, physics step by physics step, the ctrl values the trial computed, so it
// follows the identical trajectory with the same contacts; only our work is missing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "sim/walk.h"

namespace {

using namespace multicpg;

constexpr long kTrialSteps = 400;

const sim::SimModel& hexapod() {
  static const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  return model;
}

sim::WalkSpec trial(bool record) {
  sim::WalkSpec spec;
  spec.steps = kTrialSteps;
  spec.record = record;
  return spec;
}

void set_rate_counters(benchmark::State& state) {
  const double simulated = kTrialSteps * hexapod().control_dt;
  state.counters["real_time_factor"] =
      benchmark::Counter(simulated, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_HexapodTrial(benchmark::State& state) {
  const sim::WalkSpec spec = trial(state.range(0) != 0);
  for (auto _ : state) {
    const sim::WalkResult r = sim::walk(hexapod(), spec);
    benchmark::DoNotOptimize(r.distance_m);
  }
  set_rate_counters(state);
}
BENCHMARK(BM_HexapodTrial)->Arg(0)->Arg(1)->ArgName("record")->Unit(benchmark::kMillisecond);

// ctrl of every physics step of one trial, captured through MuJoCo's control callback, which
// mj_forward calls (in every mj_step, after our servo code has set ctrl, and once when the
// state is made).
std::vector<mjtNum>* capture = nullptr;
void capture_ctrl(const mjModel* m, mjData* d) {
  capture->insert(capture->end(), d->ctrl, d->ctrl + m->nu);
}

struct TrialControls {
  std::vector<mjtNum> ctrl;  // [physics step * nu + actuator]
  double final_x;            // where the trial's trunk ended, to check the replay
};

TrialControls trial_controls() {
  std::vector<mjtNum> controls;
  capture = &controls;
  mjcb_control = capture_ctrl;
  const sim::WalkResult r = sim::walk(hexapod(), trial(false));
  mjcb_control = nullptr;
  capture = nullptr;
  controls.erase(controls.begin(), controls.begin() + hexapod().mj->nu);  // make_sim_state's
  return {controls, r.record.x.back()};
}

void BM_BareMjStep(benchmark::State& state) {
  const sim::SimModel& model = hexapod();
  const mjModel* m = model.mj.get();
  const TrialControls trial = trial_controls();
  const std::vector<mjtNum>& controls = trial.ctrl;
  const long physics_steps = kTrialSteps * model.substeps;
  if (controls.size() != static_cast<std::size_t>(physics_steps * m->nu)) {
    state.SkipWithError("ctrl capture does not match the trial's physics steps");
    return;
  }
  mjData* d = mj_makeData(m);
  for (auto _ : state) {
    mj_resetDataKeyframe(m, d, model.start_key);
    mj_forward(m, d);
    for (long s = 0; s < physics_steps; ++s) {
      std::copy_n(controls.data() + s * m->nu, m->nu, d->ctrl);
      mj_step(m, d);
    }
    benchmark::DoNotOptimize(d->qpos[0]);
  }
  const bool same = d->qpos[model.root_qpos] == trial.final_x;
  mj_deleteData(d);
  if (!same) state.SkipWithError("the replay left the trial's trajectory");
  set_rate_counters(state);
}
BENCHMARK(BM_BareMjStep)->Unit(benchmark::kMillisecond);

}  // namespace
