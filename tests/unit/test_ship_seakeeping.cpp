// Seakeeping: a hull much shorter than the dominant waves follows the slope of the sea it
// spans, so its RMS pitch (roll) is the RMS slope along (across) its keel of the waves
// longer than about twice its length (Lewis, "Principles of Naval Architecture" III §8:
// the "wave slope" limit of the response operator, |RAO| → 1 for λ ≫ L). Roll follows the
// slope across its beam likewise: the 3 m × 1.5 m × 10 m box at density 450 with its ballast
// (KG = 0.3 m) has GM = KB + BM − KG = 0.33 + 1.14 − 0.30 = 1.17 m from its hull's own
// waterplane and a natural roll frequency ≈ 3.5 rad/s, above the band of those waves
// (ω = sqrt(g·k) ≤ 1.75 rad/s at the cut): the response is quasi-static, amplified by at most
// 1/(1 − 0.5²) = 1.33 at the cut, and reduced by the water's motion fading with depth over
// its draft (the Smith effect, e^{−k·T} = 0.81 at the cut, 0.94 at the sea's peak). So roll is
// checked to lie between 0.8 and 2 times the slope (a uniform box, GM 0.72 m, rolls 1.4–1.7 times it:
// its 2.3 s period meets the 8 m waves the reference leaves out).
#include "ecs/components.h"
#include "behaviours/ship.h"
#include "sim/objects.h"
#include "world/sandbox.h"
#include "world/scene.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace ob;

namespace {

// The slope variance along direction ψ (radians from the wind) of a Phillips sea's waves
// with k < kc, integrated here on its own from the closed form (not the ocean's code):
//   ⟨(∂h/∂s)²⟩ = ∫∫ k²cos²(θ−ψ) · 2A·exp(−1/(k·Lw)²)/k⁴ · cos²θ · k dk dθ,   Lw = V²/g.
double phillipsSlopeVariance(double amplitude, double wind, double gravity, double kc, double psi) {
    const double lw = wind * wind / gravity;
    double radial = 0.0;  // ∫ exp(−1/(k·Lw)²)/k dk = ∫ exp(−1/(k·Lw)²) d(ln k), midpoint in ln k
    const int n = 4000;
    const double lo = std::log(1e-4), hi = std::log(kc), dl = (hi - lo) / n;
    for (int i = 0; i < n; ++i) {
        const double k = std::exp(lo + (i + 0.5) * dl);
        radial += std::exp(-1.0 / (k * lw * k * lw)) * dl;
    }
    double angular = 0.0;  // ∫ cos²(θ−ψ)·cos²θ dθ over the circle
    const int m = 720;
    for (int i = 0; i < m; ++i) {
        const double t = (i + 0.5) * 2.0 * M_PI / m;
        angular += std::pow(std::cos(t - psi) * std::cos(t), 2) * 2.0 * M_PI / m;
    }
    return 2.0 * amplitude * radial * angular;
}

struct Motion {
    double pitchRms = 0, rollRms = 0;        // measured, rad (about the mean)
    double pitchRef = 0, rollRef = 0;        // the wave-slope reference, rad
    float maxRoll = 0, minWet = 1;           // deg, fraction
};

// Every ship of the default scene at wind `wind`, `seconds` after a `settle` s start.
std::vector<Motion> measure(float wind, float seconds, float settle) {
    game::SceneDef scene = game::loadScene(game::defaultScenePath(),
                                           {"ocean.resolution=64", "ripples.enabled=false", "ocean.wind_speed=" + std::to_string(wind)});
    game::Sandbox sandbox(scene);
    auto& ships = sandbox.world().pool<game::Ship>();
    const glm::vec2 w = glm::normalize(scene.ocean.wind_direction);
    const double windAngle = std::atan2(w.y, w.x);
    std::vector<Motion> out(ships.size());
    std::vector<double> sumP(ships.size()), sumP2(ships.size()), sumR(ships.size()), sumR2(ships.size());
    const int skip = int(settle * 60.0f), steps = int(seconds * 60.0f);
    for (int step = 0; step < skip + steps; ++step) {
        sandbox.step();
        if (step < skip) continue;
        for (size_t i = 0; i < ships.size(); ++i) {
            const ecs::Entity e = ships.entities()[i];
            const auto& t = sandbox.world().get<ecs::Transform>(e);
            const glm::vec2 rp = glm::radians(game::rollPitchDeg(t.rotation));
            sumP[i] += rp.y, sumP2[i] += rp.y * rp.y, sumR[i] += rp.x, sumR2[i] += rp.x * rp.x;
            // The reference at this step's heading: pitch sees the slope along the keel
            // (wavelengths over twice the hull's length), roll the slope across it (over twice its beam
            // would be the same cut; the hull spans its length in any case, so one cut, the keel's).
            const glm::vec3 bow = t.rotation * glm::vec3(0, 0, 1);
            const double psi = std::atan2(bow.z, bow.x) - windAngle;
            const glm::vec3 hull = ships.components()[i].def.hull;
            const double kc = 2.0 * M_PI / (2.0 * hull.z);
            const double a = scene.ocean.amplitude, g = scene.ocean.gravity;
            out[i].pitchRef += phillipsSlopeVariance(a, wind, g, kc, psi);
            out[i].rollRef += phillipsSlopeVariance(a, wind, g, kc, psi + 0.5 * M_PI);
            out[i].maxRoll = std::max(out[i].maxRoll, std::abs(glm::degrees(rp.x)));
            out[i].minWet = std::min(out[i].minWet, sandbox.world().get<game::Body>(e).submergedFraction);
        }
    }
    for (size_t i = 0; i < out.size(); ++i) {
        const double mp = sumP[i] / steps, mr = sumR[i] / steps;
        out[i].pitchRms = std::sqrt(sumP2[i] / steps - mp * mp);
        out[i].rollRms = std::sqrt(sumR2[i] / steps - mr * mr);
        out[i].pitchRef = std::sqrt(out[i].pitchRef / steps);
        out[i].rollRef = std::sqrt(out[i].rollRef / steps);
    }
    return out;
}

} // namespace

TEST_CASE("in a 22 m/s storm a 10 m ship pitches as the slope of the waves longer than twice its length (within 35%), rolls 0.8-2x it, upright",
          "[ship][seakeeping][long]") {
    const std::vector<Motion> motions = measure(22.0f, 60.0f, 5.0f);
    REQUIRE(motions.size() >= 2);
    for (const Motion& m : motions) {
        INFO("pitch RMS " << glm::degrees(m.pitchRms) << " deg (reference " << glm::degrees(m.pitchRef) << "), roll RMS "
                          << glm::degrees(m.rollRms) << " deg (reference " << glm::degrees(m.rollRef) << "), max roll " << m.maxRoll
                          << " deg, min submerged " << m.minWet);
        CHECK(m.pitchRms == Approx(m.pitchRef).epsilon(0.35));
        CHECK(m.rollRms > 0.8 * m.rollRef);
        CHECK(m.rollRms < 2.0 * m.rollRef);
        CHECK(m.maxRoll < 45.0f);  // upright: no capsize
        CHECK(m.minWet > 0.0f);    // never thrown clear of the water (off a crest a hull is down to ~3% wetted)
        CHECK(m.minWet < 0.95f);   // never under
    }
}
