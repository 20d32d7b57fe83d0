// The player's tools, driven through the input queue as a window or a script drives them:
// the pick lies on the surface drawn (not on y = 0) at steep and grazing views, on crests
// and in troughs; a drop lands under the click; a grabbed crate follows the cursor and flies
// on when let go; the stir's ripples grow with its speed; erase takes exactly the body under
// the cursor; the cannon tool's ball comes down where the player clicked.
#include "world/tools.h"
#include "behaviours/cannon.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/camera.h"
#include "world/picking.h"
#include "support/scripted_input.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <glm/glm.hpp>

using namespace ob;
using platform::InputEvent;
using T = InputEvent::Type;

namespace {

using test::at;
using test::DT;
using test::pixelOf;
using test::push;
using test::runTo;
using test::SIZE;
using test::view;

// A still sea (no swell, no FFT waves), a fixed camera 10 m up looking at the origin.
const std::string CALM = "[window]\nwidth = 640\nheight = 360\n[ocean]\namplitude = 0.0\nresolution = 16\n[gerstner]\ncount = 0\n"
                         "[camera]\nmode = \"fixed\"\nposition = [0, 10, -20]\ntarget = [0, 0, 0]\n";

void tap(game::Sandbox& sandbox, platform::Key key, double time) {
    push(sandbox, {T::KeyDown, time, key});
    push(sandbox, {T::KeyUp, time, key});
}

void click(game::Sandbox& sandbox, glm::vec2 pixel, double time, double hold = 0.05) {
    push(sandbox, at(T::Move, time, pixel));
    push(sandbox, at(T::ButtonDown, time, pixel));
    push(sandbox, {T::ButtonUp, time + hold, platform::Key::W, platform::MouseButton::Left});
}

// Where the pixel's ray meets y = 0: the calm sea, by hand (the view's own matrices inverted).
glm::vec3 onPlane(game::Sandbox& sandbox, glm::vec2 pixel) {
    const game::Ray ray = game::pixelRay(view(sandbox), SIZE, pixel);
    return ray.at(-ray.origin.y / ray.direction.y);
}


const ecs::Transform* body(game::Sandbox& sandbox, const std::string& name) {
    const ecs::Entity e = game::findObject(sandbox.world(), name);
    return e == ecs::Entity::None ? nullptr : sandbox.world().find<ecs::Transform>(e);
}

} // namespace

TEST_CASE("picking: the hit lies on the drawn surface within 2 cm, the first crossing, at steep and grazing views", "[tools]") {
    // A rough sea (14 m/s, two cascades, swell) with ripples from a dropped ball.
    game::Sandbox sandbox(game::parseScene("[ocean]\nwind_speed = 14.0\ncascades = 2\n[gerstner]\ncount = 6\n"
                                           "[ripples]\nmodel = \"ewave\"\n"
                                           "[[objects]]\ntype = \"sphere\"\nposition = [0, 3, 10]\nradius = 0.5\n",
                                           "rough.toml"));
    runTo(sandbox, 1.5);
    const water::WaterQuery& water = *sandbox.world().resource<game::OceanState>()->water;
    int crests = 0, troughs = 0, hits = 0;
    for (const glm::vec3 eye : {glm::vec3(0, 30, 0), glm::vec3(0, 6, -40), glm::vec3(3, 2.5f, -60)})
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 9; ++j) {
                // Straight down from 30 m (steep) to 2 % under the horizon from 2.5 m (grazing).
                const glm::vec3 look = glm::normalize(glm::vec3(0.08f * float(i - 4), -0.02f - 0.12f * float(j), 1.0f));
                const game::Ray ray{eye, eye.y > 20.0f ? glm::normalize(glm::vec3(0.05f * float(i - 4), -1.0f, 0.05f * float(j - 4))) : look};
                const std::optional<glm::vec3> hit = game::pickWater(water, ray, 3000.0f);
                REQUIRE(hit);
                ++hits;
                const water::WaterSample s = water.sample(hit->x, hit->z);
                INFO("eye " << eye.y << " ray " << ray.direction.x << " " << ray.direction.y << " " << ray.direction.z);
                CHECK(std::abs(hit->y - s.height) < 0.02f);
                // Nothing of the ray before it is under the water (5 cm steps).
                const float tHit = glm::length(*hit - eye);
                bool above = true;
                for (float t = 0.0f; t < tHit - 0.05f; t += 0.05f) {
                    const glm::vec3 p = ray.at(t);
                    above = above && p.y > water.sample(p.x, p.z).height - 0.02f;
                }
                CHECK(above);
                crests += s.height > 0.4f;
                troughs += s.height < -0.4f;
            }
    CHECK(hits == 3 * 81);
    // The sample covers crests and troughs, where a pick against y = 0 would be off by > 0.4 m.
    CHECK(crests > 5);
    CHECK(troughs > 5);
}

