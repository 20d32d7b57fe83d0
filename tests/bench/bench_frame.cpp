// Whole-frame benchmark: the default scene as `oceanbox run --headless` plays it (1280×720
// OSMesa, one fixed step per frame), with projected-grid resolutions set by overrides.
#include "core/clock.h"
#include "core/log.h"
#include "gfx/gl.h"
#include "platform/platform.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

constexpr int WARM_UP_FRAMES = 3;  // llvmpipe compiles each shader variant at its first draw
// Frames take ~0.1 s on llvmpipe: each repetition runs at least this long (s) for ~10 samples.
constexpr double MIN_SECONDS = 1.0;

// One iteration: Sandbox::frame (input, the step due, the previous frame presented (glFinish),
// render).
void BM_Frame(benchmark::State& state, std::vector<std::string> overrides) {
    ob::setLogQuiet(true);
    const ob::game::SceneDef scene =
        ob::game::loadScene(OCEANBOX_SOURCE_DIR "/config/scenes/default.toml", overrides);
    const auto platform = ob::platform::createHeadlessPlatform({1280, 720});
    ob::game::Sandbox sandbox(scene);
    sandbox.attachPlatform(*platform, false);
    ob::FixedStepClock clock(1.0 / scene.sim.step_hz);
    for (int f = 0; f < WARM_UP_FRAMES; ++f) sandbox.frame(clock.now());
    for (auto _ : state) sandbox.frame(clock.now());  // presents the frame before it
    sandbox.present();
    state.SetLabel(ob::gfx::glRendererName());
}
BENCHMARK_CAPTURE(BM_Frame, default, std::vector<std::string>{})
    ->Unit(benchmark::kMillisecond)->MinTime(MIN_SECONDS)->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, grid_64, std::vector<std::string>{"render.grid_resolution=64"})
    ->Unit(benchmark::kMillisecond)->MinTime(MIN_SECONDS)->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, grid_128, std::vector<std::string>{"render.grid_resolution=128"})
    ->Unit(benchmark::kMillisecond)->MinTime(MIN_SECONDS)->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, grid_256, std::vector<std::string>{"render.grid_resolution=256"})
    ->Unit(benchmark::kMillisecond)->MinTime(MIN_SECONDS)->UseRealTime();

} // namespace
