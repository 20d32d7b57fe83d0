// The ewave layer's horizontal surface velocity against linear wave theory (SPEC §2.5c): per
// Fourier mode û = i·K/(|K|·tanh(|K|d))·∂ĥ/∂t, so a travelling wave h = a·cos(K·X − ωt) carries
// u = a·ω/tanh(|K|d)·cos(K·X − ωt)·K̂ (deep water: tanh → 1), ω the medium's dispersion; the
// nested levels' composite cross-fades it as it does h and v; kang2008 has none.
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "interaction/ripple_levels.h"
#include "interaction/ewave/ewave_solver.h"
#include "interaction/ripple_patch.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>

using namespace ob::interaction;

namespace {

constexpr double PI = std::numbers::pi;

// A travelling mode of (mx, mz) wavelengths over an n-cell grid of `cell` m: K in rad/m.
struct Mode {
    int mx, mz;
    glm::dvec2 wavevector(int n, double cell) const { return 2.0 * PI / (n * cell) * glm::dvec2(mx, mz); }
};

// h = a·cos θ, v = a·ω·sin θ with θ = K·X, X = (x, z)·cell: the wave a·cos(K·X − ωt) at t = 0.
void setTravelling(EWaveField& f, Mode m, double a) {
    const int n = f.rows();
    const glm::dvec2 k = m.wavevector(n, f.cellSize());
    const double w = f.omega(glm::length(k));
    const std::span<double> h = f.editHeight(), v = f.editVelocity();
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const double theta = glm::dot(k, glm::dvec2(x, z) * double(f.cellSize()));
            h[size_t(z) * size_t(n) + size_t(x)] += a * std::cos(theta);
            v[size_t(z) * size_t(n) + size_t(x)] += a * w * std::sin(theta);
        }
}

// Linear theory's horizontal surface velocity of that wave at X (m) and time t (s), m/s:
// a·ω/tanh(|K|d)·cos(K·X − ωt)·K̂ (d = 0: deep, tanh = 1).
glm::dvec2 theory(glm::dvec2 k, double a, double w, double depth, glm::dvec2 at, double t) {
    const double kk = glm::length(k);
    const double t_h = depth > 0.0 ? std::tanh(kk * depth) : 1.0;
    return a * w / t_h * std::cos(glm::dot(k, at) - w * t) * (k / kk);
}

// max over the cells (x, z) in [0, n − 2]² (bilinear's interior) of |got − want|, m/s.
double worstOver(int n, const std::function<glm::dvec2(int, int)>& got, const std::function<glm::dvec2(int, int)>& want) {
    double worst = 0.0;
    for (int z = 0; z <= n - 2; ++z)
        for (int x = 0; x <= n - 2; ++x) worst = std::max(worst, glm::length(got(x, z) - want(x, z)));
    return worst;
}

// A single travelling mode on a periodic n² solver of 0.25 m cells, `steps` steps of 1/60 s: the
// worst error of horizontalVelocityAt against theory and of the vertical-velocity-only answer
// (0 horizontal), both over a·ω.
struct ModeResult {
    double error, zeroError, deepError, wavenumber, k;
};
ModeResult runMode(Mode m, double depth, int steps) {
    const int n = 64;
    const double cell = 0.25, a = 0.01, dt = 1.0 / 60.0;
    EWaveMedium medium = EWaveMedium::ideal();  // g, σ/ρ of a default [environment]; no viscosity
    medium.depth = depth;
    EWaveSolver solver(n, float(cell), EWaveDef{}, medium, RippleBoundary::Periodic, 32);
    setTravelling(solver.field(), m, a);
    solver.fieldEdited();
    for (int s = 0; s < steps; ++s) solver.step(float(dt));
    const glm::dvec2 k = m.wavevector(n, cell);
    const double w = medium.omega(glm::length(k)), t = steps * dt;
    auto got = [&](int x, int z) { return glm::dvec2(solver.horizontalVelocityAt(glm::vec2(x, z))); };
    auto want = [&](int x, int z) { return theory(k, a, w, depth, glm::dvec2(x, z) * cell, t); };
    auto deep = [&](int x, int z) { return theory(k, a, w, 0.0, glm::dvec2(x, z) * cell, t); };
    auto zero = [](int, int) { return glm::dvec2(0.0); };
    const double aw = a * w;
    return {worstOver(n, got, want) / aw, worstOver(n, zero, want) / aw, worstOver(n, deep, want) / aw,
            double(solver.velocityWavenumber()), glm::length(k)};
}

