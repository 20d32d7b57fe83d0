// Splash particles (engine/splash): the emission law against its formula written here, the
// crossing trigger, the landing-time bound, the flight against linear drag's closed form, the
// energy landings put into the ripple layer, bow spray's rate, the cap, and determinism.
#include "core/hash.h"
#include "core/parallel.h"
#include "interaction/kang2008/kang2008_solver.h"
#include "interaction/ripple_patch.h"
#include "splash/splash_particles.h"
#include "water/water_query.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

using namespace ob;
using splash::Crossing;
using splash::Impact;
using splash::SplashDef;
using splash::SplashParticles;

namespace {

constexpr double G = 9.81;
constexpr float DT = 1.0f / 60.0f;

// A body of mass m (kg) and radius r (m) meeting still water at y = 0 going down at v (m/s).
Impact entry(float mass, float v, float radius = 0.25f) {
    Impact i;
    i.centre = glm::vec3(0.0f, 0.0f, 0.0f);
    i.velocity = glm::vec3(0.0f, -v, 0.0f);
    i.radius = radius;
    i.mass = mass;
    return i;
}

// The stated count law, written from the header's text: N = floor(8·sqrt(½·m·v²)).
int lawCount(double mass, double v, double scale = 1.0) { return int(std::floor(scale * 8.0 * std::sqrt(0.5 * mass * v * v))); }

uint64_t hashOf(const SplashParticles& p) {
    StateHasher h;
    p.hash(h);
    return h.value();
}

} // namespace

TEST_CASE("an impact throws floor(8·sqrt(E/1 J)) drops, E = ½·m·v_n²: more energy, more drops", "[splash]") {
    SplashDef def;
    def.max_particles = 10000000;
    struct Case { float mass, v; };
    const Case cases[] = {{1.0f, 3.0f}, {1.0f, 6.0f}, {1.0f, 12.0f}, {4.0f, 6.0f}, {510.0f, 15.0f}, {510.0f, 30.0f}, {10.0f, 9.9f}};
    int previousSameMass = -1;
    for (const Case& c : cases) {
        SplashParticles p(def, 1);
        const int n = p.emitImpact(entry(c.mass, c.v));
        INFO("m " << c.mass << " kg, v " << c.v << " m/s");
        CHECK(n == lawCount(c.mass, c.v));
        CHECK(p.size() == n);
        if (c.mass == 1.0f) {
            CHECK(n > previousSameMass);  // same mass, faster: more energy, more drops
            previousSameMass = n;
        }
    }
    // Four times the energy (twice the speed, or four times the mass) doubles the count.
    SplashParticles a(def, 1), b(def, 1), c(def, 1);
    const int n1 = a.emitImpact(entry(510.0f, 15.0f));
    const int n2 = b.emitImpact(entry(510.0f, 30.0f));
    const int n3 = c.emitImpact(entry(2040.0f, 15.0f));
    CHECK(std::abs(n2 - 2 * n1) <= 2);
    CHECK(std::abs(n3 - 2 * n1) <= 2);

    // emission_scale multiplies; only the normal speed counts (a skimming body throws the
    // vertical part's drops); the surface's own motion is subtracted.
    def.emission_scale = 2.5f;
    SplashParticles s(def, 1);
    CHECK(s.emitImpact(entry(10.0f, 5.0f)) == lawCount(10.0, 5.0, 2.5));
    def.emission_scale = 1.0f;
    Impact skim = entry(10.0f, 5.0f);
    skim.velocity.x = 30.0f;
    CHECK(splash::impactDropCount(skim, def) == lawCount(10.0, 5.0));
    Impact moving = entry(10.0f, 5.0f);
    moving.surfaceVelocity = -2.0f;  // the water falls at 2 m/s: the body meets it at 3 m/s
    CHECK(splash::impactDropCount(moving, def) == lawCount(10.0, 3.0));
}

