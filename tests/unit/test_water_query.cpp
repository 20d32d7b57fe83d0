// WaterQuery (docs/references.md#composite-ocean): the flat stub; the composite surface inverted to world (x, z) on a
// Gerstner-only sea (against a double reference of docs/references.md#gerstner-waves), an FFT-only sea (displaced grid
// points X + λD(X) return h(X)), both together; vertical velocity against finite differences
// in time; the ripple hook; batch = single; the `dump surface` file contract.
#include "tools/cmd_dump_surface.h"
#include "core/error.h"
#include "core/npy.h"
#include "ocean/ocean_fft_cpu.h"
#include "support/test_support.h"
#include "water/composite_water.h"

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace ob;
using namespace ob::water;
using ocean::GerstnerWave;

namespace {

constexpr double PI = std::numbers::pi;
constexpr float GF = 9.81f;
constexpr double G = double(GF);

// [Min2023]'s first 8 waves (kx, kz, a, φ), docs/references.md#gerstner-waves: Σ k·a = 0.68.
const std::vector<GerstnerWave> SEED002_FIRST8 = {
    {0.3f, -0.46f, 0.2f, 0.0f},  {-0.33f, 0.40f, 0.12f, 0.0f}, {0.0f, 0.56f, 0.2f, 0.2f},
    {-0.33f, 0.0f, 0.12f, 0.3f}, {0.3f, -0.26f, 0.2f, 0.7f},   {-0.33f, 0.20f, 0.12f, 0.9f},
    {0.17f, 0.3f, 0.3f, -1.0f},  {-0.15f, -0.1f, 0.7f, 0.6f}};

struct Vec3d {
    double x, y, z;
};

// docs/references.md#gerstner-waves in double: position of rest point (α, β) at t, and its unit normal from the
// cross product of central differences (∂r/∂β × ∂r/∂α, y up).
Vec3d reference(const std::vector<GerstnerWave>& waves, double alpha, double beta, double t) {
    Vec3d r{alpha, 0.0, beta};
    for (const GerstnerWave& w : waves) {
        const double k = std::hypot(double(w.kx), double(w.kz)), a = w.amplitude;
        const double theta = w.kx * alpha + w.kz * beta - std::sqrt(G * k) * t - w.phase;
        r.x -= w.kx / k * a * std::sin(theta);
        r.z -= w.kz / k * a * std::sin(theta);
        r.y += a * std::cos(theta);
    }
    return r;
}
Vec3d referenceNormal(const std::vector<GerstnerWave>& waves, double alpha, double beta, double t) {
    const double h = 1e-5;
    const Vec3d p = reference(waves, alpha + h, beta, t), m = reference(waves, alpha - h, beta, t);
    const Vec3d q = reference(waves, alpha, beta + h, t), n = reference(waves, alpha, beta - h, t);
    const Vec3d da{p.x - m.x, p.y - m.y, p.z - m.z}, db{q.x - n.x, q.y - n.y, q.z - n.z};
    const Vec3d c{db.y * da.z - db.z * da.y, db.z * da.x - db.x * da.z, db.x * da.y - db.y * da.x};
    const double l = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
    return {c.x / l, c.y / l, c.z / l};
}

// A small, moderately choppy FFT ocean (few folds), deterministic.
ocean::OceanDef smallOcean(int cascades = 1) {
    ocean::OceanDef def;
    def.resolution = 64;
    def.patch_size = 80.0f;
    def.wind_speed = 9.0f;
    def.choppiness = 1.0f;
    def.cascades = cascades;
    def.seed = 42;
    return def;
}

float maxAbsVelocity(const std::vector<float>& v) {
    float m = 0.0f;
    for (float x : v) m = std::max(m, std::abs(x));
    return m;
}

} // namespace