RippleDef velocityDef(RippleModel model, int n, float cell, int levels) {
    RippleDef def;
    def.model = model;
    def.backend = ob::Backend::Cpu;
    def.resolution = n;
    def.cell_size = cell;
    def.levels = levels;
    def.boundary = RippleBoundary::Periodic;
    return def;
}

} // namespace

// 1 s of steps (60 at 60 Hz): the wave has travelled 1.2–2.2 of its wavelengths, so a wrong
// phase, direction or gain would show at every cell. The bound 1e-4 leaves room for the float
// spectra (about 1e-6 here); the vertical-velocity-only answer misses by a·ω (1.0 of the bound's
// unit) and the deep-water formula at depth by 1/tanh(|K|d) − 1.
TEST_CASE("ewave horizontal velocity: a travelling mode carries u = a·ω/tanh(|K|d)·cos(K·X − ωt)·K̂ to 1e-4 of a·ω",
          "[ewave][ewave_velocity]") {
    const Mode modes[] = {{3, 0}, {0, 3}, {2, 2}, {4, -3}};  // along x, along z, diagonal both ways
    for (double depth : {0.0, 0.5, 2.0}) {
        for (const Mode& m : modes) {
            const ModeResult r = runMode(m, depth, 60);
            INFO("mode (" << m.mx << ", " << m.mz << "), depth " << depth << " m (0 = deep): max |u − theory| / a·ω "
                          << r.error << "; 0 horizontal: " << r.zeroError << "; deep-water formula: " << r.deepError);
            CHECK(r.error <= 1e-4);
            CHECK(r.zeroError > 1e-4);  // the negative control: vertical velocity only fails the bound
            if (depth > 0.0) CHECK(r.deepError > 1e-4);  // and at depth, the deep-water Riesz transform
            // One mode: its velocity variance is all at |K|.
            CHECK(r.wavenumber == Approx(r.k).epsilon(1e-5));
        }
    }
}

// Two travelling waves of wavenumbers k1 and k2 hold velocity variance (a1·ω1)²/2 and (a2·ω2)²/2:
// the centre is their k-weighted mean; still water has none (0).
TEST_CASE("ewave horizontal velocity: velocityWavenumber is the velocity variance's centre Σk·|v̂|²/Σ|v̂|²",
          "[ewave][ewave_velocity]") {
    const int n = 64;
    const double cell = 0.25, dt = 1.0 / 60.0;
    RipplePatch patch(velocityDef(rippleModel("ewave"), n, float(cell), 1));
    CHECK(patch.velocityWavenumber() == 0.0f);
    EWaveSolver& solver = *patch.solverAs<EWaveSolver>();
    const Mode m1{2, 1}, m2{0, 7};
    const double a1 = 0.02, a2 = 0.005;
    setTravelling(solver.field(), m1, a1);
    setTravelling(solver.field(), m2, a2);
    solver.fieldEdited();
    patch.step(float(dt));
    const double k1 = glm::length(m1.wavevector(n, cell)), k2 = glm::length(m2.wavevector(n, cell));
    const double p1 = std::pow(a1 * solver.field().omega(k1), 2), p2 = std::pow(a2 * solver.field().omega(k2), 2);
    const double want = (k1 * p1 + k2 * p2) / (p1 + p2);
    INFO("k1 " << k1 << ", k2 " << k2 << " rad/m; centre " << want);
    CHECK(patch.velocityWavenumber() == Approx(want).epsilon(1e-5));
    CHECK(std::abs(patch.velocityWavenumber() - k1) > 0.05 * k1);  // not just the stronger wave's
    solver.clear();
    patch.step(float(dt));
    CHECK(patch.velocityWavenumber() == 0.0f);
}

