// Bounding spheres, [Kang2008] eq. 3–7 and Table 2 (docs/references.md#ripple-layer): footprints by hand, AF by
// hand, the stamp/no-stamp decisions, and the remembered base height.
#include "interaction/kang2008/ripple_field.h"
#include "interaction/kang2008/footprint_stamp.h"
#include "interaction/sphere_stamp.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace ob::interaction;

namespace {

// Fills the interior of both levels with `v`, leaving the ring at 0.
void fillInterior(RippleField& f, float cur, float prev) {
    for (int z = 1; z < f.rows() - 1; ++z)
        for (int x = 1; x < f.cols() - 1; ++x) {
            f.current()[size_t(z * f.cols() + x)] = cur;
            f.previous()[size_t(z * f.cols() + x)] = prev;
        }
}

float prevAt(const RippleField& f, int x, int z) { return f.previous()[size_t(z * f.cols() + x)]; }

} // namespace

TEST_CASE("eq. 3-4: the SR = 2 footprint is the 9 cells with PR < 2 and PH = sqrt(4 - PR^2)", "[stamp]") {
    const FootprintProfile fp = makeFootprint(2.0f);
    // By hand: PR = 0 → PH = 2; PR = 1 (4 edge cells) → √3; PR = √2 (4 diagonals) → √2;
    // PR = 2 at (±2, 0), (0, ±2) is not < SR, so those cells are out.
    REQUIRE(fp.rows.size() == 3);
    for (int r = 0; r < 3; ++r) {
        CHECK(fp.rows[size_t(r)].dz == r - 1);
        CHECK(fp.rows[size_t(r)].dx0 == -1);
        CHECK(fp.rows[size_t(r)].count == 3);
        CHECK(fp.rows[size_t(r)].offset == 3 * r);
    }
    const float s2 = std::sqrt(2.0f), s3 = std::sqrt(3.0f);
    const std::vector<float> hand{s2, s3, s2, s3, 2.0f, s3, s2, s3, s2};
    REQUIRE(fp.ph.size() == 9);
    for (size_t i = 0; i < 9; ++i) CHECK(fp.ph[i] == Approx(hand[i]).epsilon(1e-6));
}

TEST_CASE("eq. 3-4: SR = 2.5 covers the 21 cells with dx^2 + dz^2 < 6.25", "[stamp]") {
    // Rows by hand: dz = 0 → |dx| <= 2 (5 cells); dz = ±1 → dx² < 5.25 → 5 each; dz = ±2 →
    // dx² < 2.25 → 3 each. Total 21.
    const FootprintProfile fp = makeFootprint(2.5f);
    REQUIRE(fp.rows.size() == 5);
    const int counts[5] = {3, 5, 5, 5, 3};
    for (int r = 0; r < 5; ++r) CHECK(fp.rows[size_t(r)].count == counts[r]);
    REQUIRE(fp.ph.size() == 21);
    CHECK(fp.ph[0] == Approx(std::sqrt(6.25 - 5.0)));  // (dx, dz) = (−1, −2)
    CHECK(fp.ph[3 + 5 + 2] == Approx(2.5));             // centre
    CHECK(makeFootprint(1.0f).ph.size() == 1);
    CHECK(makeFootprint(0.0f).ph.empty());
}

TEST_CASE("eq. 5: stamping SR = 2 writes base + PH*SD*SHR*cell size on exactly the footprint", "[stamp]") {
    // Base 0.1 m, SD = −1, SHR = 1.5, cell 0.25 m: Vh = 0.1 − 0.375·PH, i.e. centre
    // 0.1 − 0.75 = −0.65, edge cells 0.1 − 0.375·√3, diagonals 0.1 − 0.375·√2.
    RippleField f(9, 9);
    fillInterior(f, 7.0f, 3.0f);
    const FootprintProfile fp = makeFootprint(2.0f);
    stampFootprint(f, fp, 4, 4, 0.1f, -1.0f * 1.5f * 0.25f, 0.0f);
    for (int z = 0; z < 9; ++z)
        for (int x = 0; x < 9; ++x) {
            const int dx = x - 4, dz = z - 4, pr2 = dx * dx + dz * dz;
            const bool ring = x == 0 || z == 0 || x == 8 || z == 8;
            float expect = ring ? 0.0f : 7.0f;
            if (pr2 < 4) expect = float(0.1 - 0.375 * std::sqrt(4.0 - pr2));
            INFO("x=" << x << " z=" << z);
            CHECK(f.currentAt(x, z) == Approx(expect).epsilon(1e-6));
        }
    CHECK(f.currentAt(4, 4) == Approx(-0.65f));
}