TEST_CASE("FlatWater: height h0, normal straight up and no motion everywhere", "[water]") {
    const FlatWater flat(1.25f);
    for (const auto& [x, z] : {std::pair{0.0f, 0.0f}, {-1e4f, 3.5f}, {123.0f, -77.0f}}) {
        const WaterSample s = flat.sample(x, z);
        CHECK(s.height == 1.25f);
        CHECK(s.normal == glm::vec3(0, 1, 0));
        CHECK(s.verticalVelocity == 0.0f);
    }
    std::vector<glm::vec2> points{{1, 2}, {3, 4}};
    std::vector<WaterSample> out(2);
    flat.sampleBatch(points, out);
    CHECK(out[1].height == 1.25f);
}

TEST_CASE("Gerstner-only sea: sample() at the displaced position of each rest point returns that point's height and normal", "[water]") {
    const double t = 3.7;
    for (const auto inversion : {CompositeSettings::Inversion::Newton, CompositeSettings::Inversion::FixedPoint}) {
        CompositeSettings settings;
        settings.inversion = inversion;
        settings.tolerance = 1e-6f;
        settings.maxIterations = 64;
        CompositeWater water(SEED002_FIRST8, GF, nullptr, settings);
        water.update(t);
        double worstHeight = 0.0, worstAngle = 0.0;
        int worstIterations = 0;
        // A dense grid of rest points (spacing 0.7 m, ~1/10 of the shortest wavelength).
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const double alpha = -20.0 + 0.7 * i, beta = -25.0 + 0.7 * j;
                const Vec3d p = reference(SEED002_FIRST8, alpha, beta, t);
                const Vec3d n = referenceNormal(SEED002_FIRST8, alpha, beta, t);
                const WaterSample s = water.sample(float(p.x), float(p.z));
                worstHeight = std::max(worstHeight, std::abs(s.height - p.y));
                const double dot = s.normal.x * n.x + s.normal.y * n.y + s.normal.z * n.z;
                const double cx = s.normal.y * n.z - s.normal.z * n.y, cy = s.normal.z * n.x - s.normal.x * n.z,
                             cz = s.normal.x * n.y - s.normal.y * n.x;
                worstAngle = std::max(worstAngle, std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot));
                const RestPoint r = water.restPoint(float(p.x), float(p.z));
                worstIterations = std::max(worstIterations, r.iterations);
                CHECK(std::hypot(r.rest.x - alpha, r.rest.y - beta) < 1e-4);
            }
        INFO((inversion == CompositeSettings::Inversion::Newton ? "Newton" : "fixed point")
             << ": worst height error " << worstHeight << " m, worst normal angle " << worstAngle
             << " rad, worst evaluations " << worstIterations);
        CHECK(worstHeight < 5e-5);
        CHECK(worstAngle < 1e-4);
    }
}

TEST_CASE("Inversion: Newton converges to 0.1 mm in a few evaluations, fixed point contracts at ≈ ‖∂D/∂α‖ ≤ Σ k·a per step", "[water]") {
    CompositeSettings newton;
    newton.maxIterations = 64;
    CompositeSettings fixed = newton;
    fixed.inversion = CompositeSettings::Inversion::FixedPoint;
    CompositeWater a(SEED002_FIRST8, GF, nullptr, newton), b(SEED002_FIRST8, GF, nullptr, fixed);
    a.update(11.0);
    b.update(11.0);
    int newtonMax = 0, fixedMax = 0;
    double newtonMean = 0, fixedMean = 0;
    const int n = 2500;
    for (int k = 0; k < n; ++k) {
        const float x = -40.0f + 80.0f * float((k * 37) % n) / n, z = -40.0f + 80.0f * float((k * 53) % 97) / 97;
        const RestPoint ra = a.restPoint(x, z), rb = b.restPoint(x, z);
        CHECK(ra.residual <= 1e-4f);
        CHECK(rb.residual <= 1e-4f);
        newtonMax = std::max(newtonMax, ra.iterations);
        fixedMax = std::max(fixedMax, rb.iterations);
        newtonMean += double(ra.iterations) / n;
        fixedMean += double(rb.iterations) / n;
    }
    INFO("evaluations to 1e-4 m: Newton mean " << newtonMean << " max " << newtonMax << "; fixed point mean "
                                              << fixedMean << " max " << fixedMax);
    CHECK(newtonMax <= 5);
    CHECK(fixedMean > newtonMean);
    // Fixed point: each step shrinks the error by at most Σ k·a = 0.68, so from |D| ≤ Σ a
    // (≈ 2 m) to 1e-4 m takes at most log(2e4)/log(1/0.68) + 1 ≈ 27 evaluations.
    CHECK(fixedMax <= 27);
}

