// The harbour scene (config/scenes/harbour.toml): fixed walls, a pier and a post obstruct the
// ripple layer. It is deterministic, nothing moves inside a wall, and a ring
// raised in front of the breakwater reaches the harbour through the gap only: behind the gap
// the water moves, behind the walls it barely does (a wall 6 cells thick keeps 1 %, by energy,
// of what passes a gap as wide, test_obstacles.cpp's shadow bound being 10 %).
#include "interaction/ripple_patch.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace ob;

namespace {

std::string scenePath(const char* name) { return std::string(OCEANBOX_SOURCE_DIR) + "/config/scenes/" + name; }

// Σ h² over the patch cells whose world (x, z) lies in [x0, x1) × [z0, z1), and their count.
std::pair<double, int> energyIn(const interaction::RipplePatch& patch, float x0, float x1, float z0, float z1) {
    double e = 0.0;
    int cells = 0;
    const float cell = patch.def().cell_size;
    for (int z = 0; z < patch.rows(); ++z)
        for (int x = 0; x < patch.cols(); ++x) {
            const glm::vec2 w = patch.origin() + glm::vec2(float(x), float(z)) * cell;
            if (w.x < x0 || w.x >= x1 || w.y < z0 || w.y >= z1) continue;
            const double h = patch.height()[size_t(z) * size_t(patch.cols()) + size_t(x)];
            e += h * h;
            ++cells;
        }
    return {e, cells};
}

} // namespace

TEST_CASE("harbour: the scene is deterministic and the walls hold the water still", "[obstacles][harbour]") {
    auto run = [] {
        game::Sandbox sandbox(game::loadScene(scenePath("harbour.toml")));
        for (int i = 0; i < 240; ++i) sandbox.step();  // the cannon has fired (at 0 s) and the ball has landed
        const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
        REQUIRE(patch);
        CHECK(!patch->obstruction().empty());
        // The breakwater's middle cells are solid (keep 0): their water does not move (it holds
        // only the even shares of the mean level the projection spread, 2e-5 m here).
        const glm::vec2 g = patch->toGrid({-13.0f, 8.0f});
        const size_t i = size_t(std::lround(g.y)) * size_t(patch->cols()) + size_t(std::lround(g.x));
        CHECK(std::abs(patch->height()[i]) < 1e-4f);
        return sandbox.stateHash();
    };
    CHECK(run() == run());
}

TEST_CASE("harbour: a ring in front of the breakwater enters through the gap", "[obstacles][harbour]") {
    // No cannon shots, no sea, the boats moored off the patch (their own ripples are not the
    // point here): a bump of 5 cm (σ 0.6 m) raised 6 m in front of the gap.
    game::Sandbox sandbox(game::loadScene(scenePath("harbour.toml"),
                                          {"objects[7].rate=0", "ocean.amplitude=0", "events=[]", "objects[4].position=[100, 0.2, 100]",
                                           "objects[5].position=[120, 0.2, 100]", "objects[6].position=[140, 0.2, 100]"}));
    sandbox.step();
    auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    REQUIRE(patch);
    const float cell = patch->def().cell_size;
    for (int z = 0; z < patch->rows(); ++z)
        for (int x = 0; x < patch->cols(); ++x) {
            const glm::vec2 w = patch->origin() + glm::vec2(float(x), float(z)) * cell - glm::vec2(0.0f, 2.0f);
            const float r2 = glm::dot(w, w);
            if (r2 < 9.0f) patch->solver().addHeight(x, z, 0.05 * std::exp(-r2 / (2.0 * 0.36)));
        }
    // Behind the gap (|x| < 2) and behind the walls (3 to 11 m from the gap's middle, either
    // side), a band 1.5 to 5 m past the breakwater, h² summed over 8 s.
    double gap = 0.0, walls = 0.0;
    int gapCells = 0, wallCells = 0;
    for (int i = 0; i < 480; ++i) {
        sandbox.step();
        const auto [g, gc] = energyIn(*patch, -2.0f, 2.0f, 9.5f, 13.0f);
        const auto [w1, c1] = energyIn(*patch, -11.0f, -3.0f, 9.5f, 13.0f);
        const auto [w2, c2] = energyIn(*patch, 3.0f, 11.0f, 9.5f, 13.0f);
        gap += g;
        walls += w1 + w2;
        gapCells = gc;
        wallCells = c1 + c2;
    }
    const double perGap = gap / gapCells, perWall = walls / wallCells;
    INFO("h² per cell over 8 s: behind the gap " << perGap << ", behind the walls " << perWall);
    REQUIRE(perGap > 0.0);
    CHECK(perWall < 0.1 * perGap);
}
