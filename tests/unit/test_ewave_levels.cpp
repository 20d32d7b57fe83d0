// Nested ewave levels (docs/ewave.md#levels): a ship's Kelvin wake read on the composite of
// the levels keeps arcsin(1/3) = 19.47° far past the fine level; the composite's height and
// slope cross the level boundaries within the bound of the cross-fade; the keys' checks.
#include "interaction/ewave/ewave_solver.h"
#include "interaction/ripple_levels.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace ob::interaction;

namespace {

RippleDef levelsDef(int n, float cell, int levels, int sponge) {
    RippleDef def;
    def.model = rippleModel("ewave");
    def.backend = ob::Backend::Cpu;
    def.resolution = n;
    def.cell_size = cell;
    def.levels = levels;
    def.sponge_width = sponge;
    def.boundary = RippleBoundary::Absorbing;
    return def;
}

// A sphere of `radius` m, half under water, pushing down (SD −1, SHR 1, AF 0), on the patch
// at world (x, z), moving at `speed` m/s along +x.
bool stampShip(RipplePatch& patch, const BoundingSphere& sphere, SphereContact& contact, glm::vec2 at, float speed) {
    return patch.stampSphere(sphere, contact, glm::vec3(at.x, 0.0f, at.y), glm::vec3(speed, 0.0f, 0.0f), 1000.0f, 0.0f);
}

BoundingSphere shipSphere(float radius) {
    BoundingSphere s;
    s.radius = radius;
    s.direction = SphereDirection::Down;
    s.heightRatio = 1.0f;
    return s;
}

// The wake's envelope angle, measured as test_ewave_wake.cpp measures it on one field, here on
// the composite (RipplePatch::heightAt) at world points: per distance d behind the ship, |h| is
// smoothed along the track by a running maximum over half a transverse wavelength each way,
// the edge on each side is the outermost lateral offset where that envelope still reaches a
// third of the cross-section's peak, and y(d) (both sides averaged) is fitted by y = a + b·d.
double envelopeAngleDeg(const RipplePatch& patch, glm::vec2 ship, double speed, double d0, double d1, int& samples) {
    const double lambda = 2.0 * std::numbers::pi * speed * speed / 9.81;
    const double dy = 0.5, dx = 1.0, half = lambda / 2.0, width = 0.5 * d1 + 20.0;
    std::vector<double> ds, ys;
    std::vector<double> env;
    for (double d = d0; d <= d1; d += dx) {
        const int ny = int(width / dy);
        env.assign(size_t(2 * ny + 1), 0.0);
        // The cross-section's mean level first: each level keeps its own volume, so the ship's
        // displaced water lifts each by a different uniform amount (docs/ewave.md#levels);
        // the wedge is the waves about that level.
        double mean = 0.0;
        for (int j = -ny; j <= ny; ++j) mean += patch.heightAt({float(ship.x - d), float(ship.y + j * dy)});
        mean /= double(2 * ny + 1);
        for (int j = -ny; j <= ny; ++j)
            for (double s = -half; s <= half; s += dx)
                env[size_t(j + ny)] = std::max(
                    env[size_t(j + ny)], std::abs(double(patch.heightAt({float(ship.x - d + s), float(ship.y + j * dy)})) - mean));
        const double peak = *std::max_element(env.begin(), env.end());
        if (!(peak > 0.0)) continue;
        int up = 0, down = 0;
        for (int j = ny; j > 0; --j)
            if (3.0 * env[size_t(j + ny)] >= peak) { up = j; break; }
        for (int j = -ny; j < 0; ++j)
            if (3.0 * env[size_t(j + ny)] >= peak) { down = -j; break; }
        ds.push_back(d);
        ys.push_back(0.5 * (up + down) * dy);
    }
    const double n = double(ds.size());
    double sd = 0, sy = 0, sdd = 0, sdy = 0;
    for (size_t i = 0; i < ds.size(); ++i) {
        sd += ds[i];
        sy += ys[i];
        sdd += ds[i] * ds[i];
        sdy += ds[i] * ys[i];
    }
    samples = int(ds.size());
    return std::atan((n * sdy - sd * sy) / (n * sdd - sd * sd)) * 180.0 / std::numbers::pi;
}

} // namespace

