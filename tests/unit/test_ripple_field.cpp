// Ripple field, [Kang2008] eq. 1–2: the kernel by hand, a naive double reference, boundaries,
// scrolling, the worker pool, and the `ripple` command on files.
#include "tools/cmd_ripple.h"
#include "core/error.h"
#include "core/npy.h"
#include "core/parallel.h"
#include "interaction/kang2008/ripple_field.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include "support/ripple_reference.h"

#include <atomic>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <tuple>
#include <stdexcept>
#include <vector>

using ob::test::randomField;
using ob::test::load;
using ob::test::leapfrogEnergy;

using ob::interaction::RippleBoundary;
using ob::interaction::RippleField;

namespace {

// Eq. 1–2 written plainly in double precision: all 8 neighbours weigh 1/4, the centre 0;
// interior cells only, the outer ring of the new level is 0.
struct NaiveRipple {
    int n, m;
    std::vector<double> cur, prev;

    void step(double df) { ob::test::naiveRippleStep(n, m, cur, prev, df); }
};

float at(std::span<const float> level, int cols, int x, int z) { return level[size_t(z) * size_t(cols) + size_t(x)]; }

// Σ_{cells in the box of half-size `box` around the centre} Vh(t)².
double centreEnergy(const RippleField& f, int box) {
    const int cz = f.rows() / 2, cx = f.cols() / 2;
    double e = 0.0;
    for (int z = cz - box; z <= cz + box; ++z)
        for (int x = cx - box; x <= cx + box; ++x) {
            const double v = f.currentAt(x, z);
            e += v * v;
        }
    return e;
}

// A Gaussian bump (σ = 2 cells, height 1) at the centre of both levels, ring left at 0.
void gaussianBump(RippleField& f) {
    const int n = f.rows(), m = f.cols(), cz = n / 2, cx = m / 2;
    for (int z = 1; z < n - 1; ++z)
        for (int x = 1; x < m - 1; ++x) {
            const float v = float(std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / 8.0));
            f.current()[size_t(z * m + x)] = v;
            f.previous()[size_t(z * m + x)] = v;
        }
}

} // namespace

TEST_CASE("eq. 1-2: one step of a unit impulse puts DF/4 on all 8 neighbours and -DF*Vh(t-1) at the centre", "[ripple]") {
    const float df = 0.9f;
    RippleField f(7, 7);
    f.current()[3 * 7 + 3] = 1.0f;
    f.previous()[3 * 7 + 3] = 0.5f;
    f.step(df);
    for (int z = 0; z < 7; ++z)
        for (int x = 0; x < 7; ++x) {
            const int d = std::max(std::abs(x - 3), std::abs(z - 3));
            const float expect = d == 0 ? -0.5f * df : d == 1 ? 0.25f * df : 0.0f;
            INFO("x=" << x << " z=" << z);
            CHECK(at(f.current(), 7, x, z) == Approx(expect).margin(1e-7));
            // The levels rotated: Vh(t−1) is the old Vh(t).
            CHECK(at(f.previous(), 7, x, z) == ((x == 3 && z == 3) ? 1.0f : 0.0f));
        }
}

TEST_CASE("eq. 1-2: two steps of a unit impulse give the hand-computed ring values", "[ripple]") {
    // DF = 0.9, Vh(t) = δ, Vh(t−1) = 0. Step 1: the 8 neighbours hold 0.25·0.9 = 0.225, the
    // centre 0. Step 2, Vh = (¼·Σ8 − Vh(t−1))·0.9 at offset (dx, dz):
    //   (0,0): (¼·8·0.225 − 1)·0.9 = (0.45 − 1)·0.9 = −0.495
    //   (1,0): neighbours holding 0.225: (0,±1), (1,±1) → ¼·0.9·0.9 = 0.2025
    //   (1,1): (0,1), (1,0) → ¼·0.45·0.9 = 0.10125
    //   (2,0): (1,−1), (1,0), (1,1) → ¼·0.675·0.9 = 0.151875
    //   (2,1): (1,0), (1,1) → 0.10125;  (2,2): (1,1) → ¼·0.225·0.9 = 0.050625;  |d| = 3: 0
    RippleField f(9, 9);
    f.current()[4 * 9 + 4] = 1.0f;
    f.step(0.9f);
    f.step(0.9f);
    auto hand = [](int dx, int dz) {
        dx = std::abs(dx);
        dz = std::abs(dz);
        if (dx < dz) std::swap(dx, dz);
        if (dx == 0) return -0.495;
        if (dx == 1) return dz == 0 ? 0.2025 : 0.10125;
        if (dx == 2) return dz == 0 ? 0.151875 : dz == 1 ? 0.10125 : 0.050625;
        return 0.0;
    };
    for (int z = 0; z < 9; ++z)
        for (int x = 0; x < 9; ++x) {
            INFO("x=" << x << " z=" << z);
            CHECK(at(f.current(), 9, x, z) == Approx(hand(x - 4, z - 4)).margin(1e-7));
        }
}

