// Seconds per rendered 640x480 frame (scene update, render, readPixels) on the process's GL
// platform. Run once per platform: MUJOCO_GL=egl and MUJOCO_GL=osmesa; the label
// names the platform used.
#include <benchmark/benchmark.h>

#include <string>

#include "report/render.h"
#include "tests/render_test_model.h"

namespace {

using namespace multicpg::report;

// Frames rendered before timing: first-frame shader and texture uploads are not the steady cost.
constexpr int kWarmupFrames = 5;

void BM_RenderFrame(benchmark::State& bench) {
  const auto model = multicpg::testing::load_render_test_model();
  const multicpg::testing::DataPtr data(mj_makeData(model.get()));
  mj_forward(model.get(), data.get());
  Renderer renderer(model.get(), kDefaultFrameWidth, kDefaultFrameHeight);
  const CameraSpec camera;
  const auto red = multicpg::testing::red_leg(model.get());
  for (int i = 0; i < kWarmupFrames; ++i)
    render_frame(renderer, model.get(), data.get(), camera, red);
  for (auto _ : bench) {
    const Image frame = render_frame(renderer, model.get(), data.get(), camera, red);
    benchmark::DoNotOptimize(frame.rgb.data());
  }
  bench.SetLabel(std::string(to_string(renderer.backend())) + " " +
                 std::to_string(renderer.width()) + "x" + std::to_string(renderer.height()));
}

BENCHMARK(BM_RenderFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