TEST_CASE("eq. 6: O = (2, 3, 1) against B = (1, 1, 1) gives AF = 5", "[stamp]") {
    // (2·3/1) / (1·1/1) − 1 = 5
    CHECK(accelerationFactor(2, 3, 1, 1, 1, 1) == Approx(5.0f));
    // Same object as the reference: 0. Twice the size, same weight and speed: 0.5 − 1 = −0.5.
    CHECK(accelerationFactor(4, 2, 3, 4, 2, 3) == Approx(0.0f).margin(1e-7));
    CHECK(accelerationFactor(1, 1, 2, 1, 1, 1) == Approx(-0.5f));
    // B = (10 kg, 5 m/s, 0.5 m): (2·10/0.25)/(10·5/0.5) − 1 = 80/100 − 1 = −0.2
    CHECK(accelerationFactor(2, 10, 0.25f, 10, 5, 0.5f) == Approx(-0.2f));
}

TEST_CASE("eq. 7: over the footprint Vh(t-1) becomes Vh(t) - Vh(t)*AF, elsewhere it is untouched", "[stamp]") {
    RippleField f(11, 11);
    fillInterior(f, 0.0f, 0.5f);
    const FootprintProfile fp = makeFootprint(3.0f);
    const float af = 0.3f;
    stampFootprint(f, fp, 5, 5, -0.2f, 0.1f, af);
    int touched = 0;
    for (int z = 1; z < 10; ++z)
        for (int x = 1; x < 10; ++x) {
            const int pr2 = (x - 5) * (x - 5) + (z - 5) * (z - 5);
            if (pr2 < 9) {
                ++touched;
                const float v = f.currentAt(x, z);
                CHECK(v == Approx(-0.2 + 0.1 * std::sqrt(9.0 - pr2)).epsilon(1e-6));
                CHECK(prevAt(f, x, z) == Approx(v * 0.7f).epsilon(1e-6));
            } else {
                CHECK(prevAt(f, x, z) == 0.5f);
            }
        }
    // SR = 3: rows dz = 0, ±1, ±2 all have |dx| <= 2 (dx² + dz² <= 8 < 9), dz = ±3 none: 25.
    CHECK(touched == 25);
}

TEST_CASE("stamping clips at the field edge and never writes the outer ring", "[stamp]") {
    RippleField f(10, 12);
    fillInterior(f, 5.0f, 5.0f);
    const FootprintProfile fp = makeFootprint(3.0f);
    stampFootprint(f, fp, 1, 0, 1.0f, 1.0f, 0.0f);    // centre on the ring
    stampFootprint(f, fp, 13, 11, 1.0f, 1.0f, 0.0f);  // centre outside, footprint overlaps a corner
    stampFootprint(f, fp, 100, 100, 1.0f, 1.0f, 0.0f);
    for (int z = 0; z < 10; ++z)
        for (int x = 0; x < 12; ++x) {
            const bool ring = x == 0 || z == 0 || x == 11 || z == 9;
            const int a2 = (x - 1) * (x - 1) + z * z, b2 = (x - 13) * (x - 13) + (z - 11) * (z - 11);
            float expect = ring ? 0.0f : 5.0f;
            if (!ring && a2 < 9) expect = float(1.0 + std::sqrt(9.0 - a2));
            if (!ring && b2 < 9) expect = float(1.0 + std::sqrt(9.0 - b2));
            INFO("x=" << x << " z=" << z);
            CHECK(f.currentAt(x, z) == Approx(expect).epsilon(1e-6));
        }
}