TEST_CASE("eq. 2: DF = 0 kills every wave in the next step", "[ripple]") {
    RippleField f(20, 30);
    load(f, randomField(600, 1), randomField(600, 2));
    f.step(0.0f);
    for (float v : f.current()) REQUIRE(v == 0.0f);
}

TEST_CASE("eq. 1-2 match a naive double-precision reference on a random 64x37 field over 50 steps", "[ripple]") {
    const int n = 64, m = 37;
    // Random values everywhere, the ring included: the ring of the given Vh(t) feeds the
    // first step, then is held at 0.
    std::vector<float> h = randomField(n * m, 11), p = randomField(n * m, 12);
    for (float df : {1.0f, 0.97f}) {
        RippleField f(n, m);
        load(f, h, p);
        NaiveRipple ref{n, m, {h.begin(), h.end()}, {p.begin(), p.end()}};
        double worst = 0.0;
        for (int k = 0; k < 50; ++k) {
            f.step(df);
            ref.step(df);
            for (int i = 0; i < n * m; ++i) worst = std::max(worst, std::abs(double(f.current()[i]) - ref.cur[i]));
        }
        INFO("DF=" << df);
        CHECK(worst < 1e-5);
    }
}

TEST_CASE("eq. 1-2 with DF = 1 and a fixed border conserve the leapfrog energy, so the field stays bounded", "[ripple]") {
    RippleField f(48, 40);
    std::vector<float> h = randomField(48 * 40, 21), p = randomField(48 * 40, 22);
    load(f, h, p);
    f.step(1.0f);  // the ring of the random input is 0 in both levels from here on
    f.step(1.0f);
    const double e0 = leapfrogEnergy(f);
    REQUIRE(e0 > 0.0);
    float maxAbs = 0.0f;
    for (int k = 0; k < 2000; ++k) {
        f.step(1.0f);
        if (k % 100 == 99) REQUIRE(leapfrogEnergy(f) == Approx(e0).epsilon(1e-3));
        for (float v : f.current()) maxAbs = std::max(maxAbs, std::abs(v));
    }
    // E bounds every cell: E >= (1 − λmax/2)·(|u|² + |v|²) with λmax < 2 on the interior.
    CHECK(maxAbs < 10.0f);
}

TEST_CASE("fixed boundary: the outer ring stays exactly 0 in both levels", "[ripple]") {
    const int n = 33, m = 21;
    RippleField f(n, m);
    load(f, randomField(n * m, 31), randomField(n * m, 32));
    for (int k = 0; k < 100; ++k) {
        f.step(1.0f);
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < m; ++x) {
                if (z != 0 && z != n - 1 && x != 0 && x != m - 1) continue;
                REQUIRE(at(f.current(), m, x, z) == 0.0f);
                if (k > 0) REQUIRE(at(f.previous(), m, x, z) == 0.0f);
            }
    }
}

TEST_CASE("fields of 1x1, 2x2 and 2xM are all border and become 0 after one step", "[ripple]") {
    for (auto [n, m] : {std::pair{1, 1}, std::pair{2, 2}, std::pair{2, 9}, std::pair{5, 2}}) {
        RippleField f(n, m);
        load(f, randomField(size_t(n * m), 41), randomField(size_t(n * m), 42));
        f.step(1.0f);
        for (float v : f.current()) REQUIRE(v == 0.0f);
    }
}

