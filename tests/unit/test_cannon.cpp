// Cannon and cannonballs ([Kang2008] §V-1): a ball fired into calm water rings the ripple
// field; the ring is a circle around the impact, and its front runs at the speed eq. 1–2
// give long waves: Vh(t+1) − 2Vh(t) + Vh(t−1) ≈ ¾∇²Vh, so c = √3/2 cells per step.
#include "behaviours/cannon.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "interaction/sphere_set.h"
#include "sim/objects.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {

// Calm sea, the paper's cannonball setting: SR 5 cells (ball radius 0.5 m on 0.1 m cells),
// SHR 1, AF 0, DF 0.95. One shot at t = 0 that lands near the patch centre.
const char* RING_SCENE = R"(
[ocean]
amplitude = 0.0
resolution = 16
[gerstner]
count = 0
[ripples]
model = "kang2008"
resolution = 256
cell_size = 0.1
damping = 0.95
[[objects]]
type = "cannon"
name = "gun"
position = [0.0, 5.0, -12.4]
elevation_deg = 40.0
muzzle_speed = 8.0
ball_radius = 0.5
[[events]]
at = 0.0
action = "fire"
target = "gun"
)";

struct Ring {
    int front = 0;          ///< outermost radius (cells) where |circle mean| > 20% of the largest
    int crest = 0;          ///< radius of the leading crest (or trough): largest |mean| within 8 cells inside the front
    float sameSign = 0.0f;  ///< fraction of the circle at the crest sharing the mean's sign
    float mean = 0.0f;      ///< circle mean at the crest, m
};

// The field on circles of radius r = 1..90 cells around `centre` (128 samples each).
Ring ringAround(const interaction::RipplePatch& patch, glm::vec2 centre) {
    const float cell = patch.def().cell_size;
    const int SAMPLES = 128;
    std::vector<float> mean(91, 0.0f), same(91, 0.0f);
    float largest = 0.0f;
    for (int r = 1; r <= 90; ++r) {
        float sum = 0.0f;
        int positive = 0;
        for (int a = 0; a < SAMPLES; ++a) {
            const float angle = 2.0f * float(M_PI) * float(a) / float(SAMPLES);
            const float h = patch.heightAt(centre + float(r) * cell * glm::vec2(std::cos(angle), std::sin(angle)));
            sum += h;
            positive += h > 0.0f ? 1 : 0;
        }
        mean[size_t(r)] = sum / float(SAMPLES);
        same[size_t(r)] = float(mean[size_t(r)] > 0.0f ? positive : SAMPLES - positive) / float(SAMPLES);
        largest = std::max(largest, std::abs(mean[size_t(r)]));
    }
    Ring ring;
    for (int r = 1; r <= 90; ++r)
        if (std::abs(mean[size_t(r)]) > 0.2f * largest) ring.front = r;
    ring.crest = ring.front;
    for (int r = std::max(1, ring.front - 8); r <= ring.front; ++r)
        if (std::abs(mean[size_t(r)]) > std::abs(mean[size_t(ring.crest)])) ring.crest = r;
    ring.sameSign = same[size_t(ring.crest)];
    ring.mean = mean[size_t(ring.crest)];
    return ring;
}

} // namespace

TEST_CASE("a cannonball's impact rings the ripple field: one sign around each circle, front at sqrt(3)/2 cell per step", "[cannon]") {
    game::Sandbox sandbox(game::parseScene(RING_SCENE, "ring.toml"));
    auto& balls = sandbox.world().pool<game::Cannonball>();
    const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    // Fly until the ball has crossed the surface; the impact point is the mean position of
    // the steps in which its sphere straddled the surface it met (Table 2 step 3).
    glm::vec2 impact(0.0f);
    int crossing = 0, sinceImpact = -1;
    std::vector<Ring> rings;
    for (int step = 0; step < 400 && rings.size() < 2; ++step) {
        sandbox.step();
        if (balls.size() == 1) {
            const auto& set = sandbox.world().get<interaction::SphereSet>(balls.entities()[0]);
            const glm::vec3 p = sandbox.world().get<ecs::Transform>(balls.entities()[0]).position;
            if (set.contacts[0].inContact() && std::abs(p.y - set.contacts[0].fixHeight) <= set.spheres[0].radius) {
                impact += glm::vec2(p.x, p.z);
                ++crossing;
                sinceImpact = 0;
            }
        }
        if (sinceImpact >= 0 && (++sinceImpact == 30 || sinceImpact == 70)) rings.push_back(ringAround(*patch, impact / float(crossing)));
    }
    REQUIRE(crossing >= 2);
    REQUIRE(rings.size() == 2);
    INFO("impact " << impact.x / crossing << ", " << impact.y / crossing << " after " << crossing << " crossing steps");
    INFO("ring front " << rings[0].front << " cells 30 steps after impact, " << rings[1].front << " cells at 70 steps ("
                       << float(rings[1].front - rings[0].front) / 40.0f << " cells/step; eq. 1-2 long waves: 0.866); crest at "
                       << rings[0].crest << ", " << rings[1].crest << " cells, same sign " << rings[0].sameSign << ", "
                       << rings[1].sameSign);
    // A ring: at its front the whole circle is raised (or lowered) together.
    CHECK(rings[0].sameSign > 0.9f);
    CHECK(rings[1].sameSign > 0.9f);
    // It spreads at the long-wave speed of eq. 1–2 (its front lags that bound a little:
    // shorter waves in the splash travel slower).
    const float speed = float(rings[1].front - rings[0].front) / 40.0f;
    CHECK(speed > 0.65f);
    CHECK(speed < 0.95f);
    // And it weakens as it spreads and DF damps it.
    CHECK(std::abs(rings[1].mean) < std::abs(rings[0].mean));
}