// Three levels of 512² (0.25 m over 128 m, 1 m over 512 m, 4 m over 2 km) centred on a ship
// (a 1 m sphere) at 5 m/s, its push ramped up over the first 10 s (a sudden start sheds a
// ring of long, fast waves that outruns the wedge, as in test_ewave_wake.cpp); after 80 s the
// wake stretches 400 m behind it (the wedge's edge d behind the ship was shed some 4d/3
// behind it, so it has formed to 300 m), through the fine level's fade (48–56 m behind) and
// level 1's (192–224 m) into level 2. The envelope's angle
// fitted on the composite over 15–250 m is the Kelvin angle: with the waves handed on
// between levels (a seam or a level missing the wake would bend or cut the envelope there).
TEST_CASE("ewave levels: the Kelvin angle holds on the composite 15-250 m behind a ship at 5 m/s",
          "[ewave][levels][wake][long]") {
    const double kelvin = std::asin(1.0 / 3.0) * 180.0 / std::numbers::pi;
    const float speed = 5.0f, dt = 1.0f / 30.0f;
    RipplePatch patch(levelsDef(512, 0.25f, 3, 32));
    REQUIRE(patch.levels() != nullptr);
    BoundingSphere sphere = shipSphere(1.0f);
    SphereContact contact;
    glm::vec2 ship(0.0f);
    const int steps = int(80.0f / dt);  // 400 m
    for (int s = 0; s < steps; ++s) {
        ship.x = speed * float(s) * dt;
        const float ramp = std::min(1.0f, float(s) * dt / 10.0f);
        sphere.heightRatio = ramp * ramp * (3.0f - 2.0f * ramp);
        patch.centerOn(ship);
        stampShip(patch, sphere, contact, ship, speed);
        patch.step(dt);
    }
    int samples = 0;
    const double angle = envelopeAngleDeg(patch, ship, speed, 15.0, 250.0, samples);
    // 20.3° measured (the single-grid wake tests hold 1.5° too).
    INFO("envelope " << angle << "° over " << samples << " cross-sections (theory " << kelvin << "°)");
    CHECK(samples >= 200);
    CHECK(std::abs(angle - kelvin) <= 1.5);
}

// The composite across level 0's fade band (x from 6 to 12 fine cells inside its border at
// sponge 6): with w level 0's weight, h = w·h0 + (1 − w)·h1, so along x
//   |∂h/∂x| ≤ max(|∂h0/∂x|, |∂h1/∂x|) + |∂w/∂x|·|h0 − h1|,  |∂w/∂x| ≤ 1.5/B
// (B the band, m; 1.5 the smoothstep's steepest slope), and between samples δ apart the
// height moves by at most δ times that (no jump, where a hard switch jumps by |h0 − h1|);
// the slope (a central difference over δ) moves by at most what each level's own does plus
//   δ·(2·(1.5/B)·max|∂h0/∂x − ∂h1/∂x| + (6/B²)·max|h0 − h1|)  (6/B²: the smoothstep's |w''|).
// A ring from a drop near the centre is read while it crosses the band, on a 64² patch of
// 0.25 m cells with a level of 1 m cells around it.
TEST_CASE("ewave levels: height and slope cross the level boundary within the cross-fade's bound", "[ewave][levels]") {
    const int n = 64, sponge = 6;
    const float cell = 0.25f, band = float(sponge) * cell, dt = 1.0f / 60.0f;
    RipplePatch patch(levelsDef(n, cell, 2, sponge));
    const RippleLevels& levels = *patch.levels();
    SphereContact contact;
    BoundingSphere ball = shipSphere(0.3f);
    ball.direction = SphereDirection::Down;
    const glm::vec2 drop(-2.0f, 0.3f);  // off-centre so the ring meets the -x border first
    for (int s = 0; s < 40; ++s) {
        if (s < 4) patch.stampSphere(ball, contact, glm::vec3(drop.x, -0.1f, drop.y), glm::vec3(0, -4, 0), 5.0f, 0.0f);
        patch.step(dt);
    }
    // The band on the -x side along z = 0.3 m: grid x from 6 to 12 (level 0's cell centres at
    // integers), world x = (originCell + g)·cell.
    const float x0 = patch.origin().x + 2.0f * cell, x1 = patch.origin().x + 16.0f * cell, z = drop.y;
    const float delta = cell / 16.0f;
    auto h0 = [&](float x) { return ob::interaction::bilinear(patch.height(), n, n, patch.toGrid({x, z})); };
    auto h1 = [&](float x) { return levels.heightAt(1, {x, z}); };
    auto hc = [&](float x) { return patch.heightAt({x, z}); };
    auto d = [&](auto f, float x) { return (f(x + 0.5f * delta) - f(x - 0.5f * delta)) / delta; };
    double slope0 = 0, slope1 = 0, gap = 0, slopeGap = 0, kink0 = 0, kink1 = 0;
    for (float x = x0; x <= x1; x += delta) {
        slope0 = std::max(slope0, double(std::abs(d(h0, x))));
        slope1 = std::max(slope1, double(std::abs(d(h1, x))));
        gap = std::max(gap, double(std::abs(h0(x) - h1(x))));
        slopeGap = std::max(slopeGap, double(std::abs(d(h0, x) - d(h1, x))));
        kink0 = std::max(kink0, double(std::abs(d(h0, x + delta) - d(h0, x))));
        kink1 = std::max(kink1, double(std::abs(d(h1, x + delta) - d(h1, x))));
    }
    REQUIRE(gap > 1e-4);  // the levels differ in the band: a switch between them would show
    const double wSlope = 1.5 / band, wCurve = 6.0 / (band * band);
    const double stepBound = delta * (std::max(slope0, slope1) + wSlope * gap) * 1.01 + 1e-7;
    const double kinkBound = std::max(kink0, kink1) + delta * (2.0 * wSlope * slopeGap + wCurve * gap) * 1.01 + 1e-6;
    double step = 0, kink = 0;
    for (float x = x0; x <= x1; x += delta) {
        step = std::max(step, double(std::abs(hc(x + delta) - hc(x))));
        kink = std::max(kink, double(std::abs(d(hc, x + delta) - d(hc, x))));
    }
    INFO("|h0 − h1| ≤ " << gap << " m; height step " << step << " ≤ " << stepBound << "; slope step " << kink << " ≤ "
                        << kinkBound << " (each level's own " << std::max(kink0, kink1) << ")");
    CHECK(step <= stepBound);
    CHECK(kink <= kinkBound);
    // The weight itself: 0 in the sponge, 1 inside twice it, between the two a smoothstep.
    CHECK(levelWeight({float(sponge), 30.0f}, n, sponge) == 0.0f);
    CHECK(levelWeight({float(2 * sponge), 30.0f}, n, sponge) == 1.0f);
    CHECK(levelWeight({1.5f * float(sponge), 30.0f}, n, sponge) == Approx(0.5f));
}

