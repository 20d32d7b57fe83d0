// The sandbox's splashes and foam end to end (game/splash_foam_system): the cannon and ship
// scenes throw drops that land, foam appears behind the ship, none of it without the sections,
// and the state hash covers it (same scene, same hash).
#include "foam/foam_map.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "splash/splash_particles.h"
#include "sim/splash_foam_system.h"

#include <catch2/catch.hpp>

#include <string>

using namespace ob;

namespace {

std::string scenePath(const char* name) { return std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/" + name; }

} // namespace

TEST_CASE("the cannon scene's balls splash: drops are thrown, land, and the splashes feed the foam", "[splash][foam][scene]") {
    game::Sandbox sandbox(game::loadScene(scenePath("cannon.toml")));
    uint64_t most = 0;
    for (int s = 0; s < 240; ++s) {  // 4 s: two shots land
        sandbox.step();
        most = std::max<uint64_t>(most, uint64_t(game::splashParticles(sandbox.world())->size()));
    }
    const splash::SplashParticles* drops = game::splashParticles(sandbox.world());
    REQUIRE(drops);
    INFO("emitted " << drops->stats().emitted << ", landed " << drops->stats().landed << ", most alive " << most);
    CHECK(drops->stats().emitted > 100);
    CHECK(drops->stats().landed > 100);
    const foam::FoamMap* foam = game::foamMap(sandbox.world());
    REQUIRE(foam);
    CHECK(foam->mean() > 0.0);

    game::SceneDef off = game::loadScene(scenePath("cannon.toml"), {"splash.enabled=false", "foam.enabled=false"});
    game::Sandbox quiet(off);
    for (int s = 0; s < 10; ++s) quiet.step();
    CHECK(game::splashParticles(quiet.world()) == nullptr);
    CHECK(game::foamMap(quiet.world()) == nullptr);
}

TEST_CASE("the ship scene leaves wake foam behind its ships, and the same run gives the same hash", "[splash][foam][scene]") {
    auto run = [] {
        game::Sandbox sandbox(game::loadScene(scenePath("ship.toml")));
        for (int s = 0; s < 180; ++s) sandbox.step();
        const foam::FoamMap* foam = game::foamMap(sandbox.world());
        REQUIRE(foam);
        CHECK(foam->mean() > 0.0);
        return sandbox.stateHash();
    };
    CHECK(run() == run());
}
