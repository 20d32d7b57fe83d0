// The sandbox's splashes and foam end to end (game/splash_foam_system): the cannon and ship
// scenes throw drops that land, foam appears behind the ship, none of it without the sections,
// and the state hash covers it (same scene, same hash).
#include "behaviours/ship.h"
#include "ecs/components.h"
#include "foam/foam_map.h"
#include "interaction/sphere_set.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "splash/splash_particles.h"
#include "sim/splash_foam_system.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

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

TEST_CASE("a 5 m/s ship's wake foam lasts its decay time on the ship scene's map: exp(−age/τ) along its track, 40 m back", "[splash][foam][scene][long]") {
    // The ship scene's map is 102.4 m across ([foam] extent_m) and follows the ship (with the
    // ripple patch, under the camera's target): foam it left 8 s ago (40 m back) is still on it.
    // On the track's centreline the hull's spheres saturate the coverage to 1; once the stern
    // has passed, it decays as exp(−age/τ) (the sea's orbital motion, wind 3 m/s, moves it by
    // centimetres). The ripple patch's 25.6 m, the old map, ended 12.8 m behind the ship.
    game::SceneDef scene = game::loadScene(scenePath("ship.toml"), {"objects[0].speed=5.0", "events=[]"});
    REQUIRE(scene.foam.extent_m >= 100.0f);
    game::Sandbox sandbox(scene);
    ecs::World& world = sandbox.world();
    const ecs::Entity ship = world.pool<game::Ship>().entities()[0];
    glm::vec3 sternOffset(0.0f);
    for (const interaction::BoundingSphere& s : world.get<interaction::SphereSet>(ship).spheres)
        if (s.offset.z < sternOffset.z) sternOffset = s.offset;
    struct Pass {
        double time;
        glm::vec3 stern, centre;
    };
    std::vector<Pass> track;
    const int frames = 900;  // 15 s: up to speed, then ~50 m at 5 m/s
    for (int f = 1; f <= frames; ++f) {
        sandbox.frame(f / 60.0);  // no platform: the steps and the camera (which the patch follows)
        const ecs::Transform& t = world.get<ecs::Transform>(ship);
        track.push_back({f / 60.0, t.position + t.rotation * sternOffset, t.position});
    }
    const foam::FoamMap* foam = game::foamMap(world);
    REQUIRE(foam);
    const double tau = foam->def().decay_s;
    const Pass& now = track.back();
    const Pass& secondAgo = track[track.size() - 61];
    const float speed = glm::length(glm::vec2(now.centre.x - secondAgo.centre.x, now.centre.z - secondAgo.centre.z));
    INFO("speed over the last second " << speed << " m/s");
    CHECK(speed > 4.5f);
    for (double age : {2.0, 4.0, 6.0, 8.0}) {
        const Pass& p = track[track.size() - 1 - size_t(std::lround(age * 60.0))];
        const float behind = glm::length(glm::vec2(now.centre.x - p.stern.x, now.centre.z - p.stern.z));
        const double coverage = foam->sample(p.stern.x, p.stern.z), expected = std::exp(-age / tau);
        INFO("the stern passed " << age << " s ago, " << behind << " m behind the ship: coverage " << coverage
                                 << ", exp(−age/τ) " << expected);
        CHECK(coverage == Approx(expected).epsilon(0.1));  // the stern sphere still adds for ~R/U after its centre passes: +4%
    }
    // Beside the track (5 m off it, beyond the hull's spheres) there is none.
    const Pass& p = track[track.size() - 1 - 240];
    CHECK(foam->sample(p.stern.x + 5.0f, p.stern.z) < 0.05f);
}