TEST_CASE("FFT-only sea: sample() at a displaced grid point X + λ·D(X) returns h(X) and the slope-form normal there", "[water]") {
    const ocean::OceanDef def = smallOcean();
    ocean::OceanFftCpu fft(def, 1);
    fft.update(3.0);
    CompositeSettings settings;
    settings.tolerance = 1e-6f;
    settings.maxIterations = 32;
    CompositeWater water({}, GF, &fft, settings);
    water.update(3.0);
    const int n = fft.resolution();
    const float cell = float(fft.patchSize(0)) / n, lambda = fft.lambda();
    const float* h = fft.channel(0, ocean::OceanChannel::Height);
    const float* dx = fft.channel(0, ocean::OceanChannel::DispX);
    const float* dz = fft.channel(0, ocean::OceanChannel::DispZ);
    const float* sx = fft.channel(0, ocean::OceanChannel::SlopeX);
    const float* sz = fft.channel(0, ocean::OceanChannel::SlopeZ);
    const float* jac = fft.channel(0, ocean::OceanChannel::Jacobian);
    int checked = 0, skipped = 0;
    float hMax = 0.0f;
    for (int j = 0; j < n; j += 3)
        for (int i = 0; i < n; i += 3) {
            const size_t p = size_t(j) * n + size_t(i);
            if (jac[p] < 0.3f) {  // near a fold the displaced point has other preimages
                ++skipped;
                continue;
            }
            ++checked;
            hMax = std::max(hMax, std::abs(h[p]));
            const float x = i * cell + lambda * dx[p], z = j * cell + lambda * dz[p];
            const WaterSample s = water.sample(x, z);
            INFO("grid point (" << i << ", " << j << ")");
            CHECK(s.height == Approx(h[p]).margin(2e-5));
            const float l = std::sqrt(sx[p] * sx[p] + 1 + sz[p] * sz[p]);
            CHECK(s.normal.x == Approx(-sx[p] / l).margin(1e-4));
            CHECK(s.normal.y == Approx(1 / l).margin(1e-4));
            CHECK(s.normal.z == Approx(-sz[p] / l).margin(1e-4));
            // The tile repeats with period L.
            const WaterSample w = water.sample(x + float(fft.patchSize(0)), z - float(fft.patchSize(0)));
            CHECK(w.height == Approx(s.height).margin(1e-4));
        }
    INFO(checked << " grid points checked, " << skipped << " near folds skipped, max |h| " << hMax << " m");
    CHECK(checked > 400);
    CHECK(hMax > 0.3f);  // a real sea, not a flat one
}

TEST_CASE("Composite sea (Gerstner + 2 FFT cascades): the displaced rest point's height is found again, and its rest point", "[water]") {
    const ocean::OceanDef def = smallOcean(2);
    ocean::OceanFftCpu fft(def, 1);
    fft.update(5.0);
    CompositeSettings settings;
    settings.tolerance = 1e-5f;
    settings.maxIterations = 32;
    CompositeWater water(SEED002_FIRST8, GF, &fft, settings);
    water.update(5.0);
    int checked = 0, maxIterations = 0;
    for (int k = 0; k < 400; ++k) {
        const float alpha = -60.0f + 0.31f * k, beta = 17.0f - 0.23f * k;
        const ocean::GerstnerSums g = water.gerstner().sums(alpha, beta);
        const CompositeWater::FftTerms f = water.fftTerms(alpha, beta);
        const float jxx = 1 - g.pxx + f.dxx, jxz = -g.pxz + f.dxz, jzz = 1 - g.pzz + f.dzz;
        if (jxx * jzz - jxz * jxz < 0.3f) continue;  // near a fold
        ++checked;
        const glm::vec3 p = water.displace(alpha, beta);
        CHECK(p.x == Approx(alpha + g.dx + f.dx).margin(1e-5));  // displacements add (docs/references.md#composite-ocean)
        CHECK(p.y == Approx(g.y + f.h).margin(1e-5));            // heights add
        const RestPoint r = water.restPoint(p.x, p.z);
        maxIterations = std::max(maxIterations, r.iterations);
        CHECK(std::hypot(r.rest.x - alpha, r.rest.y - beta) < 1e-3);
        CHECK(water.sample(p.x, p.z).height == Approx(p.y).margin(1e-4));
    }
    INFO(checked << " rest points, worst evaluations " << maxIterations);
    CHECK(checked > 300);
}

