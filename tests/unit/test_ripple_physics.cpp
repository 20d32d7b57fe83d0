// Ripple layer physics, [Kang2008] eq. 1–7 and Table 2 (docs/references.md#ripple-layer), beyond the kernel-by-hand
// tests of test_ripple_field.cpp and test_sphere_stamp.cpp: isotropy and speed of a drop's
// ring, energy over long runs, what AF does to a splash, how much the sponge reflects, and
// when a moving sphere stamps; and `dump ripples`.
#include "core/error.h"
#include "core/npy.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/ripple_patch.h"
#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/sphere_stamp.h"
#include "world/sandbox.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include "support/ripple_reference.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace ob::interaction;
using ob::test::leapfrogEnergy;

namespace {

// Energy of the scheme u(t+1) + u(t−1) = A·u(t) (A = ¼·8-neighbour sum, symmetric):
// A drop: an SR cell footprint pushed down to depth·PH/SR at cell (c, c), at rest (AF 0).
void drop(RippleField& f, float sr, int c, float depthPerCell, float af = 0.0f) {
    stampFootprint(f, makeFootprint(sr), c, c, 0.0f, -depthPerCell, af);
}

// Cells along the ray from (c, c) in direction (ux, uz) (unit steps, so a diagonal step is √2
// long) up to the last interior cell.
int rayLength(const RippleField& f, int c, int ux, int uz) {
    int k = 0;
    while (true) {
        const int x = c + (k + 1) * ux, z = c + (k + 1) * uz;
        if (x < 1 || z < 1 || x > f.cols() - 2 || z > f.rows() - 2) return k;
        ++k;
    }
}

// Radius (cells) of the ring's front along a ray: the outermost cell with |Vh| > threshold,
// refined to where |Vh| crosses the threshold linearly towards the next cell out.
double frontRadius(const RippleField& f, int c, int ux, int uz, double threshold) {
    const double step = std::sqrt(double(ux * ux + uz * uz));
    for (int k = rayLength(f, c, ux, uz) - 1; k > 0; --k) {
        const double a = std::abs(f.currentAt(c + k * ux, c + k * uz));
        if (a > threshold) {
            const double b = std::abs(f.currentAt(c + (k + 1) * ux, c + (k + 1) * uz));
            return (double(k) + (a - threshold) / (a - b)) * step;
        }
    }
    return 0.0;
}

// Radius (cells) of the ring's leading crest along a ray: the outermost local maximum of
// |Vh| above threshold, refined by a parabola through it and its two neighbours.
double crestRadius(const RippleField& f, int c, int ux, int uz, double threshold) {
    const double step = std::sqrt(double(ux * ux + uz * uz));
    for (int k = rayLength(f, c, ux, uz) - 1; k > 0; --k) {
        const double a = std::abs(f.currentAt(c + k * ux, c + k * uz));
        const double in = std::abs(f.currentAt(c + (k - 1) * ux, c + (k - 1) * uz));
        const double out = std::abs(f.currentAt(c + (k + 1) * ux, c + (k + 1) * uz));
        if (a > threshold && a >= in && a >= out) return (double(k) + 0.5 * (in - out) / (in - 2.0 * a + out)) * step;
    }
    return 0.0;
}

// Centre heights Vh(t) of a 129² field after an SR 5 drop 0.5 m deep with the given AF, DF,
// for `steps` steps; element 0 is the stamp itself.
std::vector<float> centreAfterDrop(float af, float df, int steps) {
    RippleField f(129, 129);
    drop(f, 5.0f, 64, 0.1f, af);
    std::vector<float> h{f.currentAt(64, 64)};
    for (int k = 0; k < steps; ++k) {
        f.step(df);
        h.push_back(f.currentAt(64, 64));
    }
    return h;
}

} // namespace