// Two periodic levels of 64²: level 0 of 0.25 m cells (16 m) holding a short wave, level 1 of
// 1 m cells (64 m) a long one. The composite at a world point is w0·u0 + (1 − w0)·u1, w0 =
// fineWeight (its fade one cell wide here: the periodic field has no sponge band), each u the
// theory of its own wave at its own grid's cell centres read through the one bilinear sampler.
// Level 1 steps every 4th frame over 4 dt from frame 2; the edit is its state at frame 1, so from
// frame 6 on both ends of its Hermite are the wave's and at frame F it reads time (F − 1)·dt
// (level 0: F·dt). Frames 6–9 cover the Hermite's whole interval, its phases between steps included.
TEST_CASE("ewave horizontal velocity: with levels the patch reads the levels' cross-faded sum, in time between "
          "a coarse level's steps",
          "[ewave][ewave_velocity][levels]") {
    const int n = 64;
    const double cell0 = 0.25, cell1 = 1.0, a0 = 0.004, a1 = 0.02, dt = 1.0 / 60.0;
    RipplePatch patch(velocityDef(rippleModel("ewave"), n, float(cell0), 2));
    RippleLevels& levels = *patch.levels();
    REQUIRE(levels.grid(1).cell == float(cell1));
    const Mode fine{3, 0}, coarse{2, 1};
    EWaveSolver& solver0 = *patch.solverAs<EWaveSolver>();
    setTravelling(solver0.field(), fine, a0);
    solver0.fieldEdited();
    setTravelling(levels.solverAs<EWaveSolver>(1)->field(), coarse, a1);
    const glm::dvec2 k0 = fine.wavevector(n, cell0), k1 = coarse.wavevector(n, cell1);
    const double w0 = solver0.field().omega(glm::length(k0)), w1 = solver0.field().omega(glm::length(k1));
    // Theory at each level's cell centres (cell (x, z) at (x, z)·cell of that level's own wave), per axis.
    auto cells = [n](glm::dvec2 k, double a, double w, double cell, double t, int axis) {
        std::vector<double> u(size_t(n) * size_t(n));
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x) u[size_t(z) * size_t(n) + size_t(x)] = theory(k, a, w, 0.0, glm::dvec2(x, z) * cell, t)[axis];
        return u;
    };
    int frame = 0;
    for (int target : {6, 7, 8, 9}) {
        while (frame < target) {
            patch.step(float(dt));
            ++frame;
        }
        std::vector<double> u0[2], u1[2];
        for (int axis = 0; axis < 2; ++axis) {
            u0[axis] = cells(k0, a0, w0, cell0, frame * dt, axis);
            u1[axis] = cells(k1, a1, w1, cell1, (frame - 1) * dt, axis);
        }
        double worst = 0.0, worstFineOnly = 0.0, worstUnfaded = 0.0;
        int faded = 0, coarseOnly = 0;
        for (double z = -12.0; z <= 12.0; z += 0.37)
            for (double x = -12.0; x <= 12.0; x += 0.37) {
                const glm::vec2 world{float(x), float(z)};
                const float wf = patch.fineWeight(world);
                faded += wf > 0.0f && wf < 1.0f;
                coarseOnly += wf == 0.0f;
                const glm::vec2 g0 = patch.toGrid(world), g1 = levels.grid(1).toGrid(world);
                glm::dvec2 v0, v1;
                for (int axis = 0; axis < 2; ++axis) {
                    v0[axis] = bilinear<double>(u0[axis], n, n, g0);
                    v1[axis] = bilinear<double>(u1[axis], n, n, g1);
                }
                const glm::dvec2 want = double(wf) * v0 + (1.0 - double(wf)) * v1;
                const glm::dvec2 got = glm::dvec2(patch.horizontalVelocityAt(world));
                worst = std::max(worst, glm::length(got - want));
                worstFineOnly = std::max(worstFineOnly, glm::length(double(wf) * v0 - want));
                worstUnfaded = std::max(worstUnfaded, glm::length(v0 + v1 - want));
            }
        const double bound = 1e-4 * std::max(a0 * w0, a1 * w1);
        INFO("frame " << frame << ": max |composite − theory| " << worst << " m/s (bound " << bound << "); level 0 alone "
                      << worstFineOnly << ", levels summed without the fade " << worstUnfaded << "; " << faded
                      << " points in the fade, " << coarseOnly << " on level 1 alone");
        CHECK(faded > 0);
        CHECK(coarseOnly > 0);
        CHECK(worst <= bound);
        CHECK(worstFineOnly > bound);  // negative controls: the coarse level missing,
        CHECK(worstUnfaded > bound);   // or the levels added without their weights
    }
}