TEST_CASE("Vertical velocity equals ∂height/∂t at a fixed world point (finite differences in time), Gerstner, FFT and both", "[water]") {
    const ocean::OceanDef def = smallOcean();
    struct Case {
        const char* name;
        bool gerstner, fft;
    };
    for (const Case c : {Case{"Gerstner", true, false}, Case{"FFT", false, true}, Case{"both", true, true}}) {
        ocean::OceanFftCpu fft(def, 1);
        CompositeSettings settings;
        settings.tolerance = 1e-6f;
        settings.maxIterations = 32;
        const std::vector<GerstnerWave> waves = c.gerstner ? SEED002_FIRST8 : std::vector<GerstnerWave>{};
        CompositeWater water(waves, GF, c.fft ? &fft : nullptr, settings);
        const double t = 7.0, dt = 0.01;
        primeAt(c.fft ? &fft : nullptr, water, t);
        if (c.fft) CHECK(water.fftRateOrder() == 2);
        std::vector<glm::vec2> points;
        for (int k = 0; k < 60; ++k) points.push_back({-30.0f + 1.37f * k, 12.0f - 0.61f * k});
        std::vector<float> velocity, particle;
        std::vector<RestPoint> rests;
        for (const glm::vec2 p : points) {
            velocity.push_back(water.sample(p.x, p.y).verticalVelocity);
            const RestPoint r = water.restPoint(p.x, p.y);
            rests.push_back(r);
            particle.push_back(water.gerstner().sums(r.rest.x, r.rest.y).vy + water.fftTerms(r.rest.x, r.rest.y).ht);
        }
        const auto heights = [&](double time) {
            if (c.fft) fft.update(time);
            water.update(time);
            std::vector<float> h;
            for (const glm::vec2 p : points) h.push_back(water.sample(p.x, p.y).height);
            return h;
        };
        const std::vector<float> up = heights(t + dt), down = heights(t - dt);
        const float scale = maxAbsVelocity(velocity);
        double worst = 0.0, eulerianVsParticle = 0.0;
        int onEdge = 0;
        for (size_t k = 0; k < points.size(); ++k) {
            // The bilinear FFT surface has kinks on cell edges: where the rest point is about to
            // cross one within ±dt, ∂height/∂t jumps and a central difference straddles the jump.
            if (c.fft) {
                const RestPoint& r = rests[k];
                const double cell = fft.patchSize(0) / fft.resolution();
                const auto edge = [&](double a) { return std::abs(a / cell - std::round(a / cell)) * cell < 0.02; };
                if (edge(r.rest.x) || edge(r.rest.y)) {
                    ++onEdge;
                    continue;
                }
            }
            const double fd = (double(up[k]) - down[k]) / (2 * dt);
            worst = std::max(worst, std::abs(fd - velocity[k]));
            eulerianVsParticle = std::max(eulerianVsParticle, std::abs(double(particle[k]) - velocity[k]));
        }
        INFO(c.name << ": max |velocity| " << scale << " m/s, worst |v − FD| " << worst << " m/s (" << onEdge
                    << " points on cell edges skipped), max |Eulerian − particle| " << eulerianVsParticle << " m/s");
        CHECK(scale > 0.1f);
        CHECK(onEdge < 5);
        CHECK(worst < 0.01 * scale + 5e-4);
        CHECK(eulerianVsParticle > 0.05 * scale);  // the query is Eulerian, not the particle's ∂y/∂t
    }
}