TEST_CASE("drop tool: a ball dropped by a click lands within 0.5 m of the clicked water point", "[tools]") {
    game::Sandbox sandbox(game::parseScene(CALM, "calm.toml"));
    const glm::vec2 pixel(400.0f, 250.0f);
    const glm::vec3 aimed = onPlane(sandbox, pixel);
    tap(sandbox, platform::Key::Num3, 0.1);
    click(sandbox, pixel, 0.3);
    runTo(sandbox, 3.0);
    const ecs::Transform* ball = body(sandbox, "ball_1");
    REQUIRE(ball);
    CHECK(glm::length(glm::vec2(ball->position.x - aimed.x, ball->position.z - aimed.z)) < 0.5f);
    CHECK(std::abs(ball->position.y) < 0.5f);  // afloat: 600 kg/m³
    // 3 again: the next object; a crate is a body too.
    tap(sandbox, platform::Key::Num3, 3.1);
    click(sandbox, {200.0f, 250.0f}, 3.3);
    runTo(sandbox, 4.0);
    CHECK(body(sandbox, "crate_2"));
}

TEST_CASE("grab tool: a crate follows the cursor's drag and flies on after the release", "[tools]") {
    game::Sandbox sandbox(game::parseScene(CALM + "[[objects]]\ntype = \"box\"\nname = \"crate\"\nposition = [0, 0, 0]\n"
                                                  "size = [1, 1, 1]\ndensity = 400.0\n",
                                           "grab.toml"));
    runTo(sandbox, 1.0);  // settles afloat
    const glm::vec3 start = body(sandbox, "crate")->position;
    const glm::vec2 pixel = pixelOf(sandbox, start + glm::vec3(0.0f, 0.45f, 0.0f));
    push(sandbox, at(T::Move, 1.05, pixel));
    push(sandbox, at(T::ButtonDown, 1.05, pixel));
    // Drag 120 px right and 80 px up over 1 s, hold still 0.6 s, then flick 60 px right in
    // 0.2 s and let go during the flick.
    for (int k = 1; k <= 30; ++k) push(sandbox, at(T::Move, 1.05 + k / 30.0, pixel + glm::vec2(4.0f, -2.67f) * float(k)));
    const glm::vec2 lifted = pixel + glm::vec2(120.0f, -80.0f);
    for (int k = 1; k <= 12; ++k) push(sandbox, at(T::Move, 2.65 + k / 60.0, lifted + glm::vec2(5.0f * float(k), 0.0f)));
    push(sandbox, {T::ButtonUp, 2.85, platform::Key::W, platform::MouseButton::Left});
    runTo(sandbox, 2.6);
    const auto& tools = *sandbox.world().resource<game::PlayerTools>();
    REQUIRE(tools.grabbed != ecs::Entity::None);
    const glm::vec3 held = body(sandbox, "crate")->position;
    // Screen right is world −x for this camera (it looks along +z): the crate is out of the
    // water, moved toward the cursor, and the point taken hangs at the cursor's ray.
    CHECK(held.x < start.x - 1.5f);
    CHECK(held.y > start.y + 0.5f);
    const glm::quat turn = sandbox.world().get<ecs::Transform>(game::findObject(sandbox.world(), "crate")).rotation;
    CHECK(glm::length(held + turn * tools.grabLocal - tools.target) < 0.2f);
    runTo(sandbox, 2.9);
    CHECK(tools.grabbed == ecs::Entity::None);
    CHECK(tools.throws == 1);
    // Thrown: it flies on the way the cursor went (−x), faster than a metre a second.
    const glm::vec3 released = body(sandbox, "crate")->position;
    runTo(sandbox, 3.2);
    CHECK(body(sandbox, "crate")->position.x < released.x - 0.3f);
}

