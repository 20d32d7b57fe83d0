// ripples.backend = "gpu" end to end: a dropped sphere in a sandbox with the GPU ripple
// field gives the same ripples (and the same body motion) as the CPU field.
#include "gfx/gl.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "platform/platform.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

using namespace ob;

TEST_CASE("a sphere dropped into the GPU ripple field rings out exactly as in the CPU field", "[ripple_gpu]") {
    gfx::requestDebugOutput(true);
    auto platform = platform::createHeadlessPlatform({32, 32});
    int errors = gfx::glErrorCount();
    auto run = [&](const char* backend) {
        game::SceneDef scene = game::parseScene(
            "[ocean]\namplitude = 0.0\n[ripples]\nmodel = \"kang2008\"\nresolution = 64\ncell_size = 0.1\ndamping = 0.98\nbackend = \"" + std::string(backend) +
                "\"\n[[objects]]\ntype = \"sphere\"\nposition = [0.3, 1.0, -0.2]\nradius = 0.3\ndensity = 600.0\n",
            "drop.toml");
        game::Sandbox sandbox(scene);
        sandbox.attachPlatform(*platform, false);
        auto* patch = sandbox.world().resource<interaction::RipplePatch>();
        REQUIRE(patch->onGpu() == (std::string(backend) == "gpu"));
        for (int i = 0; i < 90; ++i) sandbox.step();
        auto field = patch->solverAs<ob::interaction::Kang2008Solver>()->field().current();
        return std::vector<float>(field.begin(), field.end());
    };
    std::vector<float> cpu = run("cpu"), gpu = run("gpu");
    float peak = 0.0f, diff = 0.0f;
    for (size_t i = 0; i < cpu.size(); ++i) {
        peak = std::max(peak, std::abs(cpu[i]));
        diff = std::max(diff, std::abs(cpu[i] - gpu[i]));
    }
    CHECK(peak > 1e-3f);
    CHECK(diff <= 1e-5f);
    CHECK(gfx::glErrorCount() == errors);
}
