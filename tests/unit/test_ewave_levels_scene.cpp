// The default scene's wake with nested ewave levels (docs/ewave.md#levels): the trader (5 m/s,
// a 340 m loop round the player's ship, beyond the fine grid's 51 m) keeps a wake on the
// composite 300 m behind it along its track.
#include "behaviours/ship.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "world/sandbox.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace ob;

namespace {

// The composite's rms about its mean over a disc of `radius` m (1 m lattice) at world p, m.
double rmsAround(const interaction::RipplePatch& patch, glm::vec2 p, float radius) {
    double sum = 0.0, sum2 = 0.0;
    int count = 0;
    for (float x = -radius; x <= radius; x += 1.0f)
        for (float z = -radius; z <= radius; z += 1.0f) {
            if (x * x + z * z > radius * radius) continue;
            const double h = patch.heightAt(p + glm::vec2(x, z));
            sum += h;
            sum2 += h * h;
            ++count;
        }
    const double mean = sum / count;
    return std::sqrt(std::max(0.0, sum2 / count - mean * mean));
}

struct WakeAlong {
    std::vector<double> rms;  // per distance behind the ship along its track
};

// Runs the default scene (a coarser FFT grid: the ripple layer is the scene's) for `seconds`,
// records the trader's track, and reads the ripples' rms in 6 m discs on the track `behind`
// metres (arc length) back from the trader.
WakeAlong wakeAlongTrack(const std::vector<std::string>& overrides, float seconds, const std::vector<double>& behind) {
    game::SceneDef scene = game::loadScene(game::defaultScenePath(), overrides);
    game::Sandbox sandbox(scene);
    ecs::Entity trader{};
    auto& ships = sandbox.world().pool<game::Ship>();
    for (size_t i = 0; i < ships.size(); ++i)
        if (!ships.components()[i].def.player) trader = ships.entities()[i];
    std::vector<glm::vec2> track;
    for (int s = 0; s < int(seconds * 60.0f); ++s) {
        sandbox.step();
        const glm::vec3 p = sandbox.world().get<ecs::Transform>(trader).position;
        track.push_back({p.x, p.z});
    }
    const auto* patch = sandbox.world().resource<interaction::RipplePatch>();
    WakeAlong out;
    for (double d : behind) {
        double arc = 0.0;
        size_t i = track.size() - 1;
        while (i > 0 && arc < d) arc += glm::length(track[i] - track[i - 1]), --i;
        out.rms.push_back(rmsAround(*patch, track[i], 6.0f));
    }
    return out;
}

} // namespace

TEST_CASE("ewave levels: the default scene's trader keeps its wake 300 m behind it", "[ewave][levels][wake][long]") {
    const std::vector<double> behind{20.0, 100.0, 200.0, 300.0};
    const WakeAlong levels = wakeAlongTrack({"ocean.resolution=64"}, 75.0f, behind);
    const WakeAlong one = wakeAlongTrack({"ocean.resolution=64", "ripples.levels=1"}, 75.0f, behind);
    for (size_t k = 0; k < behind.size(); ++k)
        WARN(behind[k] << " m behind: rms " << levels.rms[k] << " m with levels = 3, " << one.rms[k] << " m with one grid");
    CHECK(levels.rms[3] >= 0.1 * levels.rms[0]);
}