TEST_CASE("footprint cache builds one profile per distinct SR and reuses it", "[stamp]") {
    FootprintCache cache;
    const FootprintProfile& a = cache.get(5.0f);
    const FootprintProfile& b = cache.get(5.0f);
    const FootprintProfile& c = cache.get(7.0f);
    CHECK(&a == &b);
    CHECK(&a != &c);
    CHECK(cache.size() == 2);
    CHECK(&cache.get(5.0f) == &a);  // still valid after another insert
    CHECK(a.radiusCells == 5.0f);
}

TEST_CASE("Table 2: first contact stores fixHeight and the centre's ripple as eq. 5's base", "[stamp][table2]") {
    SphereContact c;
    // Entirely above the water (bottom 0.6 > 0.3): airborne, no stamp.
    CHECK_FALSE(updateContact(c, 1.0f, 0.4f, 0.3f, 0.05f));
    CHECK(c.phase == ContactPhase::Airborne);
    // Touching (bottom 0.1 <= 0.3 <= top 0.9): first contact, stamp.
    CHECK(updateContact(c, 0.5f, 0.4f, 0.3f, 0.05f));
    CHECK(c.inContact());
    CHECK(c.fixHeight == 0.3f);
    CHECK(c.baseRipple == 0.05f);
    // Still crossing, the live surface and ripple have moved: the stored values stay.
    CHECK(updateContact(c, 0.4f, 0.4f, 0.6f, -0.2f));
    CHECK(c.fixHeight == 0.3f);
    CHECK(c.baseRipple == 0.05f);
}

TEST_CASE("Table 2: a sphere entirely below fixHeight does not stamp, one crossing it does", "[stamp][table2]") {
    SphereContact c;
    REQUIRE(updateContact(c, 0.0f, 0.5f, 0.0f, 0.0f));  // first contact at the surface, fixHeight 0
    // Crossing fixHeight = 0 (bottom −0.9, top 0.1), even with the live surface above the top.
    CHECK(updateContact(c, -0.4f, 0.5f, 0.3f, 0.0f));
    // Entirely below fixHeight (top −0.1 < 0): no stamp, still in contact.
    CHECK_FALSE(updateContact(c, -0.6f, 0.5f, 0.0f, 0.0f));
    CHECK(c.inContact());
    // Comes back up across fixHeight: stamps again against the same fixHeight.
    CHECK(updateContact(c, -0.3f, 0.5f, -0.5f, 0.0f));
    CHECK(c.fixHeight == 0.0f);
    // Deep (top −1.1 < fixHeight − 2·radius = −1): released; no stamp.
    CHECK_FALSE(updateContact(c, -1.6f, 0.5f, 0.0f, 0.0f));
    CHECK(c.phase == ContactPhase::Free);
    // Rising again from deep water: no stamp until it touches, then a fresh fixHeight.
    CHECK_FALSE(updateContact(c, -0.8f, 0.5f, 0.2f, 0.0f));
    CHECK(updateContact(c, -0.2f, 0.5f, 0.25f, 0.07f));
    CHECK(c.fixHeight == 0.25f);
    CHECK(c.baseRipple == 0.07f);
}

TEST_CASE("Table 2: leaving the water resets contact, the next touch stores a new fixHeight", "[stamp][table2]") {
    SphereContact c;
    REQUIRE(updateContact(c, 0.0f, 0.5f, 0.0f, 0.0f));
    // Bottom 0.1 above fixHeight 0 but the raised live surface (0.2) still reaches it: no
    // stamp, still in contact.
    CHECK_FALSE(updateContact(c, 0.6f, 0.5f, 0.2f, 0.0f));
    CHECK(c.inContact());
    // Bottom 0.5 above both: out of the water.
    CHECK_FALSE(updateContact(c, 1.0f, 0.5f, 0.2f, 0.0f));
    CHECK(c.phase == ContactPhase::Airborne);
    CHECK(updateContact(c, 0.6f, 0.5f, 0.4f, 0.1f));
    CHECK(c.fixHeight == 0.4f);
    CHECK(c.baseRipple == 0.1f);
}

