// The current layer moves what floats, and what floats moves it: a crate released in a uniform
// current takes up the current's speed; a stir sets the water turning and the turning water
// carries a ball away (none without the layer); a ship shoves a crate beside its track and
// draws one in its track along behind it; bodies and layer together keep their momentum.
#include "core/error.h"
#include "currents/current_layer.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "sim/water_systems.h"
#include "water/composite_water.h"
#include "world/camera.h"
#include "world/live_keys.h"
#include "world/sandbox.h"
#include "world/scene.h"
#include "world/tools.h"
#include "support/scripted_input.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace ob;
using namespace ob::test;  // the scripted input: push, at, runTo, pixelOf
using T = platform::InputEvent::Type;

namespace {

// Still water, no wind: nothing moves a body but what the test does. (The still sea's grid is
// the smallest, its heights are 0 at any size, and it has no foam to draw.)
const std::string STILL = "[window]\nwidth = 640\nheight = 360\n[ocean]\namplitude = 0.0\nwind_speed = 0.0\nresolution = 16\n"
                          "[gerstner]\ncount = 0\n[foam]\nenabled = false\n"
                          "[camera]\nmode = \"fixed\"\nposition = [0, 10, -20]\ntarget = [0, 0, 0]\n";

glm::vec3 position(game::Sandbox& sandbox, const std::string& name) {
    const ecs::Entity e = game::findObject(sandbox.world(), name);
    REQUIRE(e != ecs::Entity::None);
    return sandbox.world().get<ecs::Transform>(e).position;
}

glm::vec3 velocity(game::Sandbox& sandbox, const std::string& name) {
    return sandbox.world().get<ecs::Motion>(game::findObject(sandbox.world(), name)).velocity;
}

} // namespace

TEST_CASE("currents: a crate released in a uniform current takes up its speed", "[currents][water_motion]") {
    game::Sandbox sandbox(game::parseScene(STILL + "[ripples]\nenabled = false\n[currents]\nuniform = [1.0, 0.0]\n[[objects]]\ntype = \"box\"\nname = \"crate\"\n"
                                                   "size = [1.0, 0.6, 1.0]\ndensity = 400.0\nposition = [0, 0, 0]\n",
                                           "uniform.toml"));
    for (int i = 0; i < 60 * 30; ++i) sandbox.step();
    const glm::vec3 v = velocity(sandbox, "crate");
    INFO("crate velocity after 30 s: " << v.x << ", " << v.z << " m/s in a current of 1 m/s along x");
    CHECK(v.x == Approx(1.0).epsilon(0.05));
    CHECK(std::abs(v.z) < 0.05);
}

TEST_CASE("currents: a circular stir sets the water turning and carries a ball 1 m from it", "[currents][water_motion][tools]") {
    // The stir: the cursor's water point runs a circle of 0.3 m about the origin once a second
    // for 5 s (1.9 m/s), its sphere of 0.6 m sweeping the water to 0.9 m; the ball floats 1 m from
    // the stir's centre, at the edge of the water it turns. The turning water carries it round;
    // without the current layer only the stir's waves move it (their Stokes drift, outward:
    // the ripples' own horizontal velocity, a real transport, docs/currents.md#play).
    const auto moved = [](bool currents) {
        game::Sandbox sandbox(game::parseScene(STILL + "[ripples]\nmodel = \"ewave\"\n[tools]\ntool = \"stir\"\n[currents]\nenabled = " +
                                                   (currents ? "true" : "false") +
                                                   "\n[[objects]]\ntype = \"sphere\"\nname = \"ball\"\nradius = 0.15\ndensity = 500.0\n"
                                                   "position = [1.0, 0, 0]\n",
                                               "stir_ball.toml"));
        runTo(sandbox, 1.0);
        const glm::vec3 start = position(sandbox, "ball");
        const double t0 = sandbox.schedule().simTime() + 0.05;
        const auto point = [](double t) {
            const double a = 2.0 * M_PI * t;
            return glm::vec3(float(0.3 * std::cos(a)), 0.0f, float(0.3 * std::sin(a)));
        };
        push(sandbox, at(T::Move, t0, pixelOf(sandbox, point(0.0))));
        push(sandbox, at(T::ButtonDown, t0, pixelOf(sandbox, point(0.0))));
        for (int k = 1; k <= 300; ++k) push(sandbox, at(T::Move, t0 + k * DT, pixelOf(sandbox, point(k * DT))));
        push(sandbox, {T::ButtonUp, t0 + 5.01, platform::Key::W, platform::MouseButton::Left});
        runTo(sandbox, t0 + 8.0);
        const glm::vec3 end = position(sandbox, "ball");
        return glm::length(glm::vec2(end.x - start.x, end.z - start.z));
    };
    const float with = moved(true), without = moved(false);
    INFO("the ball moved " << with << " m with the current layer, " << without << " m without");
    CHECK(with >= 1.0f);
    CHECK(without < 0.5f * with);
}