TEST_CASE("a falling ball throws no drop before contact, its crown at contact, and a body resting on the water none",
          "[splash]") {
    SplashDef def;
    water::FlatWater sea(0.0f);
    SECTION("falling ball") {
        SplashParticles p(def, 3);
        splash::SurfaceCrossing crossing;
        const float radius = 0.25f, mass = 510.0f;
        float y = 6.0f, vy = -5.0f;
        bool contact = false;
        for (int step = 0; step < 300 && !contact; ++step) {
            vy -= float(G) * DT;  // the ball's own flight (semi-implicit Euler)
            y += vy * DT;
            const Crossing c = crossing.update(y, radius, 0.0f);
            contact = y - radius <= 0.0f;
            if (!contact) {
                REQUIRE(c == Crossing::None);
                REQUIRE(p.size() == 0);
                continue;
            }
            REQUIRE(c == Crossing::Entry);
            Impact i = entry(mass, -vy, radius);
            i.centre.y = y;
            CHECK(p.emitImpact(i) == lawCount(mass, -vy));
            CHECK(p.size() > 1000);
        }
        REQUIRE(contact);
        // Under water it stays in contact: no more crossings.
        for (int step = 0; step < 60; ++step) {
            y -= 0.05f;
            CHECK(crossing.update(y, radius, 0.0f) == Crossing::None);
        }
    }
    SECTION("resting and bobbing bodies") {
        splash::SurfaceCrossing resting, bobbing;
        for (int step = 0; step < 600; ++step) {
            const float t = float(step) * DT;
            CHECK(resting.update(0.0f, 0.5f, 0.0f) == Crossing::None);            // centre on the surface
            CHECK(bobbing.update(0.2f * std::sin(2.0f * t), 0.5f, 0.0f) == Crossing::None);  // always wetted
        }
        SplashParticles p(def, 3);
        Impact still = entry(1000.0f, 0.0f, 0.5f);
        CHECK(p.emitImpact(still) == 0);
        Impact slow = entry(1000.0f, 0.9f * def.min_speed, 0.5f);  // a slow crossing: below the threshold
        CHECK(p.emitImpact(slow) == 0);
        CHECK(p.size() == 0);
    }
    SECTION("a fish leaving the water is an exit, re-entering an entry") {
        splash::SurfaceCrossing fish;
        CHECK(fish.update(-1.0f, 0.2f, 0.0f) == Crossing::None);  // first update only records
        CHECK(fish.update(-0.1f, 0.2f, 0.0f) == Crossing::None);
        CHECK(fish.update(0.3f, 0.2f, 0.0f) == Crossing::Exit);
        CHECK(fish.update(0.8f, 0.2f, 0.0f) == Crossing::None);
        CHECK(fish.update(0.1f, 0.2f, 0.0f) == Crossing::Entry);
    }
}

TEST_CASE("every drop of an impact on still water lands within T = 2·u_c/g, u_c = sqrt(2·g·R·sqrt(Fr))", "[splash]") {
    SplashDef def;
    def.max_life = 1000.0f;  // nothing may expire: every drop must land
    water::FlatWater sea(0.0f);
    for (float v : {3.0f, 10.0f, 25.0f}) {
        for (float radius : {0.1f, 0.25f, 1.0f}) {
            SplashParticles p(def, 11);
            const Impact i = entry(100.0f, v, radius);
            const int n = p.emitImpact(i);
            REQUIRE(n > 0);
            const double fr = double(v) * v / (G * radius);
            const double uc = std::sqrt(2.0 * G * radius * std::sqrt(fr));
            const double bound = 2.0 * uc / G;
            double t = 0.0;
            for (int step = 0; step < 100000 && p.size() > 0; ++step) {
                p.step(DT, sea);
                t += DT;
                for (const splash::Landing& l : p.landings()) REQUIRE(std::abs(l.position.y) < 1e-6f);
            }
            INFO("v " << v << " R " << radius << ": all landed after " << t << " s, bound " << bound << " s");
            CHECK(p.size() == 0);
            CHECK(t <= bound + DT);
            CHECK(p.stats().landed == uint64_t(n));
            CHECK(p.stats().expired == 0);
        }
    }
    // max_life removes drops that stay up (here: a sea far below).
    def.max_life = 0.5f;
    SplashParticles p(def, 11);
    const int n = p.emitImpact(entry(100.0f, 10.0f));
    water::FlatWater abyss(-1e6f);
    for (int step = 0; step < 31; ++step) p.step(DT, abyss);
    CHECK(p.size() == 0);
    CHECK(p.stats().expired == uint64_t(n));
}