TEST_CASE("Ripple hook: height, slope and rate are added at the world position, an absent slope comes from differences", "[water]") {
    CompositeWater water({}, GF);
    water.update(0.0);
    RippleHook hook;
    hook.height = [](float x, float z) { return 0.2f * std::sin(0.3f * x + 0.1f * z); };
    hook.rate = [](float, float) { return 0.7f; };
    water.setRipple(hook);
    for (const auto& [x, z] : {std::pair{0.0f, 0.0f}, {3.0f, -5.0f}, {-11.0f, 2.5f}}) {
        const WaterSample s = water.sample(x, z);
        const float c = 0.2f * std::cos(0.3f * x + 0.1f * z);
        const glm::vec3 n = glm::vec3(-0.3f * c, 1.0f, -0.1f * c) / std::sqrt(0.09f * c * c + 1.0f + 0.01f * c * c);
        CHECK(s.height == Approx(0.2f * std::sin(0.3f * x + 0.1f * z)).margin(1e-6));
        CHECK(s.verticalVelocity == Approx(0.7f).margin(1e-6));
        CHECK(s.normal.x == Approx(n.x).margin(1e-4));
        CHECK(s.normal.y == Approx(n.y).margin(1e-4));
        CHECK(s.normal.z == Approx(n.z).margin(1e-4));
    }
    hook.slope = [](float, float) { return glm::vec2(1.0f, 0.0f); };  // a given slope wins
    water.setRipple(hook);
    CHECK(water.sample(0, 0).normal.x == Approx(-1 / std::sqrt(2.0f)).margin(1e-6));
}

TEST_CASE("Layers: a query of some layers equals the sea built of those layers alone, ripples left out add nothing", "[water]") {
    // Independent references: a CompositeWater made of only the layers asked for.
    const ocean::OceanDef def = smallOcean();
    ocean::OceanFftCpu fft(def, 1);
    fft.update(3.0);
    CompositeWater all(SEED002_FIRST8, GF, &fft), gerstnerOnly(SEED002_FIRST8, GF), fftOnly({}, GF, &fft);
    RippleHook hook;
    hook.height = [](float x, float z) { return 0.3f * std::sin(0.5f * x - 0.2f * z); };
    hook.rate = [](float x, float) { return 0.4f + 0.01f * x; };
    all.setRipple(hook);
    CompositeWater noRipples(SEED002_FIRST8, GF, &fft);
    for (CompositeWater* w : {&all, &gerstnerOnly, &fftOnly, &noRipples}) w->update(3.0);
    const auto same = [](const WaterSample& a, const WaterSample& b) {
        return a.height == b.height && a.normal == b.normal && a.verticalVelocity == b.verticalVelocity;
    };
    for (int k = 0; k < 50; ++k) {
        const float x = -20.0f + 0.83f * float(k), z = 9.0f - 0.47f * float(k);
        INFO("at (" << x << ", " << z << ")");
        CHECK(same(all.sample(x, z, {.ripples = false}), noRipples.sample(x, z)));
        CHECK(same(all.sample(x, z, {.fft = false, .ripples = false}), gerstnerOnly.sample(x, z)));
        CHECK(same(all.sample(x, z, {.gerstner = false, .ripples = false}), fftOnly.sample(x, z)));
        const WaterSample flat = all.sample(x, z, {.gerstner = false, .fft = false, .ripples = false});
        CHECK((flat.height == 0.0f && flat.normal == glm::vec3(0, 1, 0) && flat.verticalVelocity == 0.0f));
        // Everything = without the ripples + the ripple layer at the world point (its height and rate).
        const WaterSample full = all.sample(x, z), ocean = all.sample(x, z, {.ripples = false});
        CHECK(full.height - ocean.height == Approx(hook.height(x, z)).margin(1e-5));
        CHECK(full.verticalVelocity - ocean.verticalVelocity == Approx(hook.rate(x, z)).margin(1e-5));
    }
}

