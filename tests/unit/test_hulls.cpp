// Floating hulls in the ripple layer (interaction/obstruction.h, docs/ewave.md#hulls) against
// theory: a hull's mask pushes what it removes just outside its outline and nowhere else, so the mean level (the k = 0 mode) is kept to rounding with a hull moving over a
// periodic field; a ring from a drop reflects off a moored hull and leaves a shadow behind it;
// a hull's waterplane follows its roll as the geometry of a cut box says.
#include "interaction/ewave/ewave_solver.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/obstruction.h"
#include "sim/obstacles.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

using namespace ob::interaction;

namespace {

constexpr float CELL = 0.1f;  // m

// A displacing ellipse (a hull's waterplane) of semi-axes `half` (m, first along x) at `centre`.
ObstacleShape hull(glm::vec2 centre, glm::vec2 half) {
    ObstacleShape s{ObstacleShape::Kind::Ellipse, centre, {1.0f, 0.0f}, half};
    s.displaces = true;
    return s;
}

std::vector<ObstructionCell> rasterise(const ObstacleShape& s, int n) {
    std::vector<ObstructionCell> cells;
    rasteriseObstacles(std::span(&s, 1), n, n, CELL, [](glm::vec2 w) { return w / CELL; }, cells);
    return cells;
}

double sum(std::span<const double> level) { return std::accumulate(level.begin(), level.end(), 0.0); }

double sumAbs(std::span<const double> level) {
    return std::accumulate(level.begin(), level.end(), 0.0, [](double a, double b) { return a + std::abs(b); });
}

// Σ h² over rows [z0, z1) × columns [x0, x1) of an n-wide field.
double energyIn(const EWaveField& f, int x0, int x1, int z0, int z1) {
    double e = 0.0;
    for (int z = z0; z < z1; ++z)
        for (int x = x0; x < x1; ++x) e += std::pow(f.heightState()[size_t(z) * size_t(f.cols()) + size_t(x)], 2.0);
    return e;
}

} // namespace

TEST_CASE("hulls: what a hull's mask removes lands just outside it, all of it, and nowhere else", "[obstacles][hulls]") {
    // Random water under a 1.2 m × 0.5 m hull on a 64² grid of 0.1 m cells.
    const int n = 64;
    const ObstacleShape h = hull({3.2f, 3.2f}, {1.2f, 0.5f});
    const std::vector<ObstructionCell> cells = rasterise(h, n);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::vector<double> level(size_t(n) * n);
    for (double& v : level) v = noise(rng);
    const std::vector<double> before = level;
    obstructKeepingMean(std::span(level), std::span<const ObstructionCell>(cells));
    double removed = 0.0, inside = 0.0;
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const size_t i = size_t(z) * n + size_t(x);
            const float d = h.distance(glm::vec2(x, z) * CELL) / CELL;  // cells from the outline
            if (d <= -0.5f) inside = std::max(inside, std::abs(level[i]));  // wholly inside: emptied
            if (d < 0.5f) removed += before[i] - level[i];
            // Past where the displaced water lands (its bilinear footprint) the water is untouched, bit for bit.
            if (d >= DISPLACEMENT_OFFSET_CELLS + 2.5f) CHECK(level[i] == before[i]);
        }
    INFO("removed " << removed << ", Σ before " << sum(before) << ", after " << sum(level));
    CHECK(std::abs(removed) > 1e-3);                                   // the mask did take water
    CHECK(inside == 0.0);                                              // none left inside the hull
    CHECK(std::abs(sum(level) - sum(before)) <= 1e-12 * sumAbs(before));  // and the water round it got all of it back

    // A fixed body of the same outline spreads it over the whole grid instead: far cells move.
    ObstacleShape fixed = h;
    fixed.displaces = false;
    const std::vector<ObstructionCell> fixedCells = rasterise(fixed, n);
    std::vector<double> spread = before;
    obstructKeepingMean(std::span(spread), std::span<const ObstructionCell>(fixedCells));
    CHECK(spread[0] != before[0]);
}