TEST_CASE("rows split over 1, 2 or 3 workers give bit-identical 512x512 fields", "[ripple][parallel]") {
    const int n = 512;
    std::vector<float> h = randomField(n * n, 51), p = randomField(n * n, 52);
    auto run = [&](int workers, RippleBoundary b) {
        ob::setWorkerCount(workers);
        RippleField f(n, n, b, 20);
        load(f, h, p);
        for (int k = 0; k < 20; ++k) f.step(0.98f);
        std::vector<float> out(f.current().begin(), f.current().end());
        return out;
    };
    for (RippleBoundary b : {RippleBoundary::Fixed, RippleBoundary::Absorbing}) {
        const auto one = run(1, b), two = run(2, b), three = run(3, b);
        ob::setWorkerCount(0);
        CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)) == 0);
        CHECK(std::memcmp(one.data(), three.data(), one.size() * sizeof(float)) == 0);
        CHECK(one != std::vector<float>(one.size(), 0.0f));
    }
}

TEST_CASE("absorbing boundary: away from the sponge it is eq. 1-2 bit for bit", "[ripple]") {
    // Waves move at most one cell a step, so for 20 steps a bump at the centre of a 129²
    // patch never reaches the 16-cell band: both boundaries must give the same bits.
    RippleField fixedF(129, 129, RippleBoundary::Fixed);
    RippleField spongeF(129, 129, RippleBoundary::Absorbing, 16);
    gaussianBump(fixedF);
    gaussianBump(spongeF);
    for (int k = 0; k < 20; ++k) {
        fixedF.step(0.99f);
        spongeF.step(0.99f);
    }
    REQUIRE(std::memcmp(fixedF.current().data(), spongeF.current().data(), 129 * 129 * sizeof(float)) == 0);
}

TEST_CASE("absorbing boundary returns far less energy to the centre than the fixed boundary", "[ripple]") {
    // A bump at the centre of a 129² patch sends a ring out; it reaches the edge (64 cells)
    // after about 64–75 steps and, if reflected, is back at the centre from about step 150.
    // Energy in the central 33² box over steps 160–260, minus what free space leaves there
    // (a 801² patch, whose edge is too far for any reflection to come back in time).
    auto returned = [](int size, RippleBoundary b) {
        RippleField f(size, size, b, 16);
        gaussianBump(f);
        double e = 0.0;
        for (int k = 0; k < 260; ++k) {
            f.step(1.0f);
            if (k >= 160) e += centreEnergy(f, 16);
        }
        return e;
    };
    const double freeSpace = returned(801, RippleBoundary::Fixed);
    const double fixedEdge = returned(129, RippleBoundary::Fixed) - freeSpace;
    const double sponge = returned(129, RippleBoundary::Absorbing) - freeSpace;
    INFO("free " << freeSpace << " fixed excess " << fixedEdge << " sponge excess " << sponge);
    REQUIRE(fixedEdge > 100.0 * freeSpace);  // the fixed edge does reflect
    CHECK(sponge < 0.1 * fixedEdge);
}

TEST_CASE("absorbing boundary: the outer ring stays 0 and the field decays", "[ripple]") {
    RippleField f(64, 64, RippleBoundary::Absorbing, 12);
    gaussianBump(f);
    const double e0 = centreEnergy(f, 31);
    for (int k = 0; k < 600; ++k) f.step(1.0f);
    for (int i = 0; i < 64; ++i) {
        REQUIRE(f.currentAt(i, 0) == 0.0f);
        REQUIRE(f.currentAt(i, 63) == 0.0f);
        REQUIRE(f.currentAt(0, i) == 0.0f);
        REQUIRE(f.currentAt(63, i) == 0.0f);
    }
    CHECK(centreEnergy(f, 31) < 0.01 * e0);
}

TEST_CASE("sponge profile: 0 on the ring, sin^2 ramp, 1 from the band width inwards", "[ripple]") {
    CHECK(RippleField::spongeFactor(0, 16) == 0.0f);
    CHECK(RippleField::spongeFactor(8, 16) == Approx(0.5));
    CHECK(RippleField::spongeFactor(4, 16) == Approx(std::pow(std::sin(std::numbers::pi / 8.0), 2)));
    CHECK(RippleField::spongeFactor(16, 16) == 1.0f);
    CHECK(RippleField::spongeFactor(40, 16) == 1.0f);
    CHECK(RippleField::spongeFactor(3, 0) == 1.0f);
}

