// A 400-step hexapod trial (paper §4 window) in MuJoCo, against bare mj_step on the same model
// for the same simulated time: what the controller, servo law, sensing and checks cost; and
// both against a plain MuJoCo hexapod: what our model and solver settings cost.
//
// The bare run replays, physics step by physics step, the ctrl values the trial computed, so it
// follows the identical trajectory with the same contacts; only our work is missing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "sim/robot_file.h"
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

// --- Side by side with a plain MuJoCo hexapod ---
//
// The plain hexapod: what a MuJoCo user would write for a robot of our size, with every MuJoCo
// default (semi-implicit Euler at 5 ms, pyramidal cones, condim 3, Newton solver, 100 iterations,
// tolerance 1e-8, every geom colliding with every other but its parent). A box trunk of our
// trunk's size (0.31 x 0.07 x 0.065 m), six legs at x = 0.13, 0, -0.13 m, each a vertical-axis
// hip, a knee and an ankle about the leg's long axis (3 DOF per leg, 18 + the free joint = 24
// DOF), capsule segments about as long as ours, one position servo per joint. It
// walks a sinusoidal tripod gait (1 Hz, hip +-0.35 rad, knee lifted 0.8 rad in swing), standing
// on about three feet like our hexapod.
constexpr const char* kPlainHexapodXml = R"(
<mujoco model="plain-hexapod">
  <option timestep="0.005"/>
  <default>
    <joint type="hinge" limited="true" damping="0.5" armature="0.01"/>
    <geom type="capsule" size="0.013"/>
    <position kp="40" ctrllimited="true" ctrlrange="-1.3 1.3"/>
  </default>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <body name="trunk" pos="0 0 0.14">
      <freejoint/>
      <geom type="box" size="0.155 0.035 0.0325" mass="2.5"/>
      LEGS
    </body>
  </worldbody>
  <actuator>
    ACTUATORS
  </actuator>
</mujoco>
)";

// Plain hexapod leg geometry (m): roughly our hexapod's (docs/robots.md "Geometry").
constexpr double kPlainRootY = 0.035;        // trunk side
constexpr double kPlainCoxaLength = 0.05;    // our shoulder + coxa reach 0.08 from the centre
constexpr double kPlainCoxaRadius = 0.0172;  // our coxa
constexpr double kPlainFemurLength = 0.06;   // our femur
constexpr double kPlainTibiaOut = 0.02;      // the tibia points down and a little out,
constexpr double kPlainTibiaDown = 0.1;      // about our tibia + foot length
constexpr std::array<double, 3> kPlainLegX{0.13, 0.0, -0.13};  // front, middle, hind

// One leg of the plain hexapod: side +1 = left, -1 = right; axes mirrored so that positive
// angles are forward (hip) and up (knee, ankle) on both sides.
std::string plain_leg(const std::string& name, double x, double side) {
  const auto n = [](double v) { return std::to_string(v); };
  const std::string out = n(side * kPlainCoxaLength);
  const std::string femur = n(side * kPlainFemurLength);
  const std::string lift = n(side) + " 0 0";
  return "<body name=\"" + name + "\" pos=\"" + n(x) + " " + n(side * kPlainRootY) + " 0\">" +
         "<joint name=\"" + name + "_hip\" axis=\"0 0 " + n(-side) + "\" range=\"-0.6 0.6\"/>" +
         "<geom fromto=\"0 0 0 0 " + out + " 0\" size=\"" + n(kPlainCoxaRadius) + "\"/>" +
         "<body pos=\"0 " + out + " 0\">" + "<joint name=\"" + name + "_knee\" axis=\"" + lift +
         "\" range=\"-1.3 1.3\"/>" + "<geom fromto=\"0 0 0 0 " + femur + " 0\"/>" +
         "<body pos=\"0 " + femur + " 0\">" + "<joint name=\"" + name + "_ankle\" axis=\"" + lift +
         "\" range=\"-1.3 1.3\"/>" + "<geom fromto=\"0 0 0 0 " + n(side * kPlainTibiaOut) + " " +
         n(-kPlainTibiaDown) + "\"/></body></body></body>";
}