TEST_CASE("a drop's ring spreads isotropically: along the axes and the diagonals the front moves within one cell per 50 steps, at about sqrt(3)/2 cells a step",
          "[ripple]") {
    // SR 3 drop at the centre of a 257² field, DF 1; the ring stays clear of the edge for
    // the 100 steps (it travels < 1 cell a step). Eq. 1's kernel has the dispersion relation
    // 2·cos ω = ½(cos kx + cos kz) + cos kx·cos kz = 2 − ¾k² + O(k⁴): long waves travel at
    // √(3/4) = 0.866 cells a step in every direction; the anisotropy is the O(k⁴) term
    // kx²kz²/8, small for the drop's wavelengths.
    const int c = 128;
    RippleField f(257, 257);
    drop(f, 3.0f, c, 0.1f);  // 0.3 m deep at the centre
    const double threshold = 1e-3;  // m: 0.3 % of the drop's depth
    struct Radii {
        double front[4], crest[4];  // +x, +z, diagonal (+x, +z), anti-diagonal (−x, +z)
    };
    const int dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
    auto measure = [&] {
        Radii r;
        for (int d = 0; d < 4; ++d) {
            r.front[d] = frontRadius(f, c, dirs[d][0], dirs[d][1], threshold);
            r.crest[d] = crestRadius(f, c, dirs[d][0], dirs[d][1], threshold);
        }
        return r;
    };
    for (int k = 0; k < 50; ++k) f.step(1.0f);
    const Radii at50 = measure();
    for (int k = 0; k < 50; ++k) f.step(1.0f);
    const Radii at100 = measure();
    // The kernel's 8-fold symmetry: −x ≡ +z ≡ +x, anti-diagonal ≡ diagonal (up to the order
    // of float sums).
    CHECK(frontRadius(f, c, -1, 0, threshold) == Approx(at100.front[0]).margin(1e-4));
    CHECK(at100.front[1] == Approx(at100.front[0]).margin(1e-4));
    CHECK(at100.front[3] == Approx(at100.front[2]).margin(1e-4));
    for (const char* what : {"front", "crest"}) {
        const bool front = what[0] == 'f';
        const double* r50 = front ? at50.front : at50.crest;
        const double* r100 = front ? at100.front : at100.crest;
        const double axisSpeed = (r100[0] - r50[0]) / 50.0, diagSpeed = (r100[2] - r50[2]) / 50.0;
        INFO(what << ": axis " << r50[0] << " -> " << r100[0] << ", diagonal " << r50[2] << " -> " << r100[2]
                  << " cells at steps 50 -> 100");
        CHECK(r50[0] > 40.0);  // it did travel
        // Same speed along axes and diagonals: the front's advance over 50 steps differs by
        // less than a cell, and its radius after 100 steps by less than 2. (The radius alone
        // carries the footprint's shape: the SR 3 disc reaches 2√2 = 2.83 cells along the
        // diagonal and 2 along the axes, a 0.83-cell head start that the front keeps.)
        CHECK(std::abs(axisSpeed - diagSpeed) * 50.0 <= 1.0);
        CHECK(std::abs(r100[0] - r100[2]) <= 2.0);
        // Long-wave speed of the kernel, √3/2 cells per step (the crest of a finite drop is a
        // little slower: its group velocity).
        CHECK(axisSpeed == Approx(std::sqrt(0.75)).epsilon(0.05));
        CHECK(diagSpeed == Approx(std::sqrt(0.75)).epsilon(0.05));
    }
}

TEST_CASE("DF = 1 keeps the discrete energy of a 64x64 field constant (bounded) over 10,000 steps", "[ripple]") {
    RippleField f(64, 64);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> dist(-1.0f, 1.0f);
    for (float& v : f.current()) v = dist(rng);
    for (float& v : f.previous()) v = dist(rng);
    f.step(1.0f);  // from here on the ring is 0 in both levels
    f.step(1.0f);
    const double e0 = leapfrogEnergy(f);
    REQUIRE(e0 > 0.0);
    double lo = e0, hi = e0;
    float maxAbs = 0.0f;
    for (int k = 0; k < 10000; ++k) {
        f.step(1.0f);
        if (k % 10 == 9) {
            const double e = leapfrogEnergy(f);
            lo = std::min(lo, e);
            hi = std::max(hi, e);
        }
        for (float v : f.current()) maxAbs = std::max(maxAbs, std::abs(v));
    }
    INFO("E0 " << e0 << ", range [" << lo << ", " << hi << "], max |Vh| " << maxAbs);
    // Float rounding only: measured 1e-7 relative over the run.
    CHECK(hi / e0 - 1.0 < 1e-4);
    CHECK(1.0 - lo / e0 < 1e-4);
    CHECK(maxAbs < 10.0f);
}

TEST_CASE("DF < 1 makes the discrete energy decay monotonically over 50-step windows, by DF per step", "[ripple]") {
    // Eq. 2 with damping: each eigenmode obeys λ² − DF·a·λ + DF = 0 (|a| < 2), complex roots
    // with |λ|² = DF: amplitudes shrink by √DF a step, the energy by DF.
    for (float df : {0.999f, 0.99f, 0.95f}) {
        RippleField f(64, 64);
        std::mt19937 rng(4);
        std::uniform_real_distribution<float> dist(-1.0f, 1.0f);
        for (float& v : f.current()) v = dist(rng);
        for (float& v : f.previous()) v = dist(rng);
        f.step(df);
        f.step(df);
        const double e0 = leapfrogEnergy(f);
        const int window = 50;
        // Long enough for a decay of 1e-12 at most, far from float underflow.
        const int windows = std::min(200, int(std::log(1e-12) / std::log(double(df))) / window);
        double previous = 0.0;
        int rising = 0;
        for (int w = 0; w < windows; ++w) {
            double sum = 0.0;
            for (int k = 0; k < window; ++k) {
                f.step(df);
                sum += leapfrogEnergy(f);
            }
            if (w > 0 && !(sum < previous)) ++rising;
            previous = sum;
        }
        const int steps = windows * window;
        const double ratio = leapfrogEnergy(f) / e0, expect = std::pow(double(df), double(steps));
        INFO("DF " << df << ": " << steps << " steps, E/E0 = " << ratio << ", DF^steps = " << expect);
        CHECK(windows >= 10);
        CHECK(rising == 0);
        CHECK(ratio == Approx(expect).epsilon(0.01));
    }
}