TEST_CASE("scroll moves both levels by whole cells, zero-fills new cells and keeps the ring 0", "[ripple]") {
    const int n = 8, m = 10;
    RippleField f(n, m);
    std::vector<float> h(n * m), p(n * m);
    for (int z = 1; z < n - 1; ++z)
        for (int x = 1; x < m - 1; ++x) {
            h[size_t(z * m + x)] = float(100 * z + x);
            p[size_t(z * m + x)] = -float(100 * z + x);
        }
    for (auto [dx, dz] : {std::pair{2, -1}, std::pair{-3, 2}, std::pair{0, 1}, std::pair{1, 0}, std::pair{-9, 0}}) {
        load(f, h, p);
        f.scroll(dx, dz);
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < m; ++x) {
                const int sx = x + dx, sz = z + dz;
                const bool ring = z == 0 || z == n - 1 || x == 0 || x == m - 1;
                const bool inside = sx >= 0 && sx < m && sz >= 0 && sz < n;
                const float expect = (!ring && inside) ? h[size_t(sz * m + sx)] : 0.0f;
                INFO("dx=" << dx << " dz=" << dz << " x=" << x << " z=" << z);
                REQUIRE(at(f.current(), m, x, z) == expect);
                REQUIRE(at(f.previous(), m, x, z) == -expect);
            }
    }
}

TEST_CASE("scroll keeps a travelling wave where it is in the world", "[ripple]") {
    // Stepping then scrolling by (3, −2) equals scrolling then stepping (away from the edge):
    // the patch moves, the waves do not.
    RippleField a(40, 40), b(40, 40);
    gaussianBump(a);
    gaussianBump(b);
    for (int k = 0; k < 5; ++k) {
        a.step(0.95f);
        b.step(0.95f);
    }
    a.scroll(3, -2);
    a.step(0.95f);
    b.step(0.95f);
    b.scroll(3, -2);
    for (int z = 8; z < 32; ++z)
        for (int x = 8; x < 32; ++x) REQUIRE(a.currentAt(x, z) == b.currentAt(x, z));
    REQUIRE(a.currentAt(20 - 3, 20 + 2) != 0.0f);
}

TEST_CASE("clear sets both levels to 0", "[ripple]") {
    RippleField f(10, 10);
    load(f, randomField(100, 61), randomField(100, 62));
    f.clear();
    for (float v : f.current()) REQUIRE(v == 0.0f);
    for (float v : f.previous()) REQUIRE(v == 0.0f);
}

TEST_CASE("parallelFor covers every index exactly once in contiguous chunks", "[parallel]") {
    for (int workers : {1, 2, 5}) {
        ob::setWorkerCount(workers);
        for (auto range : {std::tuple{0, 1000, 10}, std::tuple{-7, 13, 1}, std::tuple{5, 5, 1}, std::tuple{0, 3, 100}}) {
            const int begin = std::get<0>(range), end = std::get<1>(range), minChunk = std::get<2>(range);
            std::vector<std::atomic<int>> hits(size_t(std::max(end - begin, 0)));
            std::atomic<int> calls{0}, emptyChunks{0};  // Catch assertions are not thread-safe
            ob::parallelFor(begin, end, minChunk, [&](int b, int e) {
                if (b >= e) ++emptyChunks;
                ++calls;
                for (int i = b; i < e; ++i) ++hits[size_t(i - begin)];
            });
            REQUIRE(emptyChunks.load() == 0);
            for (auto& h : hits) REQUIRE(h.load() == 1);
            REQUIRE(calls.load() <= workers);
            if (end - begin < 2 * minChunk) REQUIRE(calls.load() <= 1);
        }
    }
    ob::setWorkerCount(0);
}

TEST_CASE("parallelFor rethrows a body's exception and runs nested calls inline", "[parallel]") {
    ob::setWorkerCount(2);
    REQUIRE_THROWS_AS(ob::parallelFor(0, 100, 1, [](int b, int) { if (b == 0) throw std::runtime_error("x"); }),
                      std::runtime_error);
    std::atomic<int> total{0};
    ob::parallelFor(0, 4, 1, [&](int b, int e) {
        ob::parallelFor(b * 10, e * 10, 1, [&](int bb, int ee) { total += ee - bb; });
    });
    REQUIRE(total.load() == 40);
    ob::setWorkerCount(0);
}