TEST_CASE("currents: a passing ship shoves a crate beside its track and draws one in its track along", "[currents][water_motion][ship]") {
    // The ship runs along +z at 5 m/s from z = −30; one crate floats 8 m beside the track, one on
    // it. The hull pushes its water aside as it comes (a Rankine body: about q/(2π·r) = 0.25 m/s
    // at 8 m for q = U·B = 15 m²/s) and lets it back as it goes: the crate beside is shoved out,
    // then drawn part way back. The one in the track starts 3 m behind the stern and is towed
    // in the current the hull drags after it (the reactions of its resistance).
    const auto run = [](bool currents) {
        game::Sandbox sandbox(game::parseScene(
            STILL + "[ripples]\nmodel = \"ewave\"\nfollow = \"ship\"\n[currents]\nenabled = " + (currents ? "true" : "false") +
                "\n[[objects]]\ntype = \"ship\"\nname = \"ship\"\nposition = [0, 0.1, -30]\nspeed = 5.0\nvelocity = [0, 0, 5]\n"
                "[[objects]]\ntype = \"box\"\nname = \"beside\"\nsize = [0.8, 0.5, 0.8]\ndensity = 400.0\nposition = [8, 0, 0]\n"
                "[[objects]]\ntype = \"box\"\nname = \"track\"\nsize = [0.8, 0.5, 0.8]\ndensity = 400.0\nposition = [0, 0, -38]\n",
            "ship_crates.toml"));
        const glm::vec3 beside0 = position(sandbox, "beside");
        float away = 0.0f;  // the largest lateral displacement while the ship passes
        for (int i = 0; i < 60 * 14; ++i) {  // the ship passes both
            sandbox.step();
            away = std::max(away, position(sandbox, "beside").x - beside0.x);
        }
        return std::pair{away, position(sandbox, "track").z};
    };
    const auto [sideways, along] = run(true);
    const auto [sidewaysOff, alongOff] = run(false);
    INFO("the crate beside the track moved " << sideways << " m away from it (" << sidewaysOff << " without the layer); the one in the track is at z = "
                                             << along << " (" << alongOff << " without), from -38");
    CHECK(sideways >= 0.2f);
    CHECK(sidewaysOff < 0.5f * sideways);
    CHECK(along > -38.0f + 0.25f);
    CHECK(along - (-38.0f) > 2.0f * (alongOff - (-38.0f)));
}