TEST_CASE("cannons fire on events and at their rate, balls sink and are removed below the sink depth", "[cannon]") {
    std::string text = RING_SCENE;
    text.replace(text.find("ball_radius"), 0, "sink_depth = 3.0\n");
    game::SceneDef scene = game::parseScene(text + "[[events]]\nat = 0.5\naction = \"fire\"\n", "fire.toml");
    game::Sandbox sandbox(scene);
    auto& cannons = sandbox.world().pool<game::Cannon>();
    auto& balls = sandbox.world().pool<game::Cannonball>();
    sandbox.step();
    CHECK(cannons.components()[0].shots == 1);  // the event at 0 s
    CHECK(balls.size() == 1);
    for (int i = 0; i < 30; ++i) sandbox.step();
    CHECK(cannons.components()[0].shots == 2);  // the event at 0.5 s (step 30)
    // An iron ball sinks: both are gone once below 3 m (a few seconds).
    int gone = -1;
    for (int i = 0; i < 600 && gone < 0; ++i) {
        sandbox.step();
        if (balls.size() == 0) gone = i;
    }
    CHECK(gone > 0);
    CHECK(sandbox.world().resource<physics::PhysicsWorld>()->bodyCount() == 1);  // the cannon's pillar, a static body
    // rate = 2 shots/s: shots at 0, 0.5, 1 and 1.5 s within the first two seconds (the event
    // at 0 s asks in the same step as the first automatic shot: one ball).
    text = RING_SCENE;
    text.replace(text.find("ball_radius"), 0, "rate = 2.0\n");
    game::Sandbox rated(game::parseScene(text, "rate.toml"));
    for (int i = 0; i < 120; ++i) rated.step();
    CHECK(rated.world().pool<game::Cannon>().components()[0].shots == 4);
}

TEST_CASE("paper bounding spheres are sized in metres: the ripple cell size changes neither a ball's nor a ship's", "[cannon][ship]") {
    // A cell size only turns metres into SR cells where a sphere stamps (planStamp), so the
    // splash crowns and the wake foam, which read the radius in metres, do not depend on it.
    auto spheres = [](const char* cellSize) {
        game::Sandbox sandbox(game::parseScene(std::string("[ripples]\nmodel = \"kang2008\"\ncell_size = ") + cellSize +
                                                   "\n[[objects]]\ntype = \"cannon\"\nball_radius = 0.3\n"
                                                   "[[objects]]\ntype = \"ship\"\nposition = [0.0, 0.3, 20.0]\n",
                                               "spheres.toml"));
        ecs::World& world = sandbox.world();
        std::pair<float, float> radii{0.0f, 0.0f};  // ball, ship
        for (const game::Cannon& c : world.pool<game::Cannon>().components()) radii.first = c.ballSphere.radius;
        auto& sets = world.pool<interaction::SphereSet>();
        for (size_t k = 0; k < sets.size(); ++k)
            if (sets.components()[k].hull) radii.second = sets.components()[k].spheres.at(0).radius;
        return radii;
    };
    const auto fine = spheres("0.1"), coarse = spheres("0.3");
    CHECK(fine.first == 0.3f);   // the ball itself
    CHECK(fine.second == 1.4f);  // [Kang2008]'s SR 7 on the ship scene's 0.2 m cells
    CHECK(coarse == fine);
}