TEST_CASE("hulls: a hull moving over a periodic field keeps the mean level to 1e-12 (ewave and kang2008)", "[obstacles][hulls]") {
    // A bump of water and a 1.5 m × 0.4 m hull crossing it at 3 m/s (a cell per 2 steps), 240
    // steps of 1/60 s, no damping. The step keeps Σh (k = 0); the projection must too.
    const int n = 128;
    const float dt = 1.0f / 60.0f;
    auto hullAt = [&](int s) { return hull({2.0f + 3.0f * dt * float(s), 6.4f}, {1.5f, 0.4f}); };
    SECTION("ewave") {
        EWaveField f(n, n, CELL, RippleBoundary::Periodic);
        f.setDamping(0.0f, 0.0f);
        auto h = f.editHeight();
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) h[size_t(z) * n + x] = 0.02 * std::exp(-(std::pow(x - 64.0, 2) + std::pow(z - 64.0, 2)) / 50.0);
        f.syncHeight();
        const double start = sum(f.heightState()), scale = sumAbs(f.heightState());
        double worstProjection = 0.0;
        for (int s = 0; s < 240; ++s) {
            f.step(dt);
            const double beforeProjection = sum(f.heightState());
            obstructField(f, rasterise(hullAt(s), n));
            worstProjection = std::max(worstProjection, std::abs(sum(f.heightState()) - beforeProjection));
        }
        INFO("Σh " << start << " → " << sum(f.heightState()) << ", Σ|h| " << scale << ", worst change by one projection "
                   << worstProjection);
        CHECK(worstProjection <= 1e-12 * scale);
        CHECK(std::abs(sum(f.heightState()) - start) <= 1e-12 * scale);
    }
    SECTION("kang2008: its float levels, to their rounding") {
        RippleField f(n, n, RippleBoundary::Periodic);
        auto cur = f.current();
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) cur[size_t(z) * n + x] = 0.02f * std::exp(-float(std::pow(x - 64.0, 2) + std::pow(z - 64.0, 2)) / 50.0f);
        std::copy(cur.begin(), cur.end(), f.previous().begin());
        auto total = [&] { return std::accumulate(f.current().begin(), f.current().end(), 0.0); };
        double worst = 0.0, scale = 0.0;
        for (float v : f.current()) scale += std::abs(v);
        for (int s = 0; s < 240; ++s) {
            f.step(1.0f);  // no damping
            const double before = total();
            const std::vector<ObstructionCell> cells = rasterise(hullAt(s), n);
            obstructKeepingMean(f.current(), std::span<const ObstructionCell>(cells));
            obstructKeepingMean(f.previous(), std::span<const ObstructionCell>(cells));
            worst = std::max(worst, std::abs(total() - before));
        }
        INFO("kang2008: worst change of Σh by one projection " << worst << " of Σ|h| " << scale);
        CHECK(worst <= 1e-6 * scale);  // float levels: each cell rounds to 6e-8 of itself
    }
}

TEST_CASE("hulls: a ring from a drop reflects off a moored hull and leaves a shadow behind it", "[obstacles][hulls]") {
    // A drop (a Gaussian bump, σ = 3 cells) at row 64 of a 256² field of 0.1 m cells; a hull 6 m
    // long and 1.2 m wide (semi-axes 3 m × 0.6 m) lies across the ring's path at row 104, its
    // centre on the drop's column. The ring's waves (0.2 to 1 m) are shorter than the hull.
    // Shadow: Σh² behind the hull's middle over 10 s, against the same without the hull.
    // Reflection: the difference of the two runs in front of the hull (what the hull sent back),
    // as energy over the free ring's there: its square root estimates R. Measured: shadow 0.10,
    // R ≈ 0.54; a fixed body of the same outline (its water spread evenly) gives 0.05 and 0.49.
    const int n = 256, steps = 600;
    const ObstacleShape moored = hull({12.8f, 10.4f}, {3.0f, 0.6f});
    const std::vector<ObstructionCell> cells = rasterise(moored, n);
    auto run = [&](bool withHull, std::vector<std::vector<double>>* front, double& shadow) {
        EWaveField f(n, n, CELL, RippleBoundary::Absorbing, 32);
        f.setDamping(0.0f, 0.0f);
        auto h = f.editHeight();
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) h[size_t(z) * n + x] = 0.01 * std::exp(-(std::pow(x - 128.0, 2) + std::pow(z - 64.0, 2)) / 18.0);
        f.syncHeight();
        shadow = 0.0;
        for (int s = 0; s < steps; ++s) {
            f.step(1.0f / 60.0f);
            if (withHull) obstructField(f, cells);
            shadow += energyIn(f, 113, 143, 125, 200);
            if (s % 10 == 0) {  // the band in front: rows [70, 94), columns [113, 143)
                std::vector<double> band;
                for (int z = 70; z < 94; ++z)
                    for (int x = 113; x < 143; ++x) band.push_back(f.heightState()[size_t(z) * n + size_t(x)]);
                front->push_back(std::move(band));
            }
        }
    };
    std::vector<std::vector<double>> freeFront, hullFront;
    double freeShadow = 0.0, hullShadow = 0.0;
    run(false, &freeFront, freeShadow);
    run(true, &hullFront, hullShadow);
    double incident = 0.0, reflected = 0.0;
    for (size_t t = 0; t < freeFront.size(); ++t)
        for (size_t i = 0; i < freeFront[t].size(); ++i) {
            incident += freeFront[t][i] * freeFront[t][i];
            reflected += std::pow(hullFront[t][i] - freeFront[t][i], 2.0);
        }
    const double shadow = hullShadow / freeShadow, r = std::sqrt(reflected / incident);
    INFO("behind the hull " << shadow << " of the free ring's energy; in front, reflected/incident energy "
                            << reflected / incident << " (R ≈ " << r << ")");
    REQUIRE(freeShadow > 0.0);
    CHECK(shadow <= 0.15);  // a shadow
    CHECK(r >= 0.45);       // and the waves went back
}