// Level L's cells are 4^L times the patch's, it steps every 4^L-th frame (first at frame
// L + 1, so no two levels step on one frame), and a sphere that level 0 stamps reaches them all.
TEST_CASE("ewave levels: a source reaches every level, each stepping every 4^L-th frame from frame L + 1",
          "[ewave][levels]") {
    const int n = 32;
    RipplePatch patch(levelsDef(n, 0.5f, 3, 4));
    const RippleLevels& levels = *patch.levels();
    REQUIRE(levels.count() == 3);
    CHECK(levels.grid(1).cell == 2.0f);
    CHECK(levels.grid(2).cell == 8.0f);
    CHECK(levels.stride(1) == 4);
    CHECK(levels.stride(2) == 16);
    SphereContact contact;
    const BoundingSphere ball = shipSphere(0.5f);
    REQUIRE(patch.stampSphere(ball, contact, glm::vec3(0.1f, 0.0f, -0.2f), glm::vec3(0.0f), 10.0f, 0.0f));
    auto hashOf = [](const RippleSolver& s) {
        ob::StateHasher h;
        s.hashState(h);
        return h.value();
    };
    std::vector<uint64_t> h1, h2;
    for (int frame = 1; frame <= 20; ++frame) {
        patch.step(1.0f / 60.0f);
        h1.push_back(hashOf(levels.solver(1)));
        h2.push_back(hashOf(levels.solver(2)));
    }
    auto changedAt = [](const std::vector<uint64_t>& h) {
        std::vector<int> frames;
        for (size_t i = 1; i < h.size(); ++i)
            if (h[i] != h[i - 1]) frames.push_back(int(i) + 1);
        return frames;
    };
    CHECK(changedAt(h1) == std::vector<int>{2, 6, 10, 14, 18});
    CHECK(changedAt(h2) == std::vector<int>{3, 19});
    CHECK(patch.solverAs<EWaveSolver>()->field().volume() == Approx(0.0).margin(1e-9));  // a pressure moves water only
    CHECK(std::abs(levels.heightAt(2, {0.1f, -0.2f})) > 0.0f);  // the source's long waves on the coarsest level
}

TEST_CASE("ewave levels: levels > 1 is refused for kang2008, naming the key, and taken on the GPU backend", "[ewave][levels]") {
    RippleDef def = levelsDef(64, 0.25f, 2, 8);
    CHECK(validate(def).empty());
    def.backend = ob::Backend::Gpu;
    CHECK(validate(def).empty());  // each level on its own twin (tests_gl "[ewave_gpu][levels]")
    def.backend = ob::Backend::Cpu;
    def.model = rippleModel("kang2008");
    REQUIRE(validate(def).size() == 1);
    CHECK(validate(def)[0].key == "levels");
    CHECK(validate(def)[0].message.find("ewave") != std::string::npos);
}