// Eq. 1–2 are a height field with no velocity law: its water moves vertically only. The same
// crater on ewave moves the water sideways too (the check can fail).
TEST_CASE("ewave horizontal velocity: kang2008 has none (0), ewave's ring has some", "[ewave][ewave_velocity]") {
    for (const bool kang : {true, false}) {
        const char* model = kang ? "kang2008" : "ewave";
        RippleDef def = velocityDef(kang ? rippleModel("kang2008") : rippleModel("ewave"), 64, 0.25f, 1);
        def.boundary = RippleBoundary::Fixed;
        RipplePatch patch(def);
        REQUIRE(patch.addCrater({0.3f, -0.2f}, -0.01));
        for (int s = 0; s < 30; ++s) patch.step(1.0f / 60.0f);
        float vertical = 0.0f, horizontal = 0.0f;
        for (float x = -6.0f; x <= 6.0f; x += 0.1f) {
            vertical = std::max(vertical, std::abs(patch.velocityAt({x, 0.1f}, 1.0f / 60.0f)));
            horizontal = std::max(horizontal, glm::length(patch.horizontalVelocityAt({x, 0.1f})));
        }
        INFO(model << ": max |w| " << vertical << " m/s, max |u| " << horizontal << " m/s, velocityWavenumber "
                   << patch.velocityWavenumber() << " rad/m");
        CHECK(vertical > 1e-4f);
        if (kang) {
            CHECK(horizontal == 0.0f);
            CHECK(patch.velocityWavenumber() == 0.0f);
        } else {
            CHECK(horizontal > 0.1f * vertical);
            CHECK(patch.velocityWavenumber() > 0.0f);
        }
    }
}

// The horizontal velocity is derived: it moves with the grid (the waves stay put in the world),
// is 0 after clear() and inside a fixed body, and no part of the state hash.
TEST_CASE("ewave horizontal velocity: scrolls with the grid, clears, is 0 inside a body, is not hashed",
          "[ewave][ewave_velocity]") {
    const int n = 64;
    RipplePatch patch(velocityDef(rippleModel("ewave"), n, 0.25f, 1));
    EWaveSolver& solver = *patch.solverAs<EWaveSolver>();
    setTravelling(solver.field(), {2, 1}, 0.01);
    solver.fieldEdited();
    patch.step(1.0f / 60.0f);
    const glm::vec2 at{1.3f, -0.7f};
    const glm::vec2 before = patch.horizontalVelocityAt(at);
    REQUIRE(glm::length(before) > 1e-3f);
    ob::StateHasher h0;
    patch.hashState(h0);
    solver.field().scaleHorizontal(size_t(n / 2) * size_t(n) + size_t(n / 2), 0.5f);
    ob::StateHasher h1;
    patch.hashState(h1);
    CHECK(h0.value() == h1.value());
    patch.centerOn({3.0f, 2.0f});  // 12 and 8 cells
    // The same four cells' values; the bilinear weights equal up to the rounding of world → grid.
    CHECK(glm::length(patch.horizontalVelocityAt(at) - before) <= 1e-5f * glm::length(before));
    // A fixed box 1 m square at the origin: its cells' velocity held at 0 after the step.
    ObstacleShape box;
    box.centre = {3.0f, 2.0f};
    box.half = {0.5f, 0.5f};
    const ObstacleShape boxes[] = {box};
    patch.setObstacles(boxes);
    patch.step(1.0f / 60.0f);
    CHECK(glm::length(patch.horizontalVelocityAt({3.0f, 2.0f})) == 0.0f);
    CHECK(glm::length(patch.horizontalVelocityAt({3.0f + 2.0f, 2.0f})) > 0.0f);
    solver.clear();
    CHECK(glm::length(patch.horizontalVelocityAt(at)) == 0.0f);
}

// The horizontal fields and the wavenumber are made in row bands (the fused pass) and by
// transforms on either worker: on 1, 2 and 3 workers (the step split over 2 or not) they are the
// same bits, as the state is (absorbing 256², noise, 3 steps).
TEST_CASE("ewave horizontal velocity: the same bits on any worker count", "[ewave][ewave_velocity][parallel]") {
    const int n = 256;
    std::vector<glm::vec2> first;
    double firstK = -1.0;
    ob::setThreadMeasuring(false);  // every worker count splits, whatever this machine measured
    for (int workers : {1, 2, 3}) {
        ob::setWorkerCount(workers);
        EWaveField f(n, n, 0.25f, RippleBoundary::Absorbing, 32);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> noise(-0.01, 0.01);
        for (double& h : f.editHeight()) h = noise(rng);
        for (double& v : f.editVelocity()) v = 3.0 * noise(rng);
        for (int s = 0; s < 3; ++s) f.step(1.0f / 60.0f);
        INFO(workers << " workers: velocityWavenumber " << f.velocityWavenumber() << " rad/m");
        CHECK(f.velocityWavenumber() > 0.0);
        if (firstK < 0.0) {
            firstK = f.velocityWavenumber();
            first.assign(f.horizontalVelocity().begin(), f.horizontalVelocity().end());
            continue;
        }
        CHECK(f.velocityWavenumber() == firstK);
        CHECK(std::equal(first.begin(), first.end(), f.horizontalVelocity().begin()));
    }
    ob::setWorkerCount(0);
    ob::setThreadMeasuring(true);
}