TEST_CASE("stir tool: the ripples it makes grow with the speed of the stroke, up to the wave-making speed", "[tools]") {
    // The stroke: the source's water point moves along x at `speed` m/s for 1 s (its pixels
    // from the view, by hand), then the button is let go; the ripple energy ∫h² is read 0.5 s on.
    const auto energy = [](float speed) {
        game::Sandbox sandbox(game::parseScene(CALM + "[ripples]\nmodel = \"ewave\"\n[tools]\ntool = \"stir\"\n", "stir.toml"));
        const glm::vec3 from(2.0f, 0.0f, 0.0f);
        push(sandbox, at(T::Move, 0.05, pixelOf(sandbox, from)));
        push(sandbox, at(T::ButtonDown, 0.05, pixelOf(sandbox, from)));
        for (int k = 1; k <= 60; ++k)
            push(sandbox, at(T::Move, 0.05 + k / 60.0, pixelOf(sandbox, from - glm::vec3(speed * float(k) / 60.0f, 0.0f, 0.0f))));
        push(sandbox, {T::ButtonUp, 1.07, platform::Key::W, platform::MouseButton::Left});
        runTo(sandbox, 1.5);
        const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
        double e = 0.0;
        const float half = 0.5f * patch->def().cell_size * float(patch->def().resolution);
        for (float x = -half; x < half; x += 0.25f)
            for (float z = -half; z < half; z += 0.25f) e += double(patch->heightAt({x, z})) * double(patch->heightAt({x, z}));
        return e;
    };
    // The source is a pressure patch of radius 0.6 m: its waves grow with its speed while the
    // speed is below about √(g·R) ≈ 2.4 m/s (a moving pressure makes the most waves near a
    // Froude number of order 1, fewer above: it passes a point too briefly to lift it). Below
    // 0.5 m/s the rings of its entry and exit, the same at any speed, are most of it.
    const double e05 = energy(0.5f), e1 = energy(1.0f), e15 = energy(1.5f), e2 = energy(2.0f), e6 = energy(6.0f);
    INFO("0.5 m/s " << e05 << "  1 m/s " << e1 << "  1.5 m/s " << e15 << "  2 m/s " << e2 << "  6 m/s " << e6);
    CHECK(e05 > 0.0);
    CHECK(e1 > e05);
    CHECK(e15 > e1);
    CHECK(e2 > e15);
    CHECK(e2 > 2.0 * e05);
    CHECK(e6 < e2);  // past the wave-making speed
}

TEST_CASE("erase tool: a click removes exactly the body under the cursor", "[tools]") {
    game::Sandbox sandbox(game::parseScene(CALM + "[tools]\ntool = \"erase\"\n"
                                                  "[[objects]]\ntype = \"sphere\"\nname = \"left\"\nposition = [3, 0, 0]\n"
                                                  "[[objects]]\ntype = \"sphere\"\nname = \"right\"\nposition = [-3, 0, 0]\n",
                                           "erase.toml"));
    runTo(sandbox, 0.5);
    click(sandbox, pixelOf(sandbox, body(sandbox, "right")->position + glm::vec3(0.0f, 0.3f, 0.0f)), 0.55);
    click(sandbox, {320.0f, 20.0f}, 0.7);  // the sky: nothing
    runTo(sandbox, 1.0);
    CHECK(body(sandbox, "left"));
    CHECK_FALSE(body(sandbox, "right"));
    CHECK(sandbox.world().resource<game::PlayerTools>()->erased == 1);
}

TEST_CASE("cannon tool: the ball comes down within 1 m of the clicked point on calm water", "[tools]") {
    game::Sandbox sandbox(game::parseScene(CALM + "[[objects]]\ntype = \"cannon\"\nplayer = true\nposition = [0, 4, -15]\n"
                                                  "muzzle_speed = 30.0\n",
                                           "cannon.toml"));
    tap(sandbox, platform::Key::Num5, 0.05);
    for (const glm::vec2 pixel : {glm::vec2(320.0f, 200.0f), glm::vec2(150.0f, 260.0f), glm::vec2(520.0f, 190.0f)}) {
        const glm::vec3 aimed = onPlane(sandbox, pixel);
        const double t0 = sandbox.schedule().simTime() + 0.05;
        click(sandbox, pixel, t0);
        runTo(sandbox, t0 + 0.1);
        // The newest ball: follow it to the surface.
        auto& balls = sandbox.world().pool<game::Cannonball>();
        REQUIRE(balls.size() > 0);
        const ecs::Entity ball = balls.entities().back();
        glm::vec3 landed(0.0f);
        for (int k = 0; k < 600 && landed == glm::vec3(0.0f); ++k) {
            runTo(sandbox, sandbox.schedule().simTime() + DT);
            const glm::vec3 p = sandbox.world().get<ecs::Transform>(ball).position;
            if (p.y < 0.0f) landed = p;
        }
        INFO("aimed " << aimed.x << " " << aimed.z << " landed " << landed.x << " " << landed.z);
        CHECK(glm::length(glm::vec2(landed.x - aimed.x, landed.z - aimed.z)) < 1.0f);
    }
}

TEST_CASE("ballistic elevation: the low arc reaches the point, none beyond the reach", "[tools]") {
    // v = 20 m/s, g = 10: on level ground the reach is v²/g = 40 m at 45°; 20 m needs 15°.
    CHECK(*game::ballisticElevationDeg({0, 0, 0}, {20, 0, 0}, 20.0f, 10.0f) == Approx(15.0f).margin(1e-3));
    CHECK(*game::ballisticElevationDeg({0, 0, 0}, {0, 0, 40}, 20.0f, 10.0f) == Approx(45.0f).margin(0.05));
    CHECK_FALSE(game::ballisticElevationDeg({0, 0, 0}, {41, 0, 0}, 20.0f, 10.0f));
}