TEST_CASE("sampleBatch equals sample() point by point (composite sea, 200 points, Exact and SlopeSum normals)", "[water]") {
    const ocean::OceanDef def = smallOcean(2);
    ocean::OceanFftCpu fft(def, 1);
    for (const auto normal : {CompositeSettings::Normal::SlopeSum, CompositeSettings::Normal::Exact}) {
        CompositeSettings settings;
        settings.normal = normal;
        CompositeWater water(SEED002_FIRST8, GF, &fft, settings);
        primeAt(&fft, water, 2.0);
        std::vector<glm::vec2> points;
        for (int k = 0; k < 200; ++k) points.push_back({-70.0f + 0.77f * k, 40.0f - 0.41f * k});
        std::vector<WaterSample> batch(points.size());
        water.sampleBatch(points, batch);
        for (size_t k = 0; k < points.size(); ++k) {
            const WaterSample s = water.sample(points[k].x, points[k].y);
            INFO("point " << k);
            CHECK(batch[k].height == Approx(s.height).margin(2e-5));
            CHECK(batch[k].normal.x == Approx(s.normal.x).margin(2e-5));
            CHECK(batch[k].normal.z == Approx(s.normal.z).margin(2e-5));
            CHECK(batch[k].verticalVelocity == Approx(s.verticalVelocity).margin(2e-5));
        }
    }
}

TEST_CASE("Exact and slope-sum normals agree on a Gerstner-only sea (its slope is −n.xz/n.y of the analytic normal)", "[water]") {
    CompositeSettings exact;
    exact.normal = CompositeSettings::Normal::Exact;
    CompositeWater a(SEED002_FIRST8, GF), b(SEED002_FIRST8, GF, nullptr, exact);
    a.update(1.0);
    b.update(1.0);
    for (int k = 0; k < 50; ++k) {
        const float x = -20.0f + 0.9f * k, z = 5.0f - 0.3f * k;
        CHECK(a.sample(x, z).normal.x == Approx(b.sample(x, z).normal.x).margin(1e-5));
        CHECK(a.sample(x, z).normal.z == Approx(b.sample(x, z).normal.z).margin(1e-5));
    }
}