struct PlainHexapod {
  std::unique_ptr<mjModel, sim::MjModelDeleter> model;
  std::array<double, 6> phase;  // tripods R1 L2 R3 and L1 R2 L3 half a cycle apart
};

const PlainHexapod& plain_hexapod() {
  static const PlainHexapod plain = [] {
    const std::array<std::pair<const char*, double>, 6> legs{
        {{"R1", -1}, {"R2", -1}, {"R3", -1}, {"L1", 1}, {"L2", 1}, {"L3", 1}}};
    std::string body, actuators;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      body += plain_leg(legs[i].first, kPlainLegX[i % 3], legs[i].second);
      for (const char* joint : {"_hip", "_knee", "_ankle"}) {
        const std::string name = std::string(legs[i].first) + joint;
        actuators += "<position name=\"" + name + "\" joint=\"" + name + "\"/>";
      }
    }
    std::string xml = kPlainHexapodXml;
    xml.replace(xml.find("LEGS"), 4, body);
    xml.replace(xml.find("ACTUATORS"), 9, actuators);
    return PlainHexapod{sim::compile_mjcf(xml),
                        {0.0, std::numbers::pi, 0.0, std::numbers::pi, 0.0, std::numbers::pi}};
  }();
  return plain;
}

// Tripod gait targets of the plain hexapod at time t: the hip swings forward while the knee
// lifts, and pushes back on the ground in stance; the ankle holds the tibia down.
void plain_gait(const PlainHexapod& plain, mjData* d) {
  constexpr double kFrequency = 1.0;      // Hz
  constexpr double kHipAmplitude = 0.35;  // rad
  constexpr double kKneeLift = 0.8;       // rad
  for (std::size_t leg = 0; leg < plain.phase.size(); ++leg) {
    const double theta = 2.0 * std::numbers::pi * kFrequency * d->time + plain.phase[leg];
    d->ctrl[3 * leg] = kHipAmplitude * std::sin(theta);
    d->ctrl[3 * leg + 1] = kKneeLift * std::max(0.0, std::cos(theta));
    d->ctrl[3 * leg + 2] = 0.0;
  }
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// This thread's CPU time for a 400-step trial of `model` from the walk's start state.
double trial_seconds(const sim::SimModel& model) {
  sim::SimState s = sim::start_walk_state(model, {});
  const double t0 = thread_seconds();
  for (long k = 0; k < kTrialSteps; ++k) sim::sim_step(model, s);
  const double t = thread_seconds() - t0;
  benchmark::DoNotOptimize(s.data->qpos[0]);
  return t;
}

// This thread's CPU time for the plain hexapod walking `steps` physics steps from its start;
// adds its contacts per step to `contacts`.
double plain_seconds(mjData* pd, long steps, long& contacts) {
  const mjModel* pm = plain_hexapod().model.get();
  mj_resetData(pm, pd);
  mj_forward(pm, pd);
  const double t0 = thread_seconds();
  for (long k = 0; k < steps; ++k) {
    plain_gait(plain_hexapod(), pd);
    mj_step(pm, pd);
    contacts += pd->ncon;
  }
  return thread_seconds() - t0;
}

// Each iteration runs, one after the other on this thread, (1) our 400-step trial (sim_step x
// 400 from the walk's start state), (2) bare mj_step replaying that trial's ctrl on our model,
// (3) the plain hexapod for the same simulated time. Times are this thread's CPU time, so other
// processes on the core hurt all three alike; the ratios are the result.
void BM_SideBySide(benchmark::State& state) {
  const sim::SimModel& model = hexapod();
  const mjModel* m = model.mj.get();
  const TrialControls trial = trial_controls();
  const long physics_steps = kTrialSteps * model.substeps;
  const mjModel* pm = plain_hexapod().model.get();
  const double simulated = kTrialSteps * model.control_dt;
  const auto plain_steps = std::lround(simulated / pm->opt.timestep);
  mjData* d = mj_makeData(m);
  mjData* pd = mj_makeData(pm);
  double ours = 0.0, bare = 0.0, plain = 0.0;
  long our_contacts = 0, plain_contacts = 0;
  for (auto _ : state) {
    ours += trial_seconds(model);

    mj_resetDataKeyframe(m, d, model.start_key);
    mj_forward(m, d);
    const double t2 = thread_seconds();
    for (long k = 0; k < physics_steps; ++k) {
      std::copy_n(trial.ctrl.data() + k * m->nu, m->nu, d->ctrl);
      mj_step(m, d);
      our_contacts += d->ncon;
    }
    const double t3 = thread_seconds();
    bare += t3 - t2;

    plain += plain_seconds(pd, plain_steps, plain_contacts);
    benchmark::DoNotOptimize(pd->qpos[0]);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["trial_ms"] = 1e3 * ours / n;
  state.counters["bare_ms"] = 1e3 * bare / n;
  state.counters["plain_ms"] = 1e3 * plain / n;
  state.counters["trial/plain"] = ours / plain;
  state.counters["bare/plain"] = bare / plain;
  state.counters["trial/bare"] = ours / bare;
  state.counters["contacts"] = static_cast<double>(our_contacts) / (n * physics_steps);
  state.counters["plain_contacts"] = static_cast<double>(plain_contacts) / (n * plain_steps);
  state.counters["plain_forward_m"] = pd->qpos[0];
  mj_deleteData(pd);
  mj_deleteData(d);
}
BENCHMARK(BM_SideBySide)->Unit(benchmark::kMillisecond);

// The example robots of examples/robots/ (docs/robots.md "Example robots").
const std::array<const char*, 3> kExampleRobots{"hobby_hexapod.toml", "spider_quadruped.toml",
                                                "spider_quadruped_urdf.toml"};

std::string example(std::int64_t index) {
  return std::string(MULTICPG_SOURCE_DIR) + "/examples/robots/" +
         kExampleRobots.at(static_cast<std::size_t>(index));
}

// Making the built-in hexapod's simulation (its MJCF generated and compiled) ...
void BM_LoadBuiltin(benchmark::State& state) {
  for (auto _ : state) {
    const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
    benchmark::DoNotOptimize(model.mj->nq);
  }
}
BENCHMARK(BM_LoadBuiltin)->Unit(benchmark::kMillisecond);

// ... against reading an example robot's file (checked by compiling its model) and making its
// simulation, as a command does.
void BM_LoadRobotFile(benchmark::State& state) {
  const std::string path = example(state.range(0));
  for (auto _ : state) {
    const robot::RobotFile file = sim::load_robot_file(path);
    const sim::SimModel model = sim::make_sim_model(file);
    benchmark::DoNotOptimize(model.mj->nq);
  }
  state.SetLabel(kExampleRobots.at(static_cast<std::size_t>(state.range(0))));
}
BENCHMARK(BM_LoadRobotFile)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// A 400-step trial of an example robot against the plain MuJoCo hexapod for the same simulated
// time, this thread's CPU time for each (as BM_SideBySide).
void BM_ExampleTrial(benchmark::State& state) {
  const sim::SimModel model = sim::make_sim_model(sim::load_robot_file(example(state.range(0))));
  const mjModel* pm = plain_hexapod().model.get();
  const auto plain_steps = std::lround(kTrialSteps * model.control_dt / pm->opt.timestep);
  mjData* pd = mj_makeData(pm);
  double ours = 0.0, plain = 0.0;
  long plain_contacts = 0;
  for (auto _ : state) {
    ours += trial_seconds(model);
    plain += plain_seconds(pd, plain_steps, plain_contacts);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["trial_ms"] = 1e3 * ours / n;
  state.counters["plain_ms"] = 1e3 * plain / n;
  state.counters["trial/plain"] = ours / plain;
  state.SetLabel(kExampleRobots.at(static_cast<std::size_t>(state.range(0))));
  mj_deleteData(pd);
}
BENCHMARK(BM_ExampleTrial)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
