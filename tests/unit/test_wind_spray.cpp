// Wind spray off breaking crests (engine/splash, game/sim/splash_foam_system): none at or below
// [splash] spray_wind, the stated rate above it, and the drops blown downwind by the air.
#include "ecs/components.h"
#include "sim/splash_foam_system.h"
#include "splash/splash_particles.h"
#include "water/water_query.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

using namespace ob;

namespace {

constexpr float DT = 1.0f / 60.0f;

// A 10 m × 10 m patch of crests, 1 m apart (each standing for 1 m²).
std::vector<glm::vec2> crestPatch() {
    std::vector<glm::vec2> crests;
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i) crests.emplace_back(float(i), float(j));
    return crests;
}

} // namespace

TEST_CASE("wind spray: none at or below spray_wind, 5·(U/U_s − 1) drops per m² per second above it, capped per step", "[splash][spray]") {
    const water::FlatWater sea(0.0f);
    const std::vector<glm::vec2> crests = crestPatch();
    splash::SplashDef def;  // spray_wind 11 m/s
    splash::SplashParticles calm(def, 1);
    for (int s = 0; s < 600; ++s) CHECK(calm.emitWindSpray(crests, 1.0f, glm::vec2(10.0f, 0.0f), DT, sea) == 0);
    CHECK(calm.emitWindSpray(crests, 1.0f, glm::vec2(11.0f, 0.0f), DT, sea) == 0);

    splash::SplashParticles storm(def, 1);
    int total = 0;
    for (int s = 0; s < 600; ++s) total += storm.emitWindSpray(crests, 1.0f, glm::vec2(20.0f, 0.0f), DT, sea);
    const double expected = 5.0 * 100.0 * (20.0 / 11.0 - 1.0) * 10.0;  // drops per m² s × m² × factor × s
    INFO("thrown " << total << ", the law's mean " << expected);
    CHECK(total == Approx(expected).epsilon(0.05));
    CHECK(storm.stats().spray == uint64_t(total));

    def.spray_per_step = 3;
    splash::SplashParticles capped(def, 1);
    for (int s = 0; s < 60; ++s) CHECK(capped.emitWindSpray(crests, 1.0f, glm::vec2(40.0f, 0.0f), DT, sea) <= 3);
}

TEST_CASE("wind spray drifts downwind: the mean landing lies within 20 degrees of the wind from the mean launch", "[splash][spray]") {
    const water::FlatWater sea(0.0f);
    const std::vector<glm::vec2> crests = crestPatch();
    const glm::vec2 wind = 20.0f * glm::normalize(glm::vec2(1.0f, 0.6f));
    splash::SplashParticles drops(splash::SplashDef{}, 7);
    int thrown = 0;
    for (int s = 0; s < 120; ++s) thrown += drops.emitWindSpray(crests, 1.0f, wind, DT, sea);
    REQUIRE(thrown > 100);
    glm::dvec2 launch(0.0);
    for (int i = 0; i < drops.size(); ++i) launch += glm::dvec2(drops.x()[size_t(i)], drops.z()[size_t(i)]);
    launch /= double(drops.size());
    // Stop throwing; fly them all down (every drop lands: max_life 10 s, flights of ~1 s).
    glm::dvec2 landed(0.0);
    uint64_t count = 0;
    for (int s = 0; s < 600 && drops.size() > 0; ++s) {
        drops.step(DT, sea);
        for (const splash::Landing& l : drops.landings()) landed += glm::dvec2(l.position.x, l.position.z), ++count;
    }
    REQUIRE(count == uint64_t(thrown));
    const glm::dvec2 drift = landed / double(count) - launch;
    const double angle = std::acos(glm::dot(glm::normalize(drift), glm::dvec2(glm::normalize(wind)))) * 180.0 / M_PI;
    INFO("mean drift " << drift.x << ", " << drift.y << " m, " << angle << " deg off the wind");
    CHECK(glm::length(drift) > 1.0);
    CHECK(angle < 20.0);
}

TEST_CASE("the default scene sprays off its crests in a 20 m/s wind, and not in a 10 m/s one", "[splash][spray][scene]") {
    auto spray = [](float wind) {
        game::Sandbox sandbox(game::loadScene(game::defaultScenePath(), {"ocean.resolution=64", "ripples.resolution=64",
                                                                         "ocean.wind_speed=" + std::to_string(wind)}));
        for (int s = 0; s < 120; ++s) sandbox.step();
        const splash::SplashParticles* drops = game::splashParticles(sandbox.world());
        REQUIRE(drops);
        return drops->stats().spray;
    };
    CHECK(spray(10.0f) == 0);
    CHECK(spray(20.0f) > 50);
}

TEST_CASE("a spray drop relaxes to the air's velocity 0.75·U10 as linear drag's closed form, v = w + (v0 − w)·e^(−kt)", "[splash][spray]") {
    const water::FlatWater sea(0.0f);
    const std::vector<glm::vec2> crests = crestPatch();
    const glm::vec2 wind(16.0f, -12.0f);  // 20 m/s
    splash::SplashParticles drops(splash::SplashDef{}, 3);
    while (drops.size() == 0) drops.emitWindSpray(crests, 1.0f, wind, DT, sea);
    const float vx0 = drops.vx()[0], vz0 = drops.vz()[0], x0 = drops.x()[0];
    const double k = splash::SplashDef{}.drag, t = 0.1;  // one step of 0.1 s, still ascending
    drops.step(float(t), sea);
    REQUIRE(drops.size() > 0);
    const double a = std::exp(-k * t), wx = 0.75 * wind.x, wz = 0.75 * wind.y;
    CHECK(drops.vx()[0] == Approx(wx + (vx0 - wx) * a).margin(1e-4));
    CHECK(drops.vz()[0] == Approx(wz + (vz0 - wz) * a).margin(1e-4));
    // x(t) = x0 + w·t + (v0 − w)·(1 − e^(−kt))/k
    CHECK(drops.x()[0] == Approx(x0 + wx * t + (vx0 - wx) * (1.0 - a) / k).margin(1e-4));
}