TEST_CASE("currents: bodies and the layer keep their horizontal momentum between them", "[currents][water_motion]") {
    // No walls, no decay, no wind: a coasting ship (engine idle), a crate thrown at 4 m/s and a
    // ball trade momentum with the current layer through every horizontal water force (drag,
    // inertia, the hull model's resistance and keel): Σ m·v of the bodies + the layer's
    // ρ·d·Δ²·Σu stays what it was. (The air's drag, a ship's propeller and the stir are outside
    // forces: no air here, the propeller works below the layer, the stir is a hand.)
    game::Sandbox sandbox(game::parseScene(
        STILL + "[environment]\nair_density = 0.0\n[ripples]\nmodel = \"ewave\"\n[currents]\ndecay_time = 0.0\nwind_drift = 0.0\n"
                "[[objects]]\ntype = \"ship\"\nname = \"ship\"\nplayer = true\nposition = [0, 0.1, -10]\nvelocity = [0, 0, 4]\n"
                "[[objects]]\ntype = \"box\"\nname = \"crate\"\nsize = [0.8, 0.5, 0.8]\ndensity = 400.0\nposition = [6, 0.5, 0]\nvelocity = [-4, 0, 1]\n"
                "[[objects]]\ntype = \"sphere\"\nname = \"ball\"\nradius = 0.3\ndensity = 300.0\nposition = [-5, 0, 5]\n",
        "momentum.toml"));
    ecs::World& world = sandbox.world();
    const auto total = [&] {
        glm::dvec2 p(world.resource<currents::CurrentLayer>()->momentum());
        auto& bodies = world.pool<game::Body>();
        for (size_t i = 0; i < bodies.size(); ++i) {
            const ecs::Motion& m = world.get<ecs::Motion>(bodies.entities()[i]);
            p += double(m.mass) * glm::dvec2(m.velocity.x, m.velocity.z);
        }
        return p;
    };
    sandbox.step();  // the first step: the bodies' first forces and the layer's first impulses
    const glm::dvec2 start = total();
    double worst = 0.0, bodies = 0.0;
    for (int i = 0; i < 600; ++i) {
        sandbox.step();
        worst = std::max(worst, glm::length(total() - start));
    }
    auto& pool = world.pool<game::Body>();
    for (size_t i = 0; i < pool.size(); ++i) {
        const ecs::Motion& m = world.get<ecs::Motion>(pool.entities()[i]);
        bodies += double(m.mass) * glm::length(glm::dvec2(m.velocity.x, m.velocity.z));
    }
    const glm::dvec2 layer(world.resource<currents::CurrentLayer>()->momentum());
    INFO("momentum at the start " << glm::length(start) << " kg·m/s; largest change " << worst << "; the layer holds "
                                  << glm::length(layer) << " at the end, the bodies " << bodies);
    CHECK(worst <= 1e-4 * glm::length(start));
    CHECK(glm::length(layer) > 0.05 * glm::length(start));  // the layer did take a share
}

TEST_CASE("tide.toml: the flood carries the balls through the harbour gap, and alone wins nothing", "[currents][water_motion][scene][long]") {
    game::Sandbox sandbox(game::loadScene("config/scenes/tide.toml"));
    for (int s = 0; s < 60 * 50; ++s) sandbox.step();
    int through = 0;
    for (int k = 1; k <= 4; ++k)
        if (position(sandbox, "ball" + std::to_string(k)).z > 9.0f) ++through;  // past the breakwaters' line (z = 8 ± 0.6)
    INFO(through << " of 4 balls through the gap after 50 s");
    CHECK(through >= 2);
    auto* layer = sandbox.world().resource<currents::CurrentLayer>();
    const float gap = layer->velocityAt({0.0f, 8.0f}).y, wall = std::abs(layer->velocityAt({-10.0f, 8.0f}).y);
    INFO("the flow through the gap " << gap << " m/s, through the wall " << wall);
    CHECK(gap > 0.3f);
    CHECK(wall < 0.01f * gap);
}

