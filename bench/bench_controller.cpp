// One controller step (all six pipeline stages) for 4, 6 and 8 legs.
#include <benchmark/benchmark.h>

#include "neural/controller.h"

namespace {

using multicpg::robot::RobotKind;

// Steps run before timing so the CPGs have locked and the delay lines are full.
constexpr int kWarmupSteps = 1000;

void BM_ControllerStep(benchmark::State& bench, RobotKind kind) {
  const auto model = multicpg::neural::make_controller_model(kind);
  auto state = multicpg::neural::make_controller_state(model, 4);
  for (int i = 0; i < kWarmupSteps; ++i) multicpg::neural::controller_step(model, state);
  for (auto _ : bench) {
    multicpg::neural::controller_step(model, state);
    benchmark::DoNotOptimize(state.legs.front().command);
  }
  bench.counters["legs"] = static_cast<double>(model.size());
  bench.counters["ns_per_leg"] = benchmark::Counter(
      static_cast<double>(bench.iterations()) * static_cast<double>(model.size()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(BM_ControllerStep, quadruped, RobotKind::quadruped);
BENCHMARK_CAPTURE(BM_ControllerStep, hexapod, RobotKind::hexapod);
BENCHMARK_CAPTURE(BM_ControllerStep, octopod, RobotKind::octopod);

}  // namespace