namespace {

double sumOf(std::span<const double> f) {
    double s = 0.0;
    for (double x : f) s += x;
    return s;
}
double sumOf(std::span<const float> f) {
    double s = 0.0;
    for (float x : f) s += double(x);
    return s;
}
double maxAbs(std::span<const float> f) {
    double m = 0.0;
    for (float x : f) m = std::max(m, double(std::abs(x)));
    return m;
}

} // namespace

// Water is moved, never made, on every level: a pressure's uniform part is dropped, a splash
// crater's volume is taken back as the k = 0 mode, and a scroll brings its new cells in at the
// mean level and puts back what the strips that left held about it. So each level's mean of h
// (its state, in double) stays what it was to rounding, 1e-12 of its largest |h|, and the
// Hermite between its two states (the shown height, float) keeps it to float rounding. Three
// periodic levels of 32² follow a sphere moving at 3 m/s on a curve (the patch scrolls every
// few frames, the coarse levels now and then), with a drop landing every 10th frame. Before,
// the scrolls filled with 0 and recounted (level 0's mean fell by 1e-2 of its largest |h| in
// 400 frames) and a crater's volume stayed on level 0 alone.
TEST_CASE("ewave levels: each level keeps its mean level under moving sources, craters and scrolling", "[ewave][levels][volume]") {
    const int n = 32;
    RippleDef def = levelsDef(n, 0.25f, 3, 4);
    def.boundary = RippleBoundary::Periodic;
    RipplePatch patch(def);
    const RippleLevels& levels = *patch.levels();
    const EWaveField& fine = patch.solverAs<EWaveSolver>()->field();
    BoundingSphere sphere = shipSphere(0.5f);
    SphereContact contact;
    const float dt = 1.0f / 60.0f;
    double worst = 0.0, worstShown = 0.0;
    for (int s = 0; s < 400; ++s) {
        const float t = float(s) * dt;
        const glm::vec2 ship(3.0f * t - 6.0f, 2.0f * std::sin(0.5f * t));
        patch.centerOn(ship);
        stampShip(patch, sphere, contact, ship, 3.0f);
        if (s % 10 == 5) {
            ob::splash::Landing drop;
            drop.position = {ship.x + 1.3f, 0.0f, ship.y - 0.7f};
            drop.velocity = {0.0f, -5.0f, 0.0f};
            drop.mass = 0.01f;
            REQUIRE(ob::splash::stampLandings(patch, std::span(&drop, 1), 0.5f) > 0.0);
        }
        patch.step(dt);
        const double cells = double(n) * n;
        worst = std::max(worst, std::abs(sumOf(fine.heightState())) / cells / maxAbs(fine.height()));
        for (int L = 1; L < levels.count(); ++L) {
            const double scale = std::max(maxAbs(levels.solver(L).height()), 1e-12);
            worst = std::max(worst, std::abs(sumOf(dynamic_cast<const EWaveSolver&>(levels.solver(L)).field().heightState())) / cells / scale);
            worstShown = std::max(worstShown, std::abs(sumOf(levels.height(L))) / cells / scale);
        }
    }
    INFO("largest |mean h| / max |h| over the levels: state " << worst << ", shown " << worstShown);
    CHECK(worst <= 1e-12);
    CHECK(worstShown <= 1e-6);  // float: a few 2^-24 of the largest |h|
}