TEST_CASE("dump surface: [K, 2] world points in, [K, 5] = (height, nx, ny, nz, vertical velocity) out, bad shapes are InputErrors", "[water]") {
    const ocean::OceanDef def = smallOcean();
    ocean::OceanFftCpu fft(def, 1);
    CompositeWater water(SEED002_FIRST8, GF, &fft);
    primeAt(&fft, water, 4.0);
    std::vector<float> xz;
    for (int k = 0; k < 33; ++k) {
        xz.push_back(-10.0f + 0.9f * k);
        xz.push_back(3.0f * std::sin(float(k)));
    }
    const std::string pointsPath = test::tempPath("points.npy"), outPath = test::tempPath("surface.npy");
    writeNpy(pointsPath, {33, 2}, xz.data());
    REQUIRE(game::dumpSurface(water, pointsPath, outPath) == 0);
    const NpyArray out = readNpy(outPath);
    REQUIRE(out.shape == std::vector<size_t>{33, 5});
    for (size_t k = 0; k < 33; ++k) {
        const WaterSample s = water.sample(xz[2 * k], xz[2 * k + 1]);
        CHECK(out.data[5 * k + 0] == Approx(s.height).margin(2e-5));
        CHECK(out.data[5 * k + 1] == Approx(s.normal.x).margin(2e-5));
        CHECK(out.data[5 * k + 2] == Approx(s.normal.y).margin(2e-5));
        CHECK(out.data[5 * k + 3] == Approx(s.normal.z).margin(2e-5));
        CHECK(out.data[5 * k + 4] == Approx(s.verticalVelocity).margin(2e-5));
    }
    const auto message = [&](const std::string& path) -> std::string {
        try {
            game::dumpSurface(water, path, outPath);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    const std::string bad = test::tempPath("bad_points.npy");
    writeNpy(bad, {3, 3}, std::vector<float>(9, 0.0f).data());
    CHECK(message(bad).find("bad_points.npy: expected float32 points of shape [K, 2]") != std::string::npos);
    CHECK(message(bad).find("got shape [3, 3]") != std::string::npos);
    writeNpy(bad, {4}, std::vector<float>(4, 0.0f).data());
    CHECK(message(bad).find("got shape [4]") != std::string::npos);
    const float nan[2] = {std::nanf(""), 0.0f};
    writeNpy(bad, {1, 2}, nan);
    CHECK(message(bad).find("point 0 is not a finite") != std::string::npos);
    CHECK(message(test::tempPath("missing.npy")) != "");
    // An empty point list is a valid [0, 2] array: the answer is [0, 5].
    writeNpy(pointsPath, {0, 2}, nullptr);
    REQUIRE(game::dumpSurface(water, pointsPath, outPath) == 0);
    CHECK(readNpy(outPath).shape == std::vector<size_t>{0, 5});
}

TEST_CASE("Horizontal velocity is the particle's ∂(x, z)/∂t: differences in time of its displaced position, Gerstner (closed form too), FFT and both", "[water][foam]") {
    const ocean::OceanDef def = smallOcean();
    struct Case {
        const char* name;
        bool gerstner, fft;
    };
    for (const Case c : {Case{"Gerstner", true, false}, Case{"FFT", false, true}, Case{"both", true, true}}) {
        ocean::OceanFftCpu fft(def, 1);
        CompositeSettings settings;
        settings.tolerance = 1e-6f;
        settings.maxIterations = 32;
        const std::vector<GerstnerWave> waves = c.gerstner ? SEED002_FIRST8 : std::vector<GerstnerWave>{};
        CompositeWater water(waves, GF, c.fft ? &fft : nullptr, settings);
        const double t = 7.0, dt = 0.01;
        primeAt(c.fft ? &fft : nullptr, water, t);
        std::vector<glm::vec2> points;
        for (int k = 0; k < 60; ++k) points.push_back({-30.0f + 1.37f * k, 12.0f - 0.61f * k});
        std::vector<glm::vec2> velocity(points.size());
        water.horizontalVelocityBatch(points, velocity);
        std::vector<glm::vec2> rests;
        double closedForm = 0.0;
        for (size_t k = 0; k < points.size(); ++k) {
            rests.push_back(water.restPoint(points[k].x, points[k].y).rest);
            if (!c.fft) {  // Σ K̂·a·ω·cos θ at the rest point (docs/references.md#gerstner-waves differentiated in t)
                glm::dvec2 v(0.0);
                for (const GerstnerWave& w : waves) {
                    const double kk = std::hypot(double(w.kx), double(w.kz)), omega = std::sqrt(G * kk);
                    const double theta = w.kx * rests[k].x + w.kz * rests[k].y - omega * t - w.phase;
                    v += glm::dvec2(w.kx, w.kz) / kk * double(w.amplitude) * omega * std::cos(theta);
                }
                closedForm = std::max(closedForm, glm::length(v - glm::dvec2(velocity[k])));
            }
        }
        // The particle at each rest point, a little before and after: its displaced (x, z).
        const auto positions = [&](double time) {
            if (c.fft) fft.update(time);
            water.update(time);
            std::vector<glm::dvec2> p;
            for (const glm::vec2 r : rests) {
                const glm::vec3 q = water.displace(r.x, r.y);
                p.push_back(glm::dvec2(q.x, q.z));
            }
            return p;
        };
        const std::vector<glm::dvec2> ahead = positions(t + dt), behind = positions(t - dt);
        double worst = 0.0, scale = 0.0;
        for (size_t k = 0; k < points.size(); ++k) {
            const glm::dvec2 fd = (ahead[k] - behind[k]) / (2 * dt);
            worst = std::max(worst, glm::length(fd - glm::dvec2(velocity[k])));
            scale = std::max(scale, double(glm::length(velocity[k])));
        }
        INFO(c.name << ": max |u| " << scale << " m/s, worst |u − FD| " << worst << " m/s, worst |u − closed form| " << closedForm);
        CHECK(scale > 0.1);
        CHECK(worst < 0.01 * scale + 5e-4);  // FFT rates: 3-point backward differences, (ω·Δt)²/3
        CHECK(closedForm < 1e-4 * scale + 1e-5);
    }
}