TEST_CASE("eq. 7: AF sets the stamp's vertical velocity AF*Vh, one step later the centre differs from AF = 0 by DF*AF*Vh(t)",
          "[ripple]") {
    // Eq. 7 writes Vh(t−1) = Vh(t)·(1 − AF); eq. 2 then gives Vh(t+1) = (Buff − Vh(t−1))·DF,
    // with Buff the same for every AF: the difference from AF = 0 is DF·AF·Vh(t) on the footprint.
    const float df = 0.95f;
    const std::vector<float> base = centreAfterDrop(0.0f, df, 1);
    for (float af : {-0.3f, 0.3f, 1.0f}) {
        const std::vector<float> h = centreAfterDrop(af, df, 1);
        CHECK(h[0] == base[0]);
        CHECK(h[1] - base[1] == Approx(df * af * h[0]).epsilon(1e-5));
    }
}

TEST_CASE("eq. 6-7 as [Kang2008] describes AF: AF > 0 drives the splash further (a deeper crater), AF < 0 returns the surface to rest sooner",
          "[ripple]") {
    // [Kang2008] §IV-2.1: AF > 0 strengthens the water's reaction, AF < 0 makes the deformation
    // die down and the surface return to its original height quickly. SR 5 drop 0.5 m deep
    // (the cannonball), DF 0.95; AF ±0.3 as the paper's fish (−0.3) and ship (+0.3).
    // Measured (centre, m): AF −0.3: at rest height after 3 steps, first crest +0.83;
    // AF 0: after 4, +0.61; AF +0.3: deepest −0.60, after 5, +0.39.
    const float df = 0.95f;
    const int steps = 40;
    const std::vector<float> neg = centreAfterDrop(-0.3f, df, steps), zero = centreAfterDrop(0.0f, df, steps),
                             pos = centreAfterDrop(0.3f, df, steps);
    // Step at which the centre first reaches its rest height (crosses 0 going up).
    auto backToRest = [](const std::vector<float>& h) {
        for (size_t k = 0; k < h.size(); ++k)
            if (h[k] >= 0.0f) return int(k);
        return -1;
    };
    // The deepest the centre goes before it first comes back to rest.
    auto deepest = [&](const std::vector<float>& h) {
        return *std::min_element(h.begin(), h.begin() + backToRest(h));
    };
    INFO("back to rest at step: AF -0.3 " << backToRest(neg) << ", 0 " << backToRest(zero) << ", +0.3 " << backToRest(pos));
    INFO("deepest: AF -0.3 " << deepest(neg) << ", 0 " << deepest(zero) << ", +0.3 " << deepest(pos));
    REQUIRE(backToRest(neg) > 0);
    REQUIRE(backToRest(zero) > 0);
    REQUIRE(backToRest(pos) > 0);
    // AF < 0: the surface heads back at once, and reaches its rest height first.
    CHECK(neg[1] > neg[0]);
    CHECK(backToRest(neg) < backToRest(zero));
    CHECK(backToRest(zero) < backToRest(pos));
    // AF > 0: the crater keeps deepening after the stamp; AF <= 0 never goes below the stamp.
    CHECK(pos[1] < pos[0]);
    CHECK(deepest(pos) < deepest(zero));
    CHECK(deepest(zero) == zero[0]);
    CHECK(deepest(neg) == neg[0]);
}