TEST_CASE("hulls: the waterplane of a hull box follows its roll and its height (the cut of a box by a plane)", "[obstacles][hulls]") {
    using ob::game::hullWaterplane;
    const glm::vec3 half{1.5f, 0.75f, 5.0f};  // the ship's 3 × 1.5 × 10 m hull
    // Upright, floating at its middle: the waterplane is the beam and the length.
    auto upright = hullWaterplane(half, {0.0f, 0.0f, 0.0f}, glm::quat(1, 0, 0, 0), 0.0f);
    REQUIRE(upright);
    CHECK(upright->displaces);
    CHECK(upright->half.x == Approx(1.5f));
    CHECK(upright->half.y == Approx(5.0f));
    // Rolled 20° about its keel line with the plane on its sides: beam/cos 20°, centred.
    const float roll = glm::radians(20.0f);
    auto rolled = hullWaterplane(half, {0.0f, 0.0f, 0.0f}, glm::angleAxis(roll, glm::vec3(0, 0, 1)), 0.0f);
    REQUIRE(rolled);
    CHECK(rolled->half.x == Approx(1.5f / std::cos(roll)).epsilon(1e-4));
    CHECK(glm::length(rolled->centre) == Approx(0.0f).margin(1e-5));
    // Rolled 30° and riding high (centre 0.5 m above the plane): the plane cuts the bottom and
    // one side. In the section: the bottom edge y = −0.75 and the low side x = −1.5 (rolled);
    // the cut runs from where the plane meets the bottom to where it meets that side.
    const float r30 = glm::radians(30.0f);
    auto high = hullWaterplane(half, {0.0f, 0.5f, 0.0f}, glm::angleAxis(r30, glm::vec3(0, 0, 1)), 0.0f);
    REQUIRE(high);
    // By hand: world y of section point (u, w) = 0.5 + u·sin30 + w·cos30.
    const float s = std::sin(r30), c = std::cos(r30);
    const float uBottom = (-0.5f + 0.75f * c) / s;   // on w = −0.75
    const float wSide = (-0.5f + 1.5f * s) / c;      // on u = −1.5
    const float span = std::hypot(uBottom + 1.5f, -0.75f - wSide);
    CHECK(2.0f * high->half.x == Approx(span).epsilon(1e-4));
    // The plane 0.5 m higher (a swell's crest under it) is the same as the hull 0.5 m lower.
    auto lifted = hullWaterplane(half, {0.0f, 0.0f, 0.0f}, glm::angleAxis(r30, glm::vec3(0, 0, 1)), -0.5f);
    REQUIRE(lifted);
    CHECK(lifted->half.x == Approx(high->half.x));
    // Clear of the water (keel above the plane): no footprint.
    CHECK(!hullWaterplane(half, {0.0f, 1.0f, 0.0f}, glm::quat(1, 0, 0, 0), 0.0f));
}