TEST_CASE("drops fly the closed form of linear drag, for any step", "[splash]") {
    water::FlatWater abyss(-1e6f);  // no landing during the flight
    for (float k : {0.0f, 0.8f, 5.0f}) {
        SplashDef def;
        def.drag = k;
        for (float dt : {1.0f / 30.0f, 1.0f / 60.0f, 1.0f / 240.0f}) {
            SplashParticles p(def, 5);
            Impact i = entry(50.0f, 12.0f);
            i.velocity.x = 6.0f;  // a slanted impact: drops carry a horizontal speed
            p.emitImpact(i);
            const int n = p.size();
            REQUIRE(n > 10);
            std::vector<double> x0(p.x().begin(), p.x().end()), y0(p.y().begin(), p.y().end()),
                z0(p.z().begin(), p.z().end()), u0(p.vx().begin(), p.vx().end()), v0(p.vy().begin(), p.vy().end()),
                w0(p.vz().begin(), p.vz().end());
            const int steps = int(std::lround(1.2 / dt));
            for (int s = 0; s < steps; ++s) p.step(dt, abyss);
            const double t = double(steps) * double(dt);
            // x(t) = x0 + v0·(1 − e^(−kt))/k;  y(t) = y0 + (v0 + g/k)·(1 − e^(−kt))/k − g·t/k
            const double e = k > 0 ? (1.0 - std::exp(-double(k) * t)) / k : t;
            const double fall = k > 0 ? G / k * (t - e) : 0.5 * G * t * t;
            double worst = 0.0;
            REQUIRE(p.size() == n);
            for (int d = 0; d < n; ++d) {
                const double ex = x0[size_t(d)] + u0[size_t(d)] * e, ey = y0[size_t(d)] + v0[size_t(d)] * e - fall,
                             ez = z0[size_t(d)] + w0[size_t(d)] * e;
                const double evy = k > 0 ? v0[size_t(d)] * std::exp(-double(k) * t) - G / k * (1 - std::exp(-double(k) * t))
                                         : v0[size_t(d)] - G * t;
                worst = std::max({worst, std::abs(p.x()[size_t(d)] - ex), std::abs(p.y()[size_t(d)] - ey),
                                  std::abs(p.z()[size_t(d)] - ez), std::abs(p.vy()[size_t(d)] - evy)});
            }
            INFO("k " << k << " /s, dt " << dt << " s: worst |error| " << worst);
            CHECK(worst < 2e-4);  // float rounding over up to 288 steps; a first-order scheme errs by cm
        }
    }
}

TEST_CASE("landing drops put ε of their kinetic energy into the ripple layer", "[splash]") {
    interaction::RippleDef rd;
    rd.model = interaction::rippleModel("kang2008");  // its Vh(t) is written and read here; ewave takes the same craters into h
    rd.resolution = 64;
    rd.cell_size = 0.25f;
    rd.boundary = interaction::RippleBoundary::Fixed;
    constexpr double RHO = 1025.0;
    auto potential = [&](const interaction::RipplePatch& patch) {  // ½·ρ·g·Δ²·Σ Vh², J
        double sum = 0.0;
        for (float h : patch.height()) sum += double(h) * h;  // either model's height
        return 0.5 * RHO * G * double(rd.cell_size) * rd.cell_size * sum;
    };
    SECTION("drops in distinct cells: exactly the law") {
        interaction::RipplePatch patch(rd);
        std::vector<splash::Landing> landings;
        double kinetic = 0.0;
        for (int k = 0; k < 20; ++k) {
            splash::Landing l;
            l.position = glm::vec3(-3.0f + 0.3f * float(k), 0.0f, 1.0f);  // 0.3 m apart: one per cell
            l.velocity = glm::vec3(0.5f, -4.0f - 0.2f * float(k), 0.0f);
            l.radius = 0.003f;
            l.mass = float(RHO * 4.0 / 3.0 * M_PI * 0.003 * 0.003 * 0.003);
            kinetic += 0.5 * l.mass * double(glm::dot(l.velocity, l.velocity));
            landings.push_back(l);
        }
        const double put = splash::stampLandings(patch, landings, 0.2f);
        CHECK(put == Approx(0.2 * kinetic).epsilon(1e-6));
        CHECK(potential(patch) == Approx(0.2 * kinetic).epsilon(1e-4));
        double volume = 0.0;
        for (float h : patch.solverAs<ob::interaction::Kang2008Solver>()->field().current()) volume += h;
        CHECK(volume < 0.0);  // craters: the water goes down where drops land
        // A landing outside the patch is skipped.
        splash::Landing far = landings[0];
        far.position = glm::vec3(100.0f, 0.0f, 0.0f);
        CHECK(splash::stampLandings(patch, std::span(&far, 1), 0.2f) == 0.0);
    }
    SECTION("a splash rains back on the water") {
        interaction::RipplePatch patch(rd);
        SplashDef def;
        SplashParticles p(def, 9);
        water::FlatWater sea(0.0f);
        const int n = p.emitImpact(entry(510.0f, 15.0f));
        REQUIRE(n > 1000);
        double put = 0.0;
        size_t landed = 0;
        while (p.size() > 0) {
            p.step(DT, sea);
            landed += p.landings().size();
            put += splash::stampLandings(patch, p.landings(), def.ripple_energy);
        }
        CHECK(landed == size_t(n));
        // Drops sharing a cell add depths, so the measured energy is at least the law's sum.
        const double measured = potential(patch);
        INFO("law " << put << " J, measured " << measured << " J");
        CHECK(put > 0.0);
        CHECK(measured >= put * (1 - 1e-4));
        // With ε = 0 the drops land without a trace.
        interaction::RipplePatch quiet(rd);
        SplashParticles q(def, 9);
        q.emitImpact(entry(510.0f, 15.0f));
        while (q.size() > 0) {
            q.step(DT, sea);
            splash::stampLandings(quiet, q.landings(), 0.0f);
        }
        CHECK(potential(quiet) == 0.0);
    }
}

