// Picking: one cursor ray against the default scene's composite water (Gerstner, two
// cascades, ewave ripples) and its bodies, as the tools cast it once a step; at a steep and
// a grazing view. The tools' budget: 0.05 ms a frame.
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/picking.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "core/log.h"

#include <benchmark/benchmark.h>
#include <glm/glm.hpp>

namespace {

void BM_Pick(benchmark::State& state, glm::vec3 direction) {
    ob::setLogQuiet(true);
    ob::game::Sandbox sandbox(ob::game::loadScene(OCEANBOX_SOURCE_DIR "/config/scenes/default.toml"));
    for (int s = 0; s < 30; ++s) sandbox.step();
    const ob::water::WaterQuery& water = *sandbox.world().resource<ob::game::OceanState>()->water;
    const ob::game::Ray ray{glm::vec3(0.0f, 9.0f, -30.0f), glm::normalize(direction)};
    for (auto _ : state) {
        auto hit = ob::game::pickWater(water, ray, 3000.0f);
        auto body = ob::game::pickBody(sandbox.world(), ray, hit ? glm::length(*hit - ray.origin) + 1.0f : 3000.0f);
        benchmark::DoNotOptimize(hit);
        benchmark::DoNotOptimize(body);
    }
}
BENCHMARK_CAPTURE(BM_Pick, steep, glm::vec3(0.1f, -1.0f, 0.4f))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Pick, grazing, glm::vec3(0.1f, -0.08f, 1.0f))->Unit(benchmark::kMicrosecond);

} // namespace