// A drop's far-field ring on the composite is the one a single fine grid makes: a periodic
// 64 m square of 0.25 m cells (256²) against a 16 m level 0 of the same cells inside a level 1
// of 1 m cells over the same 64 m (so the two hold the same modes up to level 1's Nyquist).
// After t = 6 s the ring 14-22 m out lies on level 1 alone (level 0's weight is 0 there),
// which saw the crater only through addCrater. Stationary phase: at (r, t) the waves have
// k = g·t²/(4r²) ≤ 0.45 rad/m here; level 1 differs from the fine grid by its bilinear splat
// of the crater and its bilinear read, each at most (k·Δ₁)²/8 of a wave of k, and its Hermite
// in time, (ω·S)⁴/384 (S = 4·dt), and the crater reaches it at its next step, here one frame
// late (level 1's still water counts as frame 1), a phase of at most ω·dt: so
// |composite − fine| ≤ ((k·Δ₁)²/4 + ω·dt + (ω·S)⁴/384)·max|h| (measured 0.075·max|h|, bound 0.12).
// Both are read through the same 2 m box filter (a 9 × 9 mean): linear, of gain ≤ 1, so level
// 1's error stays within that bound, while the fine grid's own ripple from its spectrum's sharp
// cut at its Nyquist (0.5 m crests, which level 1 cannot hold) drops to a few percent.
// Without the crater on level 1 the composite is 0 there (the difference is max|h|).
TEST_CASE("ewave levels: a drop's far ring on the composite matches a single fine grid", "[ewave][levels][splash]") {
    const float dt = 1.0f / 30.0f, cell = 0.25f, coarse = 1.0f;
    RippleDef refDef = levelsDef(256, cell, 1, 4);
    refDef.boundary = RippleBoundary::Periodic;
    RippleDef lvDef = levelsDef(64, cell, 2, 4);
    lvDef.boundary = RippleBoundary::Periodic;
    RipplePatch ref(refDef), lv(lvDef);
    ob::splash::Landing drop;
    drop.position = {0.125f, 0.0f, 0.125f};  // a fine cell's centre on both fine grids
    drop.velocity = {0.0f, -6.0f, 0.0f};
    drop.mass = 0.05f;
    const double e = ob::splash::stampLandings(ref, std::span(&drop, 1), 0.5f);
    CHECK(ob::splash::stampLandings(lv, std::span(&drop, 1), 0.5f) == e);
    const int steps = 180;  // 6 s
    for (int s = 0; s < steps; ++s) {
        ref.step(dt);
        lv.step(dt);
    }
    const double t = steps * dt, g = 9.81, r0 = 14.0, r1 = 22.0;
    auto box = [](const RipplePatch& patch, glm::vec2 p) {
        double sum = 0.0;
        for (int i = -4; i <= 4; ++i)
            for (int j = -4; j <= 4; ++j) sum += patch.heightAt(p + 0.25f * glm::vec2(float(i), float(j)));
        return sum / 81.0;
    };
    double peak = 0.0, diff = 0.0;
    for (int a = 0; a < 8; ++a) {
        const double phi = 2.0 * std::numbers::pi * (a + 0.3) / 8.0;
        for (double r = r0; r <= r1; r += 0.25) {
            const glm::vec2 p(float(r * std::cos(phi)), float(r * std::sin(phi)));
            REQUIRE(lv.fineWeight(p + glm::vec2(-1.0f)) == 0.0f);
            const double h = box(ref, p), hl = box(lv, p);
            peak = std::max(peak, std::abs(h));
            diff = std::max(diff, std::abs(hl - h));
        }
    }
    const double k = g * t * t / (4.0 * r0 * r0), omega = std::sqrt(g * k), omegaS = omega * 4.0 * dt;
    const double bound = ((k * coarse) * (k * coarse) / 4.0 + omega * dt + std::pow(omegaS, 4) / 384.0) * peak;
    INFO("far ring: peak " << peak << " m, |composite − fine| " << diff << " m, bound " << bound << " (k ≤ " << k << " rad/m)");
    REQUIRE(peak > 1e-5);
    CHECK(diff <= bound);
}

// A sphere beyond level 0 is planned on the finest level that covers it, but pushes every
// coarser level as level 0 would: the same ∫a·w dA, the sphere's own (radius max(r, Δ₀)), not
// that of a footprint widened to the planning level's cell. A 1 m sphere at rest on three levels
// of 32² (0.25, 1, 4 m) at the centre (planned on level 0) and 40 m out (on level 2, level 1
// reaching 16 m): level 2's response under each, both 10 of its cells from its centre's sub-cell
// offset apart, is the same (before: 16 times, (4 m / 1 m)², under the far one).
TEST_CASE("ewave levels: a sphere planned on a coarse level pushes it as level 0 would", "[ewave][levels]") {
    auto response = [](glm::vec2 at) {
        RipplePatch patch(levelsDef(32, 0.25f, 3, 4));
        BoundingSphere sphere = shipSphere(1.0f);
        SphereContact contact;
        for (int s = 0; s < 20; ++s) {
            stampShip(patch, sphere, contact, at, 0.0f);
            patch.step(1.0f / 60.0f);
        }
        return double(patch.levels()->heightAt(2, at));
    };
    const double centre = response({0.0f, 0.0f}), far = response({40.0f, 0.0f});
    INFO("level 2 under the sphere: " << centre << " m at the centre, " << far << " m 40 m out");
    REQUIRE(std::abs(centre) > 0.0);
    CHECK(far == Approx(centre).epsilon(1e-4));
}