TEST_CASE("bow spray: none at or below bow_speed, the stated rate above it, thrown from the bow", "[splash]") {
    SplashDef def;
    SplashParticles p(def, 21);
    const glm::vec3 centre(0.0f, 0.0f, 0.0f);
    const float radius = 1.5f;
    for (int s = 0; s < 600; ++s) CHECK(p.emitBowSpray(centre, glm::vec3(def.bow_speed, 0.0f, 0.0f), radius, DT) == 0);
    CHECK(p.size() == 0);
    const float u = 8.0f;
    long total = 0;
    for (int s = 0; s < 600; ++s) total += p.emitBowSpray(centre, glm::vec3(0.0f, 0.0f, u), radius, DT);
    const double expected = 100.0 * radius * radius * (u / def.bow_speed - 1.0) * 600 * DT;  // 10 s at the stated rate
    INFO(total << " drops in 10 s, law " << expected);
    CHECK(std::abs(double(total) - expected) < 0.05 * expected);
    for (int d = 0; d < p.size(); ++d) CHECK(p.z()[size_t(d)] == Approx(radius));  // the bow: R ahead along +z
}

TEST_CASE("max_particles caps the live drops and counts the rest as dropped", "[splash]") {
    SplashDef def;
    def.max_particles = 500;
    SplashParticles p(def, 2);
    const int n = lawCount(510.0, 15.0);
    CHECK(p.emitImpact(entry(510.0f, 15.0f)) == 500);
    CHECK(p.size() == 500);
    CHECK(p.stats().dropped == uint64_t(n - 500));
}

TEST_CASE("same inputs and seed give bit-identical splash states, for any worker count", "[splash][determinism]") {
    auto run = [](uint64_t seed, int workers) {
        setWorkerCount(workers);
        SplashDef def;
        def.emission_scale = 10.0f;  // ~60,000 drops: the flight is split over the workers
        SplashParticles p(def, seed);
        water::FlatWater sea(0.0f);
        for (int s = 0; s < 150; ++s) {
            if (s % 50 == 0) p.emitImpact(entry(2000.0f, 12.0f + float(s) * 0.01f, 0.5f));
            p.emitBowSpray(glm::vec3(float(s) * 0.1f, 0.0f, 0.0f), glm::vec3(7.0f, 0.0f, 1.0f), 1.0f, DT);
            p.step(DT, sea);
        }
        setWorkerCount(0);
        return hashOf(p);
    };
    const uint64_t a = run(7, 1);
    CHECK(run(7, 1) == a);
    CHECK(run(7, 2) == a);
    CHECK(run(7, 3) == a);
    CHECK(run(8, 1) != a);
}
