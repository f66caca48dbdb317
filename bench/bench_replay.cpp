// What a 3D replay (docs/replay.md) costs besides its run: recording every step (the recorder's
// pose computation and copies, on top of the walk itself) and writing the page (encoding the
// poses and assembling the HTML), for a 10,000-step hexapod walk.
#include <benchmark/benchmark.h>

#include "report/replay/page.h"
#include "report/replay/recording.h"
#include "sim/walk.h"

namespace {

using namespace multicpg;

constexpr long kSteps = 10'000;

sim::WalkSpec walk_spec(sim::Observer* observer) {
  sim::WalkSpec spec;
  spec.steps = kSteps;
  spec.faults = body::fail_at({0}, 0);
  spec.keep_record = false;
  spec.observer = observer;
  return spec;
}

// The walk alone, then the walk recorded: the difference is the recorder's cost.
void BM_Walk(benchmark::State& bench) {
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  for (auto _ : bench) benchmark::DoNotOptimize(sim::walk(model, walk_spec(nullptr)).distance_m);
}

void BM_WalkRecorded(benchmark::State& bench) {
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  for (auto _ : bench) {
    report::ReplayRecorder recorder;
    benchmark::DoNotOptimize(sim::walk(model, walk_spec(&recorder)).distance_m);
  }
}

void BM_ReplayPage(benchmark::State& bench) {
  const sim::SimModel model = sim::make_sim_model(robot::RobotKind::hexapod);
  report::ReplayRecorder recorder;
  sim::walk(model, walk_spec(&recorder));
  std::size_t bytes = 0;
  for (auto _ : bench) {
    const std::string page = report::replay_html(recorder.recording(), "bench");
    bytes = page.size();
    benchmark::DoNotOptimize(page.data());
  }
  bench.counters["page_MB"] = static_cast<double>(bytes) / 1e6;
}

BENCHMARK(BM_Walk)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_WalkRecorded)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_ReplayPage)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
