// The dump tools' files (they can open a GL context for the GPU backends): what `dump
// ocean` and `dump ripples` write is the simulation's own maps, in the documented layout.
#include "core/error.h"
#include "core/npy.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "ocean/ocean_fft_cpu.h"
#include "support/test_support.h"
#include "tools/cmd_dump_ocean.h"
#include "tools/cmd_dump_ripples.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace ob::interaction;

TEST_CASE("dump ocean writes cascade 0's maps as [N, N, 5] float32 (the layout: tests/unit/test_ocean_fft.cpp)",
          "[ocean][cli]") {
    ob::ocean::OceanDef def;
    def.resolution = 16;
    def.cascades = 1;
    def.backend = ob::Backend::Cpu;
    const std::string path = ob::test::tempPath("ocean.npy");
    REQUIRE(ob::game::dumpOcean(def, 2.0, path) == ob::EXIT_OK);
    const ob::NpyArray a = ob::readNpy(path);
    REQUIRE(a.shape == std::vector<size_t>{16, 16, size_t(ob::ocean::OCEAN_DUMP_CHANNELS)});
    ob::ocean::OceanFftCpu ocean(def);
    ocean.update(2.0);
    std::vector<float> want(a.data.size());
    ocean.fillDump(0, want.data());
    CHECK(std::equal(want.begin(), want.end(), a.data.begin()));
}

TEST_CASE("dump ripples writes the patch's Vh(t) after K steps as [N, N] float32, and refuses a scene without ripples",
          "[ripple][cli]") {
    ob::game::SceneDef scene;
    scene.ripples.model = rippleModel("kang2008");
    scene.ripples.resolution = 32;
    scene.ocean.resolution = 16;
    const std::string out = ob::test::tempPath("ripples.npy");
    REQUIRE(ob::game::dumpRipples(scene, 3, out) == ob::EXIT_OK);
    const ob::NpyArray a = ob::readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{32, 32});
    // The same scene stepped here gives the same field, bit for bit.
    ob::game::Sandbox sandbox(scene);
    for (int k = 0; k < 3; ++k) sandbox.step();
    const auto* patch = sandbox.world().resource<RipplePatch>();
    REQUIRE(patch);
    const auto field = patch->solverAs<ob::interaction::Kang2008Solver>()->field().current();
    CHECK(std::equal(field.begin(), field.end(), a.data.begin()));
    scene.ripples.enabled = false;
    CHECK_THROWS_AS(ob::game::dumpRipples(scene, 3, out), ob::InputError);
    CHECK_THROWS_WITH(ob::game::dumpRipples(scene, 3, out), Catch::Contains("ripples.enabled"));
}