TEST_CASE("Table 2: a sphere that passes through the surface within one step stamps once", "[stamp][table2]") {
    SphereContact c;
    CHECK_FALSE(updateContact(c, 2.0f, 0.2f, 0.0f, 0.0f));  // airborne
    CHECK(updateContact(c, -1.0f, 0.2f, 0.0f, 0.0f));       // now entirely under: crossed in between
    CHECK(c.fixHeight == 0.0f);
    CHECK_FALSE(updateContact(c, -1.5f, 0.2f, 0.0f, 0.0f));  // entirely below fixHeight
    // A sphere that starts under water and never touches does not stamp.
    SphereContact d;
    CHECK_FALSE(updateContact(d, -3.0f, 0.2f, 0.0f, 0.0f));
    CHECK(d.phase == ContactPhase::Free);
}

TEST_CASE("a sphere resting on the water for 10 steps rewrites the same hole each step, it does not dig", "[stamp][table2]") {
    // Cannonball-like sphere (radius 0.5 m, cell 0.1 m → SR 5, SHR 1, SD −1, AF 0) resting
    // with its centre at the still water level 0; the surface it sees is the live ripple.
    RippleField f(41, 41);
    FootprintCache cache;
    BoundingSphere def;
    def.radius = 0.5f;
    def.direction = SphereDirection::Down;
    SphereContact contact;
    std::vector<float> centre;
    for (int k = 0; k < 10; ++k) {
        SphereMotion m;
        m.gridX = 20.2f;  // snaps to cell 20
        m.gridZ = 19.6f;  // snaps to cell 20
        m.centreY = 0.0f;
        m.surfaceY = f.currentAt(20, 20);
        REQUIRE(stepSphere(f, cache, 0.1f, def, contact, m));
        centre.push_back(f.currentAt(20, 20));
        CHECK(f.currentAt(23, 20) == Approx(-0.1 * std::sqrt(25.0 - 9.0)));  // PR = 3: −0.1·4
        f.step(0.95f);
    }
    // Base = ripple at first contact (0) + PH(0)·SD·SHR·Δ = −5·0.1: the same bits every step.
    for (float v : centre) CHECK(v == centre[0]);
    CHECK(centre[0] == Approx(-0.5f));
    CHECK(contact.baseRipple == 0.0f);
    CHECK(cache.size() == 1);
}

TEST_CASE("SD auto: a rising sphere pulls the water up, a falling one pushes it down", "[stamp]") {
    BoundingSphere def;
    def.radius = 0.3f;  // SR 3 at 0.1 m cells
    def.heightRatio = 1.4f;
    for (float vy : {2.0f, -2.0f}) {
        RippleField f(21, 21);
        FootprintCache cache;
        SphereContact contact;
        SphereMotion m;
        m.gridX = 10.0f;
        m.gridZ = 10.0f;
        m.verticalVelocity = vy;
        REQUIRE(stepSphere(f, cache, 0.1f, def, contact, m));
        // PH(0) = 3 cells → ±3·1.4·0.1 = ±0.42 m
        CHECK(f.currentAt(10, 10) == Approx(vy > 0 ? 0.42f : -0.42f));
    }
}

TEST_CASE("eq. 6-7 through stepSphere: AF from mass and speed rewrites Vh(t-1) on the footprint", "[stamp]") {
    // O = (2 kg, 3 m/s, 0.2 m) against B = (1 kg, 1 m/s, 0.1 m): (6/0.2)/(1/0.1) − 1 = 2.
    BoundingSphere def;
    def.radius = 0.2f;
    def.direction = SphereDirection::Down;
    def.afFromMotion = true;
    def.reference = {1.0f, 1.0f, 0.1f};
    RippleField f(15, 15);
    FootprintCache cache;
    SphereContact contact;
    SphereMotion m;
    m.gridX = 7.0f;
    m.gridZ = 7.0f;
    m.mass = 2.0f;
    m.speed = 3.0f;
    REQUIRE(stepSphere(f, cache, 0.1f, def, contact, m));
    const float v = f.currentAt(7, 7);
    CHECK(v == Approx(-0.2f));
    CHECK(prevAt(f, 7, 7) == Approx(v * (1.0f - 2.0f)));
}