TEST_CASE("ripple command: K steps of eq. 1-2 on .npy files match the naive reference", "[ripple][cli]") {
    const int n = 12, m = 9;
    std::vector<float> h = randomField(n * m, 71), p = randomField(n * m, 72);
    const std::string in = ob::test::tempPath("in.npy"), prev = ob::test::tempPath("prev.npy"),
                      out = ob::test::tempPath("out.npy");
    ob::writeNpy(in, {size_t(n), size_t(m)}, h.data());
    ob::writeNpy(prev, {size_t(n), size_t(m)}, p.data());
    for (bool withPrev : {false, true}) {
        REQUIRE(ob::game::rippleCommand({in, withPrev ? prev : "", out, 3, 0.9f}) == 0);
        NaiveRipple ref{n, m, {h.begin(), h.end()}, withPrev ? std::vector<double>(p.begin(), p.end())
                                                           : std::vector<double>(h.begin(), h.end())};
        for (int k = 0; k < 3; ++k) ref.step(0.9);
        ob::NpyArray a = ob::readNpy(out);
        REQUIRE(a.shape == std::vector<size_t>{size_t(n), size_t(m)});
        for (int i = 0; i < n * m; ++i) REQUIRE(a.data[size_t(i)] == Approx(ref.cur[size_t(i)]).margin(1e-6));
    }
    // K = 0 writes the input unchanged.
    REQUIRE(ob::game::rippleCommand({in, "", out, 0, 0.5f}) == 0);
    REQUIRE(ob::readNpy(out).data == h);
}

TEST_CASE("ripple command: bad flags and files throw InputError with a one-line message", "[ripple][cli]") {
    const std::string in = ob::test::tempPath("in2.npy"), out = ob::test::tempPath("out2.npy");
    const std::vector<float> h(12, 1.0f);
    ob::writeNpy(in, {3, 4}, h.data());
    const std::string vec = ob::test::tempPath("vec.npy"), other = ob::test::tempPath("other.npy");
    ob::writeNpy(vec, {12}, h.data());
    ob::writeNpy(other, {4, 3}, h.data());
    using Catch::Contains;
    using ob::game::rippleCommand;
    REQUIRE_THROWS_WITH(rippleCommand({in, "", out, 1, 1.5f}), Contains("--damping 1.5") && Contains("[0, 1]"));
    REQUIRE_THROWS_WITH(rippleCommand({in, "", out, 1, -0.1f}), Contains("--damping"));
    REQUIRE_THROWS_WITH(rippleCommand({in, "", out, 1, std::nanf("")}), Contains("--damping"));
    REQUIRE_THROWS_WITH(rippleCommand({in, "", out, -1, 0.5f}), Contains("--steps -1"));
    REQUIRE_THROWS_WITH(rippleCommand({in + ".missing", "", out, 1, 0.5f}), Contains(in + ".missing"));
    REQUIRE_THROWS_WITH(rippleCommand({vec, "", out, 1, 0.5f}), Contains(vec) && Contains("2-D"));
    REQUIRE_THROWS_WITH(rippleCommand({in, other, out, 1, 0.5f}), Contains(other) && Contains("(4, 3)"));
    REQUIRE_THROWS_AS(rippleCommand({in, "", out, 1, 1.5f}), ob::InputError);
    REQUIRE_THROWS_AS(rippleCommand({in, other, out, 1, 0.5f}), ob::InputError);
    try {
        rippleCommand({in, "", out, 1, 2.0f});
    } catch (const ob::InputError& e) {
        REQUIRE(std::string(e.what()).find('\n') == std::string::npos);
    }
}

TEST_CASE("ripple command: a 2x2 field is all border and comes out 0", "[ripple][cli]") {
    const std::string in = ob::test::tempPath("in22.npy"), out = ob::test::tempPath("out22.npy");
    const float h[4] = {1, 2, 3, 4};
    ob::writeNpy(in, {2, 2}, h);
    REQUIRE(ob::game::rippleCommand({in, "", out, 1, 1.0f}) == 0);
    REQUIRE(ob::readNpy(out).data == std::vector<float>(4, 0.0f));
}

TEST_CASE("a copied ripple field owns its levels: stepping the copy leaves the original as it was", "[ripple]") {
    ob::interaction::RippleField a(16, 16);
    a.current()[8 * 16 + 8] = 1.0f;
    a.step(1.0f);  // the level pointers now sit swapped in the storage
    ob::interaction::RippleField b = a;
    std::vector<float> before(a.current().begin(), a.current().end());
    b.step(1.0f);
    b.step(1.0f);
    CHECK(std::equal(before.begin(), before.end(), a.current().begin()));
    CHECK(!std::equal(before.begin(), before.end(), b.current().begin()));
    ob::interaction::RippleField c(4, 4);
    c = a;
    CHECK(std::equal(before.begin(), before.end(), c.current().begin()));
}
