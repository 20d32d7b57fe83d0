// GPU ripple field (RippleFieldGpu, shaders/ripple_*.comp) against its CPU twin: eq. 1–2 steps
// with both boundaries, eq. 5 + 7 stamps with and without overlap, scrolling, Table 2 planning
// on the CPU, readback (docs/references.md#ripple-layer, [Kang2008]; timings: tests/bench/bench_ripple.cpp).
#include "gfx/gl.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/kang2008/gpu/ripple_gpu.h"
#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/sphere_stamp.h"
#include "platform/platform.h"

#include <catch2/catch.hpp>
#include "support/ripple_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

using namespace ob;
using namespace ob::interaction;
using ob::test::randomField;
using ob::test::load;

namespace {

std::unique_ptr<platform::Platform> glContext() {
    gfx::requestDebugOutput(true);
    return platform::createHeadlessPlatform({16, 16});
}

// Largest |a − b| over two equal-sized arrays, and how many elements differ in any bit.
struct Difference {
    double maxAbs = 0.0;
    size_t bitsDiffer = 0;
};

Difference compare(std::span<const float> a, std::span<const float> b) {
    REQUIRE(a.size() == b.size());
    Difference d;
    for (size_t i = 0; i < a.size(); ++i) {
        d.maxAbs = std::max(d.maxAbs, std::abs(double(a[i]) - double(b[i])));
        if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0) ++d.bitsDiffer;
    }
    return d;
}

// Both levels of the GPU field against the CPU one.
Difference compareLevels(const RippleFieldGpu& gpu, const RippleField& cpu) {
    std::vector<float> cur, prev;
    gpu.readCurrent(cur);
    gpu.readPrevious(prev);
    Difference a = compare(cur, cpu.current()), b = compare(prev, cpu.previous());
    return {std::max(a.maxAbs, b.maxAbs), a.bitsDiffer + b.bitsDiffer};
}

} // namespace

