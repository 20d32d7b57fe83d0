// Batched stamping ([Kang2008] eq. 5, 7, Table 2; docs/references.md#ripple-layer): applying a list of stamps once,
// in row bands on any number of workers, leaves the field bit for bit as stampFootprint for
// each stamp in order; reads between pushes see what the sequential stamps would have written.
#include "core/parallel.h"
#include "sim/fish_swarm.h"
#include "interaction/kang2008/ripple_field.h"
#include "interaction/sphere_stamp.h"
#include "interaction/kang2008/stamp_batch.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

using namespace ob::interaction;

namespace {

struct StampArgs {
    float radiusCells;
    int cx, cz;
    float base, heightScale, af;
};

// Overlapping stamps of mixed SR, some centred off the field or on its ring, so footprints
// clip on every side.
std::vector<StampArgs> randomStamps(int count, int rows, int cols, uint32_t seed) {
    std::mt19937 rng(seed);
    const float radii[] = {0.5f, 1.0f, 2.5f, 3.0f, 7.0f, 12.3f, 20.0f};
    std::uniform_int_distribution<int> pick(0, int(std::size(radii)) - 1);
    std::uniform_int_distribution<int> x(-15, cols + 15), z(-15, rows + 15);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<StampArgs> out;
    for (int i = 0; i < count; ++i) out.push_back({radii[pick(rng)], x(rng), z(rng), u(rng), u(rng), 0.5f * u(rng)});
    return out;
}

void fillRandom(RippleField& f, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-0.3f, 0.3f);
    for (int z = 1; z < f.rows() - 1; ++z)
        for (int x = 1; x < f.cols() - 1; ++x) {
            f.current()[size_t(z * f.cols() + x)] = u(rng);
            f.previous()[size_t(z * f.cols() + x)] = u(rng);
        }
}

bool sameBits(const RippleField& a, const RippleField& b) {
    return std::memcmp(a.current().data(), b.current().data(), a.current().size_bytes()) == 0 &&
           std::memcmp(a.previous().data(), b.previous().data(), a.previous().size_bytes()) == 0;
}

} // namespace

