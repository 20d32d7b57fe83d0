// Jumping fish ([Kang2008] §V-2): a fish stamps the ripple field only while its sphere crosses
// the surface (Table 2), pushing the water up on the way out (SD +1) and down on the way
// back in (SD −1); between jumps it swims at depth and leaves the water alone.
#include "behaviours/fish.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {

// Calm sea, the paper's fish setting (SHR 1.4, AF −0.3, DF 0.93) on 5 cm cells.
const char* FISH_SCENE = R"(
[ocean]
amplitude = 0.0
resolution = 16
[gerstner]
count = 0
[ripples]
model = "kang2008"
resolution = 256
cell_size = 0.05
damping = 0.93
[[objects]]
type = "fish_school"
position = [0.0, 0.0, 0.0]
radius = 3.0
count = 1
speed = 2.0
depth = 1.5
jump_height = 1.0
jump_interval = 1.0
length = 0.6
)";

} // namespace

TEST_CASE("a fish stamps only while crossing the surface: up on the way out, down on the way in", "[fish]") {
    game::Sandbox sandbox(game::parseScene(FISH_SCENE, "fish.toml"));
    game::FishSchool& school = sandbox.world().pool<game::FishSchool>().components()[0];
    const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    const float r = school.sphere.radius, dt = 1.0f / 60.0f;
    REQUIRE(r == Approx(0.35f * 0.6f));  // smaller than the 0.6 m body
    int rising = 0, falling = 0, swimmingSteps = 0, airborneSteps = 0, badStamps = 0, wrongSign = 0;
    for (int step = 0; step < 600; ++step) {
        sandbox.step();
        const glm::vec3 p = school.position[0], v = school.velocity[0];
        const bool stamped = school.stamped[0] != 0;
        // Calm water: the surface is at 0 up to the ripples themselves (a few cm).
        const float gap = std::abs(p.y);  // centre to the mean surface
        if (!school.jumping[0]) ++swimmingSteps;
        if (p.y - r > 0.1f) ++airborneSteps;
        if (!stamped) continue;
        // Crossing: the sphere reaches the surface now, or passed through it within the step.
        if (gap > r + std::abs(v.y) * dt + 0.05f) ++badStamps;
        // Eq. 5 with SD from the motion: Vh(t) at the centre (now the previous level) went up
        // for a rising fish and down for a falling one.
        const float stampedHeight = patch->solverAs<ob::interaction::Kang2008Solver>()->field().previous()[size_t(std::lround(patch->toGrid({p.x, p.z}).y)) * 256 +
                                                              size_t(std::lround(patch->toGrid({p.x, p.z}).x))];
        if (v.y > 0.0f) ++rising, wrongSign += stampedHeight <= 0.0f;
        else ++falling, wrongSign += stampedHeight >= 0.0f;
    }
    INFO("rising stamps " << rising << ", falling " << falling << ", jumps " << school.jumps);
    CHECK(school.jumps >= 2);
    CHECK(swimmingSteps > 60);
    CHECK(airborneSteps > 20);
    CHECK(rising >= int(school.jumps) - 1);   // every completed jump stamped on the way out...
    CHECK(falling >= int(school.jumps) - 1);  // ...and on the way back
    CHECK(badStamps == 0);                    // never away from the surface
    CHECK(wrongSign == 0);
    CHECK(school.stamps == uint64_t(rising + falling));
}

TEST_CASE("fish swim their circle at their speed, the school is deterministic", "[fish]") {
    auto run = [](int steps) {
        game::Sandbox sandbox(game::parseScene(FISH_SCENE, "fish.toml", {"objects=[{type = \"fish_school\", count = 50, radius = 8.0}]"}));
        for (int i = 0; i < steps; ++i) sandbox.step();
        return sandbox.world().pool<game::FishSchool>().components()[0];
    };
    game::FishSchool a = run(120), b = run(120);
    REQUIRE(a.size() == 50);
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(a.position[i] == b.position[i]);
        const float lane = std::hypot(a.position[i].x, a.position[i].z);
        CHECK(lane == Approx(a.lane[i]).epsilon(1e-4));  // on its lane of the circle
        CHECK(lane > 0.84f * 8.0f);
        CHECK(lane < 1.16f * 8.0f);
        CHECK(std::hypot(a.velocity[i].x, a.velocity[i].z) == Approx(a.speed).epsilon(1e-5));
    }
}
