// [sim] pipelined: the next step's ocean maps, the ripples' coarse levels, the current layer's
// step and the foam's sweep computed on worker threads while the frame goes on must leave every bit of the state as stepping
// in line does, whatever the steps a frame (docs/frame.md#pipelined).
#include "core/clock.h"
#include "currents/current_layer.h"
#include "interaction/ripple_patch.h"
#include "world/sandbox.h"
#include "sim/splash_foam_system.h"
#include "sim/water_systems.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace ob;

namespace {

// The default scene's state hash after `steps` steps run `perFrame` a frame on a fixed clock.
uint64_t hashOf(bool pipelined, int perFrame, int steps) {
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), {pipelined ? "sim.pipelined=true" : "sim.pipelined=false"});
    scene.sim.max_steps_per_frame = std::max(scene.sim.max_steps_per_frame, perFrame);
    game::Sandbox sandbox(scene);
    sandbox.schedule().setFirstFrameSeconds(perFrame / double(scene.sim.step_hz));
    FixedStepClock clock(perFrame / double(scene.sim.step_hz));
    while (sandbox.schedule().steps() < uint64_t(steps)) sandbox.frame(clock.now());
    REQUIRE(sandbox.schedule().steps() == uint64_t(steps));
    const game::OceanState* ocean = sandbox.world().resource<game::OceanState>();
    REQUIRE(ocean);
    CHECK((ocean->cpuNext != nullptr) == pipelined);  // the second map buffer: the maps made ahead
    // Every step's foam sweep on a worker (the foam map exists from the first step on).
    CHECK(game::foamSweepsOnWorker(sandbox.world()) == (pipelined ? uint64_t(steps) : 0u));
    // Every step's current layer beside the ripples' step.
    const auto* layer = sandbox.world().resource<currents::CurrentLayer>();
    REQUIRE(layer);
    CHECK(layer->stepsOnWorker() == (pipelined ? uint64_t(steps) : 0u));
    return sandbox.stateHash();
}

} // namespace

TEST_CASE("the default scene pipelined and not gives the same state hash at 1, 2 and 8 steps a frame", "[determinism][pipelined][threads][long]") {
    // 48 steps: every coarse level (levels = 3: steps every 4th and 16th frame) has stepped on a
    // worker at least twice, the ocean's maps came from the other buffer 47 times, and the current
    // layer's step and the foam's sweep ran on a worker 48 times (joined by the next step, or by the hash after the last).
    // Under ThreadSanitizer 32: each coarse level has still stepped on a worker twice.
    const int steps = test::THREAD_SANITIZER ? 32 : 48;
    const uint64_t reference = hashOf(false, 1, steps);
    for (int perFrame : {1, 2, 8}) {
        INFO(perFrame << " steps a frame");
        CHECK(hashOf(true, perFrame, steps) == reference);
        if (perFrame > 1) CHECK(hashOf(false, perFrame, steps) == reference);
    }
    CHECK(hashOf(true, 1, steps - 1) != reference);  // the hash sees a step
}