TEST_CASE("absorbing boundary: the amplitude a ring reflects back to the centre is at most 5% of the fixed edge's with a 32-cell sponge, and shrinks with the width",
          "[ripple]") {
    // An SR 3 drop at the centre of a 129² patch; the ring reaches the edge (64 cells) after
    // about 75 steps and what it reflects is back in the central 33² box from about step
    // 130. Reflected amplitude = max |Vh − Vh_free| over the box and steps 116–258, where
    // Vh_free is the same drop in an 801² patch (its edge too far to answer in time).
    const int t0 = 116, t1 = 258, box = 16;
    auto record = [&](int size, RippleBoundary boundary, int width) {
        RippleField f(size, size, boundary, width);
        const int c = size / 2;
        drop(f, 3.0f, c, 0.1f);
        std::vector<float> out;
        for (int k = 0; k < t1; ++k) {
            f.step(1.0f);
            if (k < t0) continue;
            for (int z = c - box; z <= c + box; ++z)
                for (int x = c - box; x <= c + box; ++x) out.push_back(f.currentAt(x, z));
        }
        return out;
    };
    const std::vector<float> freeSpace = record(801, RippleBoundary::Fixed, 0);
    auto reflected = [&](const std::vector<float>& run) {
        double m = 0.0;
        for (size_t i = 0; i < run.size(); ++i) m = std::max(m, std::abs(double(run[i]) - double(freeSpace[i])));
        return m;
    };
    double freeMax = 0.0;
    for (float v : freeSpace) freeMax = std::max(freeMax, double(std::abs(v)));
    const double fixedEdge = reflected(record(129, RippleBoundary::Fixed, 0));
    const double w8 = reflected(record(129, RippleBoundary::Absorbing, 8)) / fixedEdge;
    const double w16 = reflected(record(129, RippleBoundary::Absorbing, 16)) / fixedEdge;
    const double w32 = reflected(record(129, RippleBoundary::Absorbing, 32)) / fixedEdge;
    INFO("free-space max " << freeMax << " m; fixed edge reflects " << fixedEdge << " m; sponge / fixed amplitude: w 8 "
                           << w8 << ", w 16 " << w16 << ", w 32 " << w32);
    REQUIRE(fixedEdge > 5.0 * freeMax);  // the fixed edge does send the ring back
    CHECK(w32 <= 0.05);
    CHECK(w16 < w8);
    CHECK(w32 < w16);
}

TEST_CASE("Table 2: a falling sphere stamps from its first contact until it is entirely below fixHeight, then never again",
          "[ripple][table2]") {
    // Radius 0.25 m on 0.0625 m cells (SR 4), falling 1/16 m a step from 1 m (all exact in
    // binary) onto still water at 0, the surface it sees is the live ripple at its centre.
    // It touches when its bottom reaches 0 (centre 0.25 m: step 12) and is entirely below
    // fixHeight = 0 once its top is (centre below −0.25 m: after step 20).
    const float cell = 0.0625f;
    RippleField f(64, 64);
    FootprintCache cache;
    BoundingSphere def;
    def.radius = 0.25f;
    SphereContact contact;
    std::vector<int> stamped;
    for (int k = 0; k < 300; ++k) {
        SphereMotion m;
        m.gridX = 32.0f;
        m.gridZ = 31.7f;
        m.centreY = 1.0f - float(k) / 16.0f;
        m.verticalVelocity = -3.75f;
        m.speed = 3.75f;
        m.surfaceY = f.currentAt(32, 32);
        if (stepSphere(f, cache, cell, def, contact, m)) stamped.push_back(k);
        f.step(0.95f);
    }
    std::vector<int> expect;
    for (int k = 12; k <= 20; ++k) expect.push_back(k);
    CHECK(stamped == expect);
    CHECK(contact.fixHeight == 0.0f);
    CHECK(contact.phase == ContactPhase::Free);  // deep: released
}

TEST_CASE("Table 2: a sphere resting on the water stamps every step, however the surface under it moves", "[ripple][table2]") {
    // The paper's ship sphere (SR 7, SHR 0.2, AF 0.3, DF 0.96) bobbing 4 cm around the rest
    // level for 1000 steps, beside a second one whose splash runs under it; each sees the live
    // ripple at its centre as the surface.
    const float cell = 0.1f;
    RippleField f(96, 96);
    FootprintCache cache;
    BoundingSphere ship;
    ship.radius = 0.7f;
    ship.heightRatio = 0.2f;
    ship.accelerationFactor = 0.3f;
    ship.direction = SphereDirection::Down;
    SphereContact a, b;
    int stampsA = 0, stampsB = 0;
    for (int k = 0; k < 1000; ++k) {
        SphereMotion m;
        m.gridX = 40.0f;
        m.gridZ = 48.0f;
        m.centreY = 0.04f * std::sin(0.1f * float(k));
        m.surfaceY = f.currentAt(40, 48);
        stampsA += stepSphere(f, cache, cell, ship, a, m) ? 1 : 0;
        m.gridX = 55.0f;
        m.centreY = 0.04f * std::cos(0.13f * float(k));
        m.surfaceY = f.currentAt(55, 48);
        stampsB += stepSphere(f, cache, cell, ship, b, m) ? 1 : 0;
        f.step(0.96f);
    }
    CHECK(stampsA == 1000);
    CHECK(stampsB == 1000);
    CHECK(a.fixHeight == 0.0f);
}

