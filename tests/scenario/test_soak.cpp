// The soak: its invariants catch what they are meant to (a non-finite cell, a runaway
// ripple, a sunk body), and a short soak of the default scene passes and reports its figures.
#include "tools/cmd_soak.h"
#include "core/error.h"
#include "ecs/components.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "world/sandbox.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

using namespace ob;

namespace {

std::string invariantError(game::Sandbox& sandbox) {
    const game::SoakBounds bounds = game::soakBounds(sandbox);
    game::SoakReport report;
    try {
        game::checkSoakInvariants(sandbox, bounds, report);
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("soak invariants hold for a fresh scene and name the cell, the bound or the body that breaks them", "[soak]") {
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), {"ripples.model=kang2008", "ripples.levels=1", "ripples.resolution=64", "ocean.resolution=64"});
    game::Sandbox sandbox(scene);
    for (int i = 0; i < 10; ++i) sandbox.step();
    CHECK(invariantError(sandbox).empty());
    auto& field = sandbox.world().resource<interaction::RipplePatch>()->solverAs<ob::interaction::Kang2008Solver>()->field();

    SECTION("a NaN in the ripple field") {
        field.current()[size_t(5 * 64 + 7)] = std::numeric_limits<float>::quiet_NaN();
        CHECK(invariantError(sandbox).find("ripple field Vh(t) cell (row 5, column 7) = nan: not a finite number") !=
              std::string::npos);
    }
    SECTION("a ripple far beyond the stamps' scale") {
        field.previous()[100] = 1000.0f;
        CHECK(invariantError(sandbox).find("ripple field Vh(t-1) reaches |Vh| = 1000 m, beyond the bound") != std::string::npos);
    }
    SECTION("a floating body deep under the surface") {
        auto& bodies = sandbox.world().pool<game::Body>();
        sandbox.world().get<ecs::Transform>(bodies.entities()[0]).position.y = -60.0f;
        CHECK(invariantError(sandbox).find("body 0 (") != std::string::npos);
        CHECK(invariantError(sandbox).find(", lighter than water) has sunk") != std::string::npos);
    }
    SECTION("an infinite velocity") {
        auto& motions = sandbox.world().pool<ecs::Motion>();
        motions.components()[0].velocity.x = std::numeric_limits<float>::infinity();
        CHECK(invariantError(sandbox).find("velocity is not finite") != std::string::npos);
    }
}

TEST_CASE("soak invariants: a fixed body (the harbour's walls, post and pillar) is not a floating body that sank", "[soak]") {
    // Fixed bodies carry no probes and no mass: they stand in the water, they do not float.
    game::SceneDef scene = game::loadScene(std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/harbour.toml",
                                           {"ripples.resolution=64", "ocean.resolution=32"});
    game::Sandbox sandbox(scene);
    for (int i = 0; i < 3; ++i) sandbox.step();
    CHECK(invariantError(sandbox).empty());
}

TEST_CASE("oceanbox soak runs a scene headless, checks every step and reports rates, maxima and memory", "[soak][cli]") {
    const std::string json = test::tempPath("soak.json");
    auto r = test::runOceanbox("soak config/scenes/default.toml --seconds 5 --stats " + json);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    CHECK(r.output.find("soak: config/scenes/default.toml: 300 steps, 5 s simulated") != std::string::npos);
    nlohmann::json stats = nlohmann::json::parse(std::ifstream(json));
    CHECK(stats["steps"] == 300);
    CHECK(stats["max_cascade_height_m"].size() == 2);
    for (size_t c = 0; c < 2; ++c) {
        CHECK(stats["max_cascade_height_m"][c].get<double>() > 0.0);
        CHECK(stats["max_cascade_height_m"][c].get<double>() <= stats["cascade_height_bound_m"][c].get<double>());
    }
    CHECK(stats["max_ripple_m"].get<double>() > 0.0);  // the bodies fell in within 5 s
    CHECK(stats["rss_mib"]["end"].get<double>() > 0.0);
    CHECK(stats["state_hash"].get<std::string>().size() == 16);
    // Bad arguments are bad input.
    CHECK(test::runOceanbox("soak config/scenes/default.toml --seconds 0").exitCode == 2);
    CHECK(test::runOceanbox("soak config/scenes/default.toml --check-every 0").exitCode == 2);
}

TEST_CASE("the soak's ripple bound counts balls and fish spawned later and an object's overlapping spheres", "[soak]") {
    // [Kang2008]'s spheres: a ball SR 5 cells, SHR 1; a ship six of SR 7, SHR 0.2, which chain
    // through eq. 5's base where they overlap; a fish radius 0.35 × length, SHR 1.4. The
    // bound is 4 stamps of the largest source, before any ball is fired or fish jumps.
    const std::string dir = std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/";
    const struct {
        const char* scene;
        float bound;
    } cases[] = {
        {"cannon.toml", 4.0f * 5.0f * 0.1f * 1.0f},          // cell 0.1 m
        {"ship.toml", 4.0f * 6.0f * 7.0f * 0.2f * 0.2f},     // cell 0.2 m
        {"fish.toml", 4.0f * 0.35f * 0.8f * 1.4f},           // length 0.8 m
    };
    for (const auto& c : cases) {
        INFO(c.scene);
        game::Sandbox sandbox(game::loadScene(dir + c.scene));
        CHECK(game::soakBounds(sandbox).ripple == Approx(c.bound).epsilon(1e-5));
    }
}