TEST_CASE("GPU eq. 1-2 steps equal RippleField::step within 1e-5 over 100 steps on random 64x64 and 256x256 fields, fixed and absorbing",
          "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    struct Case {
        int rows, cols;
        RippleBoundary boundary;
        int sponge;
        float df;
    };
    const Case cases[] = {
        {64, 64, RippleBoundary::Fixed, 0, 1.0f},      {64, 64, RippleBoundary::Absorbing, 16, 1.0f},
        {256, 256, RippleBoundary::Fixed, 0, 0.97f},   {256, 256, RippleBoundary::Absorbing, 16, 0.97f},
        {256, 256, RippleBoundary::Absorbing, 40, 1.0f}, {37, 70, RippleBoundary::Absorbing, 12, 0.99f},  // N ≠ M: rows are z
    };
    unsigned seed = 100;
    for (const Case& c : cases) {
        const size_t cells = size_t(c.rows) * size_t(c.cols);
        // Random everywhere, the ring included: it feeds the first step, then is held at 0.
        const std::vector<float> h = randomField(cells, ++seed), p = randomField(cells, ++seed);
        RippleField cpu(c.rows, c.cols, c.boundary, c.sponge);
        RippleFieldGpu gpu(c.rows, c.cols, c.boundary, c.sponge);
        REQUIRE(gpu.spongeWidth() == cpu.spongeWidth());
        load(cpu, h, p);
        gpu.upload(cpu);
        Difference worst;
        for (int k = 1; k <= 100; ++k) {
            cpu.step(c.df);
            gpu.step(c.df);
            if (k % 10 == 0) {
                const Difference d = compareLevels(gpu, cpu);
                worst.maxAbs = std::max(worst.maxAbs, d.maxAbs);
                worst.bitsDiffer += d.bitsDiffer;
            }
        }
        INFO(c.rows << "x" << c.cols << (c.boundary == RippleBoundary::Fixed ? " fixed" : " absorbing") << " sponge "
                    << c.sponge << " DF " << c.df << ": max |gpu - cpu| " << worst.maxAbs << ", values differing in any bit "
                    << worst.bitsDiffer);
        CHECK(worst.maxAbs <= 1e-5);
        // The field is still alive, so the comparison means something.
        std::vector<float> cur;
        gpu.readCurrent(cur);
        CHECK(*std::max_element(cur.begin(), cur.end()) > 0.01f);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("GPU step holds the outer ring at exactly 0 and DF = 0 kills every wave", "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = 33, m = 21;
    RippleFieldGpu gpu(n, m);
    gpu.upload(randomField(size_t(n * m), 7), randomField(size_t(n * m), 8));
    std::vector<float> cur;
    for (int k = 0; k < 5; ++k) {
        gpu.step(1.0f);
        gpu.readCurrent(cur);
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < m; ++x)
                if (z == 0 || x == 0 || z == n - 1 || x == m - 1) REQUIRE(cur[size_t(z * m + x)] == 0.0f);
    }
    gpu.step(0.0f);
    gpu.readCurrent(cur);
    for (float v : cur) REQUIRE(v == 0.0f);
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("GPU stamps whose footprints do not overlap equal stampFootprint on the CPU within 1e-6 (eq. 5 and eq. 7)",
          "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = 96, m = 80;
    // SRs of several shapes (a point, fractional, the paper's 5 and 7), bases, SD·SHR·Δ and
    // AF of both signs; two clipped by the field's edge, one entirely off it.
    const std::vector<RippleStamp> stamps = {
        {12, 12, 5.0f, 0.1f, -0.25f, 0.0f},   {40, 14, 7.0f, -0.05f, 0.05f, 0.3f},  {66, 15, 2.5f, 0.0f, -0.1f, -0.3f},
        {15, 40, 0.8f, 0.2f, 0.35f, 0.5f},    {33, 45, 3.3f, 0.01f, -0.14f, 2.0f},  {60, 50, 6.2f, -0.3f, 0.02f, 0.0f},
        {1, 75, 4.0f, 0.0f, 1.0f, 0.0f},      {79, 95, 5.0f, 0.4f, -0.5f, 0.1f},    {300, -40, 5.0f, 1.0f, 1.0f, 0.0f},
        {45, 80, 2.0f, 0.07f, -0.033f, -0.5f},
    };
    for (RippleBoundary boundary : {RippleBoundary::Fixed, RippleBoundary::Absorbing}) {
        RippleField cpu(n, m, boundary, 10);
        RippleFieldGpu gpu(n, m, boundary, 10);
        load(cpu, randomField(size_t(n * m), 21, -0.2f, 0.2f), randomField(size_t(n * m), 22, -0.2f, 0.2f));
        cpu.step(0.95f);  // a stepped field: the ring is 0 in Vh(t), as in use
        gpu.upload(cpu);
        FootprintCache cache;
        for (const RippleStamp& s : stamps)
            stampFootprint(cpu, cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.accelerationFactor);
        gpu.stamp(stamps);
        Difference d = compareLevels(gpu, cpu);
        INFO("max |gpu - cpu| " << d.maxAbs << ", values differing in any bit " << d.bitsDiffer);
        CHECK(d.maxAbs <= 1e-6);
        // A second round (the claims were released) and a step after it still agree.
        for (const RippleStamp& s : stamps)
            stampFootprint(cpu, cache.get(s.radiusCells), s.cx + 1, s.cz, s.base, s.heightScale, s.accelerationFactor);
        std::vector<RippleStamp> moved = stamps;
        for (RippleStamp& s : moved) s.cx += 1;
        gpu.stamp(moved);
        cpu.step(0.95f);
        gpu.step(0.95f);
        d = compareLevels(gpu, cpu);
        CHECK(d.maxAbs <= 1e-6);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("GPU overlapping stamps: the last stamp in list order wins every shared cell, in both levels", "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = 64;
    // 40 random stamps over the whole field, a ship-like row of 6 SR 7 spheres that overlap
    // heavily, then by hand: two SR 3 stamps 2 cells apart share the cells between them, and a
    // later SR 1 stamp inside both owns its one cell.
    std::vector<RippleStamp> stamps;
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cell(-3, n + 2);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int k = 0; k < 40; ++k)
        stamps.push_back({cell(rng), cell(rng), 1.0f + 6.0f * std::abs(unit(rng)), 0.1f * unit(rng), 0.3f * unit(rng), unit(rng)});
    for (int k = 0; k < 6; ++k) stamps.push_back({30 + 4 * k, 44, 7.0f, 0.02f * float(k), -0.05f, 0.3f});
    const size_t first = stamps.size();
    stamps.push_back({20, 20, 3.0f, 0.0f, -1.0f, 0.0f});
    stamps.push_back({22, 20, 3.0f, 0.0f, 1.0f, 0.5f});
    stamps.push_back({21, 21, 1.0f, 0.25f, 0.0f, 0.0f});

    RippleField cpu(n, n);
    RippleFieldGpu gpu(n, n);
    load(cpu, randomField(size_t(n * n), 31, -0.1f, 0.1f), randomField(size_t(n * n), 32, -0.1f, 0.1f));
    cpu.step(1.0f);
    gpu.upload(cpu);
    FootprintCache cache;
    for (const RippleStamp& s : stamps)
        stampFootprint(cpu, cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.accelerationFactor);
    gpu.stamp(stamps);
    std::vector<float> cur, prev;
    gpu.readCurrent(cur);
    gpu.readPrevious(prev);
    // The documented rule is what the CPU does stamping the list in order.
    const Difference d = compareLevels(gpu, cpu);
    INFO("max |gpu - sequential cpu| " << d.maxAbs);
    CHECK(d.maxAbs <= 1e-6);
    // The hand cases: (21, 20) is in both SR 3 discs (PR 1 from each): the second wins with
    // PH = √8, AF 0.5; (21, 21) belongs to the SR 1 stamp, the last of the three.
    CHECK(cur[size_t(20 * n + 21)] == Approx(std::sqrt(8.0)).epsilon(1e-6));
    CHECK(prev[size_t(20 * n + 21)] == Approx(0.5 * std::sqrt(8.0)).epsilon(1e-6));
    CHECK(cur[size_t(21 * n + 21)] == 0.25f);
    CHECK(prev[size_t(21 * n + 21)] == 0.25f);
    // (19, 20) is only in the first disc: −1·PH(1) = −√8.
    CHECK(cur[size_t(20 * n + 19)] == Approx(-std::sqrt(8.0)).epsilon(1e-6));
    // Reversing the list reverses the winner where the two SR 3 discs overlap.
    RippleFieldGpu reversed(n, n);
    reversed.upload(cpu);
    std::vector<RippleStamp> two = {stamps[first + 1], stamps[first]};
    reversed.stamp(two);
    reversed.readCurrent(cur);
    CHECK(cur[size_t(20 * n + 21)] == Approx(-std::sqrt(8.0)).epsilon(1e-6));
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("GPU scroll moves both levels like RippleField::scroll, zero-filling new cells and keeping the ring 0",
          "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = 40, m = 52;
    RippleField cpu(n, m, RippleBoundary::Absorbing, 8);
    RippleFieldGpu gpu(n, m, RippleBoundary::Absorbing, 8);
    load(cpu, randomField(size_t(n * m), 41), randomField(size_t(n * m), 42));
    cpu.step(0.98f);
    gpu.upload(cpu);
    const std::pair<int, int> shifts[] = {{2, -1}, {-3, 2}, {0, 1}, {1, 0}, {-9, 0}, {0, 0}, {5, 7}, {60, 0}, {0, -41}};
    for (auto [dx, dz] : shifts) {
        if (dx == 60) {  // refill after the clearing shifts, so later comparisons see data
            load(cpu, randomField(size_t(n * m), 43), randomField(size_t(n * m), 44));
            gpu.upload(cpu);
        }
        cpu.scroll(dx, dz);
        gpu.scroll(dx, dz);
        cpu.step(0.98f);
        gpu.step(0.98f);
        const Difference d = compareLevels(gpu, cpu);
        INFO("dx=" << dx << " dz=" << dz << ": max |gpu - cpu| " << d.maxAbs);
        CHECK(d.maxAbs <= 1e-6);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("Table 2 on the CPU (planSphereStamp) with GPU stamps and steps reproduces stepSphere on RippleField",
          "[ripple_gpu]") {
    // A cannonball falling through the water and a sphere bobbing at the surface, 80 steps;
    // the surface the spheres see is the live ripple at their centre, read back each step.
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = 64;
    const float cell = 0.1f, df = 0.95f;
    BoundingSphere ball;
    ball.radius = 0.5f;
    BoundingSphere buoy;
    buoy.radius = 0.35f;
    buoy.heightRatio = 0.2f;
    buoy.afFromMotion = true;
    buoy.reference = {10.0f, 1.0f, 0.5f};
    RippleField cpu(n, n, RippleBoundary::Absorbing, 8);
    RippleFieldGpu gpu(n, n, RippleBoundary::Absorbing, 8);
    FootprintCache cache;
    SphereContact cpuBall, cpuBuoy, gpuBall, gpuBuoy;
    std::vector<float> heights;
    int stamped = 0;
    for (int k = 0; k < 80; ++k) {
        SphereMotion a;
        a.gridX = 24.3f;
        a.gridZ = 30.0f;
        a.centreY = 1.0f - 0.05f * float(k);
        a.verticalVelocity = -3.0f;
        a.speed = 3.0f;
        SphereMotion b;
        b.gridX = 40.0f;
        b.gridZ = 33.6f;
        b.centreY = 0.1f * std::sin(0.2f * float(k));
        b.verticalVelocity = 0.02f * std::cos(0.2f * float(k)) * 60.0f;
        b.speed = std::abs(b.verticalVelocity) + 1.0f;
        b.mass = 20.0f;
        // --- CPU path
        a.surfaceY = cpu.currentAt(24, 30);
        b.surfaceY = cpu.currentAt(40, 34);
        const bool cpuA = stepSphere(cpu, cache, cell, ball, cpuBall, a);
        b.surfaceY = cpu.currentAt(40, 34);  // after the ball's stamp, as the sandbox reads it
        const bool cpuB = stepSphere(cpu, cache, cell, buoy, cpuBuoy, b);
        cpu.step(df);
        // --- GPU path: decisions from the read-back Vh(t), stamps in one call
        gpu.readCurrent(heights);
        std::vector<RippleStamp> list;
        RippleStamp s;
        a.surfaceY = heights[size_t(30 * n + 24)];
        b.surfaceY = heights[size_t(34 * n + 40)];
        const bool gpuA = planSphereStamp(heights, n, n, cell, ball, gpuBall, a, s);
        if (gpuA) list.push_back(s);
        const bool gpuB = planSphereStamp(heights, n, n, cell, buoy, gpuBuoy, b, s);
        if (gpuB) list.push_back(s);
        gpu.stamp(list);
        gpu.step(df);
        INFO("step " << k);
        REQUIRE(gpuA == cpuA);
        REQUIRE(gpuB == cpuB);
        stamped += int(cpuA) + int(cpuB);
        const Difference d = compareLevels(gpu, cpu);
        REQUIRE(d.maxAbs <= 1e-5);
    }
    CHECK(stamped > 60);  // both spheres did stamp
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("GPU asynchronous readback (beginReadback, finishReadback) returns the same Vh(t) as readCurrent", "[ripple_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    RippleFieldGpu gpu(48, 48);
    std::vector<float> out, direct;
    CHECK_FALSE(gpu.finishReadback(out));  // nothing pending
    gpu.upload(randomField(48 * 48, 51), randomField(48 * 48, 52));
    gpu.step(0.9f);
    gpu.beginReadback();
    gpu.step(0.9f);  // later work does not change the copy
    REQUIRE(gpu.finishReadback(out, true));
    gpu.readPrevious(direct);
    CHECK(out == direct);
    CHECK_FALSE(gpu.finishReadback(out));
    CHECK(gfx::glErrorCount() == errorsBefore);
}