TEST_CASE("tide.toml: a strong push back out through the mouth leaves the flood through the gap flowing in", "[currents][water_motion][scene]") {
    // The scene's [currents] and its breakwaters (the fixed boxes, wall to wall across the grid)
    // on a layer where the sandbox puts it (on the ripple patch's centre). After 20 s of flood a
    // push of 5 kN southward 2.5 m inside the mouth (a vigorous stir's stroke, ½ρ·C_d·A·v² for the
    // scene's 0.8 m stir sphere at 3 m/s, held for 10 s) drives a jet back out through the gap.
    // The scene's periodic layer makes the sea, the gap and the basin one circuit: the flood is
    // the whole patch's water moving, and the push takes a small share of it. The same scene with
    // the open edge (docs/currents.md#edges) loses most of its flood sideways through the sea's
    // open edges, and the same push nearly stops what is left: the open edge is not the tide's.
    const game::SceneDef scene = game::loadScene("config/scenes/tide.toml");
    REQUIRE(scene.currents.edge == currents::CurrentEdge::Periodic);
    std::vector<interaction::ObstacleShape> walls;
    for (const game::ObjectDef& o : scene.objects)
        if (o.type == game::ObjectType::Box && o.box.fixed)
            walls.push_back({interaction::ObstacleShape::Kind::Rect, {o.position.x, o.position.z}, {1.0f, 0.0f},
                             0.5f * glm::vec2(o.box.size.x, o.box.size.z)});
    REQUIRE(walls.size() == 2);
    const auto run = [&](currents::CurrentEdge edge) {
        currents::CurrentsDef def = scene.currents;
        def.edge = edge;
        currents::CurrentLayer layer(def, scene.environment.water_density);
        layer.centerOn(scene.ripples.center);
        layer.setWalls(walls);
        const auto gapFlux = [&] {  // m²/s into the harbour through the 8 m gap, on the breakwaters' line
            double q = 0.0;
            for (float x = -3.75f; x <= 3.75f; x += 0.5f) q += double(layer.velocityAt({x, 8.0f}).y) * 0.5;
            return q;
        };
        constexpr float PUSH = 5000.0f;  // N
        const float dt = float(DT);
        for (int s = 0; s < 60 * 20; ++s) layer.step(dt);
        const double flood = gapFlux();
        double least = flood;
        for (int s = 0; s < 60 * 15; ++s) {
            if (s < 60 * 10) layer.addImpulse({0.0f, 10.5f}, {0.0f, -PUSH * dt}, 1.0f);
            layer.step(dt);
            least = std::min(least, gapFlux());
        }
        CHECK(layer.finite());
        return std::pair{flood, least};
    };
    const auto [flood, least] = run(currents::CurrentEdge::Periodic);
    const auto [floodOpen, leastOpen] = run(currents::CurrentEdge::Open);
    INFO("periodic (the scene): the flood through the gap " << flood << " m²/s, its least under the push " << least
                                                            << "; with the open edge: " << floodOpen << ", least " << leastOpen);
    CHECK(flood > 4.0);          // 0.5 m/s across the 8 m gap at least
    CHECK(least > 0.5 * flood);  // the push takes a small share of the circuit's flow
    CHECK(floodOpen < 0.5 * flood);
    CHECK(leastOpen < 0.5 * floodOpen);
}

TEST_CASE("currents: a bad [currents] key is refused with the file, its line and the key", "[currents][scene_config]") {
    const auto refused = [](const std::string& text) {
        try {
            game::parseScene(text, "bad_currents.toml");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string range = refused("[sim]\nseed = 1\n[currents]\ndecay_time = -3.0\n");
    CHECK(range.find("bad_currents.toml:4") != std::string::npos);
    CHECK(range.find("decay_time") != std::string::npos);
    const std::string unknown = refused("[currents]\nspeed_of_river = 1.0\n");
    CHECK(unknown.find("bad_currents.toml:2") != std::string::npos);
    CHECK(unknown.find("speed_of_river") != std::string::npos);
    const std::string source = refused("[[currents.sources]]\ncenter = [0.0, 0.0]\nradius = 0.0\n");
    CHECK(source.find("bad_currents.toml:3") != std::string::npos);
    CHECK(source.find("radius") != std::string::npos);
    const std::string nan = refused("[currents]\nuniform = [nan, 0.0]\n");
    CHECK(nan.find("uniform") != std::string::npos);
    CHECK(game::checkLiveSet("currents.speed", 12.0f).find("[0, 10]") != std::string::npos);
}