TEST_CASE("a batch of overlapping stamps equals stampFootprint in list order, bit for bit, on 1, 2 and 3 workers",
          "[stamp][batch]") {
    // 300 × 263: not a multiple of 64 columns (partial coverage words), and enough work that
    // the interior splits into row bands.
    for (int count : {1, 7, 400, 6000}) {  // 400: light overlap (forward), 6000: heavy (backward walk)
        const auto stamps = randomStamps(count, 300, 263, uint32_t(count));
        FootprintCache cache;
        RippleField reference(300, 263);
        fillRandom(reference, 5);
        for (const StampArgs& s : stamps)
            stampFootprint(reference, cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
        for (int workers : {1, 2, 3}) {
            ob::setWorkerCount(workers);
            RippleField batched(300, 263);
            fillRandom(batched, 5);
            StampBatch batch(300, 263);
            for (const StampArgs& s : stamps)
                batch.push(cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
            batch.apply(batched);
            INFO(count << " stamps, " << workers << " workers");
            CHECK(sameBits(reference, batched));
            CHECK(batch.size() == 0);
        }
    }
    ob::setWorkerCount(0);
}

TEST_CASE("a crowd that leaves cells unreached (the walk's reach masks) still equals the sequential stamps",
          "[stamp][batch]") {
    // 8000 stamps of SR 3, 7 and 12.3 centred on a lattice of spacing 10 in the middle of a
    // 300 × 260 field: the cells near the edges and, for the small footprints, between the
    // lattice points are never reached, so the backward walk stalls and closes them from the
    // centres' dilation.
    std::mt19937 rng(9);
    std::uniform_int_distribution<int> x(6, 20), z(6, 24), pick(0, 2);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float radii[] = {3.0f, 7.0f, 12.3f};
    FootprintCache cache;
    RippleField reference(300, 260);
    fillRandom(reference, 4);
    std::vector<StampArgs> stamps;
    for (int i = 0; i < 8000; ++i) {
        stamps.push_back({radii[pick(rng)], 10 * x(rng), 10 * z(rng), u(rng), u(rng), u(rng)});
        const StampArgs& s = stamps.back();
        stampFootprint(reference, cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
    }
    for (int workers : {1, 2}) {
        ob::setWorkerCount(workers);
        RippleField batched(300, 260);
        fillRandom(batched, 4);
        StampBatch batch(300, 260);
        for (const StampArgs& s : stamps) batch.push(cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
        batch.apply(batched);
        INFO(workers << " workers");
        CHECK(sameBits(reference, batched));
    }
    ob::setWorkerCount(0);
}

TEST_CASE("reads between pushes see exactly what the stamps so far would have written", "[stamp][batch]") {
    // 300 stamps over 150 × 200 cells: a read often finds no cover among the newest stamps and
    // goes through the index of older ones.
    const int rows = 150, cols = 200;
    const auto stamps = randomStamps(300, rows, cols, 11);
    FootprintCache cache;
    RippleField sequential(rows, cols), pending(rows, cols);
    fillRandom(sequential, 3);
    fillRandom(pending, 3);
    StampBatch batch(rows, cols);
    std::mt19937 rng(2);
    std::uniform_int_distribution<int> x(0, cols - 1), z(0, rows - 1);
    int mismatches = 0;
    for (const StampArgs& s : stamps) {
        stampFootprint(sequential, cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
        batch.push(cache.get(s.radiusCells), s.cx, s.cz, s.base, s.heightScale, s.af);
        for (int k = 0; k < 50; ++k) {
            const int px = x(rng), pz = z(rng);
            const float want = sequential.currentAt(px, pz), got = batch.currentAt(pending, px, pz);
            mismatches += std::memcmp(&want, &got, sizeof want) != 0;
        }
    }
    CHECK(mismatches == 0);
    batch.apply(pending);
    CHECK(sameBits(sequential, pending));
}

TEST_CASE("queueSphere then apply gives stepSphere's field and contacts over 120 steps of a random swarm",
          "[stamp][batch][table2]") {
    // Spheres of SR 3–9 cells bobbing through a surface at y = 0 with random phases, so first
    // contacts happen under earlier stamps of the same step.
    const int n = 64, count = 300;
    const float cell = 0.1f;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-4.0f, float(n) + 4.0f), ph(0.0f, 6.28f), rad(0.3f, 0.9f);
    std::vector<BoundingSphere> defs(count);
    std::vector<float> gx(count), gz(count), phase(count);
    for (int i = 0; i < count; ++i) {
        defs[size_t(i)].radius = rad(rng);
        defs[size_t(i)].heightRatio = 1.4f;
        defs[size_t(i)].accelerationFactor = -0.3f;
        gx[size_t(i)] = pos(rng);
        gz[size_t(i)] = pos(rng);
        phase[size_t(i)] = ph(rng);
    }
    RippleField a(n, n), b(n, n);
    FootprintCache cacheA, cacheB;
    StampBatch batch(n, n);
    std::vector<SphereContact> ca(count), cb(count);
    int stamped = 0;
    for (int step = 0; step < 120; ++step) {
        for (int i = 0; i < count; ++i) {
            SphereMotion m;
            m.gridX = gx[size_t(i)] + 0.05f * float(step);
            m.gridZ = gz[size_t(i)];
            const float w = 0.2f * float(step) + phase[size_t(i)];
            m.centreY = 1.5f * std::sin(w);
            m.verticalVelocity = std::cos(w);
            const int cx = int(std::floor(m.gridX + 0.5f)), cz = int(std::floor(m.gridZ + 0.5f));
            m.surfaceY = cx >= 0 && cx < n && cz >= 0 && cz < n ? 0.1f * a.currentAt(cx, cz) : 0.0f;
            const bool sa = stepSphere(a, cacheA, cell, defs[size_t(i)], ca[size_t(i)], m);
            const bool sb = queueSphere(batch, b, cacheB, cell, defs[size_t(i)], cb[size_t(i)], m);
            REQUIRE(sa == sb);
            stamped += sa;
        }
        batch.apply(b);
        a.step(0.95f);
        b.step(0.95f);
        REQUIRE(sameBits(a, b));
        for (int i = 0; i < count; ++i) {
            REQUIRE(ca[size_t(i)].phase == cb[size_t(i)].phase);
            REQUIRE(ca[size_t(i)].fixHeight == cb[size_t(i)].fixHeight);
            REQUIRE(ca[size_t(i)].baseRipple == cb[size_t(i)].baseRipple);
        }
    }
    CHECK(stamped > 1000);
}

TEST_CASE("the Table 5 fish swarm batched on two workers matches the sequential reference bit for bit",
          "[stamp][batch][swarm]") {
    // A random overlapping swarm: 3000 fish of SR 20 over 128² cells, as the bench runs it,
    // 60 steps (a quarter of a jump period: fish rise, fall and enter the water).
    ob::game::FishSwarmDef def;
    def.count = 3000;
    def.seed = 3;
    ob::setWorkerCount(2);
    def.mode = ob::game::StampMode::Sequential;
    ob::game::FishSwarm reference(def);
    def.mode = ob::game::StampMode::Batched;
    ob::game::FishSwarm batched(def);
    int stamps = 0;
    for (int step = 0; step < 60; ++step) {
        reference.step();
        batched.step();
        REQUIRE(reference.lastStamps() == batched.lastStamps());
        stamps += batched.lastStamps();
        REQUIRE(sameBits(reference.field(), batched.field()));
    }
    for (size_t i = 0; i < reference.contacts().size(); ++i) {
        CHECK(reference.contacts()[i].baseRipple == batched.contacts()[i].baseRipple);
        CHECK(reference.contacts()[i].phase == batched.contacts()[i].phase);
    }
    CHECK(stamps > 10000);
    ob::setWorkerCount(0);
}
