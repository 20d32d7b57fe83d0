// Gerstner waves (docs/references.md#gerstner-waves; [Lee2007] eq. 8, [Min2023] §2): circular orbits, the trochoid's
// sharp crest, dispersion, analytic normals against finite differences of a double-precision
// reference written from the SPEC, validation of k·a, spectrum-derived waves, the dump.
#include "tools/cmd_dump_surface.h"
#include "core/error.h"
#include "core/npy.h"
#include "core/toml_reader.h"
#include "ocean/gerstner.h"
#include "ocean/spectrum.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace ob::ocean;

namespace {

constexpr double PI = std::numbers::pi;
constexpr double G = double(9.81f);  // the float the code receives, so ω·t agrees at t = 1e5 s

// [Min2023]'s 13 example waves (kx, kz, a, φ); the paper uses the first 8 (docs/references.md#gerstner-waves).
const std::vector<GerstnerWave> SEED002 = {
    {0.3f, -0.46f, 0.2f, 0.0f},   {-0.33f, 0.40f, 0.12f, 0.0f}, {0.0f, 0.56f, 0.2f, 0.2f},
    {-0.33f, 0.0f, 0.12f, 0.3f},  {0.3f, -0.26f, 0.2f, 0.7f},   {-0.33f, 0.20f, 0.12f, 0.9f},
    {0.17f, 0.3f, 0.3f, -1.0f},   {-0.15f, -0.1f, 0.7f, 0.6f},  {-0.15f, 0.1f, 0.6f, 0.5f},
    {0.15f, -0.1f, 0.8f, 0.4f},   {0.15f, 0.1f, 0.3f, 0.3f},    {-0.25f, -0.1f, 0.2f, 0.2f},
    {-0.15f, -0.25f, 0.4f, 0.1f}};
const std::vector<GerstnerWave> SEED002_FIRST8(SEED002.begin(), SEED002.begin() + 8);

struct Vec3d {
    double x, y, z;
};
Vec3d sub(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d cross(Vec3d a, Vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3d unit(Vec3d a) {
    const double l = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return {a.x / l, a.y / l, a.z / l};
}

// docs/references.md#gerstner-waves written plainly, in double: the position of rest point (α, β) at time t.
Vec3d reference(const std::vector<GerstnerWave>& waves, double alpha, double beta, double t, double g = G) {
    Vec3d r{alpha, 0.0, beta};
    for (const GerstnerWave& w : waves) {
        const double kx = w.kx, kz = w.kz, k = std::hypot(kx, kz), a = w.amplitude;
        const double theta = kx * alpha + kz * beta - std::sqrt(g * k) * t - w.phase;
        r.x -= kx / k * a * std::sin(theta);
        r.z -= kz / k * a * std::sin(theta);
        r.y += a * std::cos(theta);
    }
    return r;
}

// Unit normal of the reference surface from central differences: ∂r/∂β × ∂r/∂α (y up).
Vec3d finiteDifferenceNormal(const std::vector<GerstnerWave>& waves, double alpha, double beta, double t) {
    const double h = 1e-5;
    const Vec3d da = sub(reference(waves, alpha + h, beta, t), reference(waves, alpha - h, beta, t));
    const Vec3d db = sub(reference(waves, alpha, beta + h, t), reference(waves, alpha, beta - h, t));
    return unit(cross(db, da));
}

// [Min2023]'s shader normal with its slip: sin θ where ∂x/∂α, ∂x/∂β, ∂z/∂β need cos θ.
Vec3d seed002SlipNormal(const std::vector<GerstnerWave>& waves, double alpha, double beta, double t) {
    double sxx = 0, sxz = 0, szz = 0, qx = 0, qz = 0;
    for (const GerstnerWave& w : waves) {
        const double kx = w.kx, kz = w.kz, k = std::hypot(kx, kz), a = w.amplitude;
        const double s = std::sin(kx * alpha + kz * beta - std::sqrt(G * k) * t - w.phase);
        sxx += kx * kx / k * a * s;
        sxz += kx * kz / k * a * s;
        szz += kz * kz / k * a * s;
        qx += kx * a * s;
        qz += kz * a * s;
    }
    const Vec3d da{1 - sxx, -qx, -sxz}, db{-sxz, -qz, 1 - szz};
    return unit(cross(db, da));
}

double angleBetween(Vec3d a, glm::vec3 b) {
    const double d = a.x * b.x + a.y * b.y + a.z * b.z;
    const double c = std::sqrt((a.y * b.z - a.z * b.y) * (a.y * b.z - a.z * b.y) +
                               (a.z * b.x - a.x * b.z) * (a.z * b.x - a.x * b.z) +
                               (a.x * b.y - a.y * b.x) * (a.x * b.y - a.y * b.x));
    return std::atan2(c, d);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A scene holding only the [gerstner] section, read by describe() as the scene loader does.
struct GerstnerScene {
    GerstnerDef gerstner;
};
template <class V> void describe(V& v, GerstnerScene& s) { v.section("gerstner", s.gerstner); }

std::vector<std::string> loadGerstner(const std::string& text, GerstnerScene& out) {
    std::vector<std::string> errors;
    ob::TomlDocument doc = ob::TomlDocument::fromString(text, "sea.toml", errors);
    ob::TomlReader reader(doc, errors);
    describe(reader, out);
    reader.finish();
    return errors;
}

} // namespace

TEST_CASE("Gerstner: a single wave moves every particle on a circle of radius a about its rest point, in the plane of K", "[gerstner]") {
    const GerstnerWave wave{0.2f, 0.15f, 1.5f, 0.4f};  // k = 0.25 rad/m, k·a = 0.375
    GerstnerField field(std::vector<GerstnerWave>{wave}, float(G));
    const double k = 0.25, period = 2 * PI / std::sqrt(G * k);
    for (const auto& [alpha, beta] : {std::pair{0.0f, 0.0f}, {3.7f, -12.5f}, {-40.0f, 25.0f}}) {
        double meanY = 0, turned = 0, lastAngle = 0;
        const int steps = 64;
        for (int s = 0; s <= steps; ++s) {
            field.setTime(period * s / steps);
            const GerstnerPoint p = field.evaluate(alpha, beta);
            const double ex = p.position.x - alpha, ey = p.position.y, ez = p.position.z - beta;
            INFO("rest (" << alpha << ", " << beta << "), step " << s);
            CHECK(std::sqrt(ex * ex + ey * ey + ez * ez) == Approx(wave.amplitude).margin(2e-5));
            CHECK(std::abs(ex * 0.6 - ez * 0.8) < 2e-5);  // no motion across K̂ = (0.8, 0.6)
            // The orbit angle in the (K̂, y) plane turns steadily, one full turn per period.
            const double angle = std::atan2(ey, ex * 0.8 + ez * 0.6);
            if (s > 0) {
                double d = angle - lastAngle;
                d -= 2 * PI * std::round(d / (2 * PI));
                CHECK(std::abs(d) == Approx(2 * PI / steps).margin(1e-4));
                turned += d;
            }
            lastAngle = angle;
            if (s < steps) meanY += ey / steps;
        }
        CHECK(std::abs(turned) == Approx(2 * PI).margin(1e-3));
        CHECK(std::abs(meanY) < 1e-5);  // circle centred on the rest height
    }
}

TEST_CASE("Gerstner: dispersion ω = sqrt(g·k): the motion repeats after T = 2π/sqrt(g·k), and y(t) = a·cos(θ0 − ωt)", "[gerstner]") {
    for (const double g : {9.81, 3.71}) {
        for (const float k : {0.05f, 0.4f, 2.0f}) {
            const GerstnerWave wave{k * 0.6f, -k * 0.8f, 0.3f / k, 1.1f};  // k·a = 0.3
            GerstnerField field(std::vector<GerstnerWave>{wave}, float(g));
            const double omega = std::sqrt(g * double(k)), period = 2 * PI / omega;
            const float alpha = 3.0f, beta = -2.0f;
            const double theta0 = double(wave.kx) * alpha + double(wave.kz) * beta - wave.phase;
            INFO("g = " << g << ", k = " << k);
            for (int s = 0; s < 16; ++s) {
                const double t = 0.37 * period * s;
                field.setTime(t);
                const GerstnerPoint p = field.evaluate(alpha, beta);
                CHECK(p.position.y == Approx(wave.amplitude * std::cos(theta0 - omega * t)).margin(2e-6 / k));
                CHECK(p.verticalVelocity == Approx(wave.amplitude * omega * std::sin(theta0 - omega * t)).margin(2e-6 * omega / k));
                field.setTime(t + period);
                const GerstnerPoint q = field.evaluate(alpha, beta);
                CHECK(q.position.x == Approx(p.position.x).margin(1e-5));
                CHECK(q.position.y == Approx(p.position.y).margin(1e-5 / k));
                CHECK(q.position.z == Approx(p.position.z).margin(1e-5));
            }
            // Not periodic with a 10% different ω: the phase would be off by 0.2π at t = T, a
            // chord of 2a·sin(0.1π) = 0.62·a on the orbit.
            field.setTime(0.0);
            const glm::vec3 r0 = field.evaluate(alpha, beta).position;
            field.setTime(1.1 * period);
            const glm::vec3 d = field.evaluate(alpha, beta).position - r0;
            CHECK(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) == Approx(2 * wave.amplitude * std::sin(0.1 * PI)).epsilon(1e-4));
        }
    }
}

TEST_CASE("Gerstner: the trochoid's crest is sharper than its trough (curvature a·k²/(1∓k·a)², crest width λ·(1/2 − k·a/π))", "[gerstner]") {
    const float k = 0.5f, a = 1.2f;  // k·a = 0.6
    GerstnerField field(std::vector<GerstnerWave>{{k, 0.0f, a, 0.0f}}, float(G));
    field.setTime(0.0);
    // Curvature of the profile curve (x(α), y(α)) from central differences of the positions.
    const auto curvature = [&](float alpha) {
        const float h = 0.02f;
        const GerstnerPoint m = field.evaluate(alpha - h, 0), c = field.evaluate(alpha, 0), p = field.evaluate(alpha + h, 0);
        const double x1 = (p.position.x - m.position.x) / (2 * h), y1 = (p.position.y - m.position.y) / (2 * h);
        const double x2 = (p.position.x - 2 * c.position.x + m.position.x) / (h * h);
        const double y2 = (p.position.y - 2 * c.position.y + m.position.y) / (h * h);
        return std::abs(x1 * y2 - y1 * x2) / std::pow(x1 * x1 + y1 * y1, 1.5);
    };
    const double ka = double(k) * a;
    const double crest = curvature(0.0f), trough = curvature(float(PI / k));
    CHECK(crest == Approx(a * k * k / ((1 - ka) * (1 - ka))).epsilon(0.01));
    CHECK(trough == Approx(a * k * k / ((1 + ka) * (1 + ka))).epsilon(0.01));
    CHECK(crest > 10 * trough);
    // Width above the mean level, as a fraction of the wavelength, from a dense profile.
    const int samples = 20000;
    double above = 0.0;
    const double wavelength = 2 * PI / k;
    for (int i = 0; i < samples; ++i) {
        const float a0 = float(wavelength * i / samples), a1 = float(wavelength * (i + 1) / samples);
        const GerstnerPoint p0 = field.evaluate(a0, 0), p1 = field.evaluate(a1, 0);
        if (p0.position.y + p1.position.y > 0) above += p1.position.x - p0.position.x;
    }
    CHECK(above / wavelength == Approx(0.5 - ka / PI).margin(2e-3));
    CHECK(above / wavelength < 0.5);
}

TEST_CASE("Gerstner: analytic normals equal the cross product of central differences of the positions ([Min2023] waves)", "[gerstner]") {
    const std::vector<GerstnerWave> mixed = {{0.8f, 0.1f, 0.3f, 0.2f}, {-0.05f, 0.3f, 1.5f, 1.0f}, {1.9f, -1.4f, 0.05f, -2.0f}};
    struct Case {
        const char* name;
        const std::vector<GerstnerWave>* waves;
    };
    for (const Case& c : {Case{"[Min2023], first 8", &SEED002_FIRST8}, Case{"[Min2023], all 13", &SEED002}, Case{"mixed", &mixed}}) {
        GerstnerField field(*c.waves, float(G));
        double worst = 0.0, worstSlip = 0.0, worstPosition = 0.0;
        for (const double t : {0.0, 1.3, 47.9}) {
            field.setTime(t);
            for (int j = 0; j < 12; ++j)
                for (int i = 0; i < 12; ++i) {
                    const float alpha = -30.0f + 5.1f * i, beta = -25.0f + 4.7f * j;
                    const GerstnerPoint p = field.evaluate(alpha, beta);
                    const Vec3d ref = reference(*c.waves, alpha, beta, t);
                    worstPosition = std::max({worstPosition, std::abs(p.position.x - ref.x),
                                              std::abs(p.position.y - ref.y), std::abs(p.position.z - ref.z)});
                    worst = std::max(worst, angleBetween(finiteDifferenceNormal(*c.waves, alpha, beta, t), p.normal));
                    const glm::vec3 slip = [&] {
                        const Vec3d s = seed002SlipNormal(*c.waves, alpha, beta, t);
                        return glm::vec3(float(s.x), float(s.y), float(s.z));
                    }();
                    worstSlip = std::max(worstSlip, angleBetween(finiteDifferenceNormal(*c.waves, alpha, beta, t), slip));
                }
        }
        INFO(c.name << ": worst normal angle " << worst << " rad, [Min2023]'s sin form " << worstSlip
                    << " rad, worst position error " << worstPosition << " m");
        CHECK(worst < 2e-5);
        CHECK(worstPosition < 2e-5);
        CHECK(worstSlip > 0.05);  // the test tells the derivative from [Min2023]'s slip
    }
}

TEST_CASE("Gerstner: the batch (vectorised over points) equals the single-point path, and long times keep their precision", "[gerstner]") {
    GerstnerField field(SEED002, float(G));
    for (const double t : {0.0, 12.5, 1e5}) {
        field.setTime(t);
        std::vector<float> alpha, beta;
        for (int i = 0; i < 37; ++i) {  // not a multiple of the SIMD width: the tail path too
            alpha.push_back(-50.0f + 2.9f * i);
            beta.push_back(20.0f - 1.3f * i);
        }
        std::vector<GerstnerPoint> batch(alpha.size());
        field.evaluate(alpha.data(), beta.data(), alpha.size(), batch.data());
        for (size_t i = 0; i < alpha.size(); ++i) {
            const GerstnerPoint one = field.evaluate(alpha[i], beta[i]);
            const Vec3d ref = reference(SEED002, alpha[i], beta[i], t);
            INFO("t = " << t << ", point " << i);
            CHECK(batch[i].position.x == Approx(one.position.x).margin(1e-5));
            CHECK(batch[i].position.y == Approx(one.position.y).margin(1e-5));
            CHECK(batch[i].normal.x == Approx(one.normal.x).margin(1e-5));
            CHECK(batch[i].verticalVelocity == Approx(one.verticalVelocity).margin(1e-5));
            CHECK(batch[i].position.x == Approx(ref.x).margin(3e-5));
            CHECK(batch[i].position.y == Approx(ref.y).margin(3e-5));
            CHECK(batch[i].position.z == Approx(ref.z).margin(3e-5));
        }
    }
}

TEST_CASE("Gerstner: a wave with k·a ≥ 1 is rejected with its key path ([Lee2007] fig. 2: the surface self-intersects)", "[gerstner]") {
    GerstnerDef def;
    def.waves = {{0.1f, 0.0f, 1.0f, 0.0f}, {0.0f, 0.2f, 1.0f, 0.0f}, {0.3f, 0.4f, 0.2f, 0.0f}, {1.2f, 0.0f, 1.0f, 0.0f}};
    std::vector<std::string> errors = validate(def);
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0], "gerstner.waves[3]: k·a = 1.2 ≥ 1: the surface would self-intersect"));

    def.waves = {{0.0f, -1.0f, 1.0f, 0.0f}};  // k·a = 1 exactly: the cusp is already a fold
    errors = validate(def);
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0], "gerstner.waves[0]: k·a = 1 ≥ 1"));

    def.waves = {{0.0f, 0.0f, 1.0f, 0.0f}};
    errors = validate(def);
    REQUIRE(errors.size() == 1);
    CHECK(contains(errors[0], "gerstner.waves[0]: wave vector [kx, kz] = [0, 0]"));

    def.waves = SEED002_FIRST8;
    CHECK(validate(def).empty());
}

TEST_CASE("Gerstner: Σ k·a ≥ 1 is accepted with one warning (each wave alone is fine)", "[gerstner]") {
    GerstnerDef def;
    def.waves = {{0.4f, 0.0f, 1.0f, 0.0f}, {0.0f, 0.4f, 1.0f, 0.0f}, {0.3f, 0.4f, 0.8f, 0.0f}};  // 0.4 each
    std::vector<std::string> warnings;
    CHECK(validate(def, nullptr, &warnings).empty());
    REQUIRE(warnings.size() == 1);
    CHECK(contains(warnings[0], "Σ k·a = 1.2 ≥ 1"));

    def.waves.pop_back();  // Σ k·a = 0.8
    warnings.clear();
    CHECK(validate(def, nullptr, &warnings).empty());
    CHECK(warnings.empty());

    def.steepness_warning = 0.5f;  // the threshold is a key
    CHECK(validate(def, nullptr, &warnings).empty());
    CHECK(warnings.size() == 1);
}

TEST_CASE("Gerstner: generated waves carry the Phillips variance of their band, A·π·L_w²·[e^(−1/(k₁L_w)²) − e^(−1/(k₀L_w)²)]", "[gerstner]") {
    OceanDef ocean;
    ocean.wind_speed = 30.0f;  // L_w = 91.7 m: the band below the FFT's first mode holds energy
    ocean.wind_direction = {1.0f, 2.0f};
    GerstnerDef def;
    def.count = 16;
    def.seed = 7;
    const GerstnerBand band = generationBand(def, ocean);
    CHECK(band.kMax == Approx(2.0 * std::sqrt(PI) / ocean.patch_size));  // the K = 0 cell's area
    const std::vector<GerstnerWave> waves = generateWaves(def, ocean);
    REQUIRE(waves.size() == 16);

    const double lw = double(ocean.wind_speed) * ocean.wind_speed / ocean.gravity;
    const auto below = [&](double k) { return ocean.amplitude * PI * lw * lw * std::exp(-1.0 / (k * lw * k * lw)); };
    double variance = 0.0;
    const double wx = 1 / std::sqrt(5.0), wz = 2 / std::sqrt(5.0);
    for (const GerstnerWave& w : waves) {
        const double k = std::hypot(double(w.kx), double(w.kz));
        variance += 0.5 * double(w.amplitude) * w.amplitude;
        CHECK(k >= band.kMin * (1 - 1e-6));
        CHECK(k <= band.kMax * (1 + 1e-6));
        CHECK((w.kx * wx + w.kz * wz) / k >= 0.0);  // every wave travels downwind
        CHECK(k * w.amplitude < 1.0);
    }
    INFO("band " << 2 * PI / band.kMax << " … " << 2 * PI / band.kMin << " m");
    CHECK(variance == Approx(below(band.kMax) - below(band.kMin)).epsilon(0.01));
    CHECK(below(band.kMin) < 0.01 * below(band.kMax));  // the auto band keeps > 99% of k < kMax
    // Same seed, same waves; another seed, other waves.
    const std::vector<GerstnerWave> again = generateWaves(def, ocean);
    CHECK(std::equal(waves.begin(), waves.end(), again.begin(), [](const GerstnerWave& a, const GerstnerWave& b) {
        return a.kx == b.kx && a.kz == b.kz && a.amplitude == b.amplitude && a.phase == b.phase;
    }));
    def.seed = 8;
    CHECK(generateWaves(def, ocean)[3].kx != waves[3].kx);
    // resolveWaves: explicit waves first, then the generated ones.
    def.waves = {SEED002[0]};
    CHECK(resolveWaves(def, ocean).size() == 17);
    CHECK(resolveWaves(def, ocean)[0].kx == SEED002[0].kx);
}

TEST_CASE("Gerstner: generated waves from JONSWAP carry ∫S(ω)dω of their band and travel downwind", "[gerstner]") {
    OceanDef ocean;
    ocean.spectrum = SpectrumKind::Jonswap;
    ocean.wind_speed = 15.0f;
    ocean.patch_size = 40.0f;  // the band reaches past the JONSWAP peak (λp ≈ 79 m)
    GerstnerDef def;
    def.count = 12;
    const GerstnerBand band = generationBand(def, ocean);
    const std::vector<GerstnerWave> waves = generateWaves(def, ocean);
    REQUIRE(waves.size() == 12);
    const SpectrumParams p = spectrumParams(ocean);
    // ∫ S(ω) dω over the band's frequencies, midpoint rule (cos² spreading integrates to 1).
    const double w0 = std::sqrt(G * band.kMin), w1 = std::sqrt(G * band.kMax);
    double expected = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) expected += jonswapFrequency(w0 + (w1 - w0) * (i + 0.5) / n, p) * (w1 - w0) / n;
    double variance = 0.0;
    for (const GerstnerWave& w : waves) {
        variance += 0.5 * double(w.amplitude) * w.amplitude;
        CHECK(w.kx > 0.0f);  // wind along +x: downwind
    }
    CHECK(variance == Approx(expected).epsilon(0.01));
    CHECK(validate(def, &ocean).empty());
}

TEST_CASE("Gerstner: validate() checks the generated waves too, naming gerstner.count", "[gerstner]") {
    OceanDef ocean;
    ocean.wind_speed = 30.0f;
    GerstnerDef def;
    def.count = 4;
    def.amplitude_scale = 100.0f;
    const std::vector<std::string> errors = validate(def, &ocean);
    REQUIRE(!errors.empty());
    CHECK(contains(errors[0], "gerstner.count: generated wave"));
    CHECK(contains(errors[0], "≥ 1"));
    def.amplitude_scale = 1.0f;
    def.min_wavelength = 500.0f;
    def.max_wavelength = 400.0f;
    REQUIRE(validate(def, &ocean).size() == 1);
    CHECK(contains(validate(def, &ocean)[0], "gerstner.max_wavelength"));
}

TEST_CASE("Gerstner: dump gerstner writes [N, N, 6] = (x, y, z, nx, ny, nz) of rest points (i·E/N, j·E/N)", "[gerstner]") {
    GerstnerDef def;
    def.waves = SEED002_FIRST8;
    const std::string out = ob::test::tempPath("gerstner_dump.npy");
    const int n = 24;
    const float extent = 60.0f;
    const double t = 2.5;
    REQUIRE(ob::game::dumpGerstner(def, float(G), t, n, extent, out) == 0);
    const ob::NpyArray a = ob::readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{size_t(n), size_t(n), 6});
    for (int j = 0; j < n; j += 5)
        for (int i = 0; i < n; i += 3) {
            const double alpha = double(i) * extent / n, beta = double(j) * extent / n;
            const Vec3d ref = reference(def.waves, alpha, beta, t);
            const Vec3d nrm = finiteDifferenceNormal(def.waves, alpha, beta, t);
            const float* e = &a.data[(size_t(j) * n + size_t(i)) * 6];
            INFO("[" << j << ", " << i << "]");
            CHECK(e[0] == Approx(ref.x).margin(3e-5));
            CHECK(e[1] == Approx(ref.y).margin(3e-5));
            CHECK(e[2] == Approx(ref.z).margin(3e-5));
            CHECK(e[3] == Approx(nrm.x).margin(3e-5));
            CHECK(e[4] == Approx(nrm.y).margin(3e-5));
            CHECK(e[5] == Approx(nrm.z).margin(3e-5));
        }
    CHECK_THROWS_AS(ob::game::dumpGerstner(def, float(G), t, 0, extent, out), ob::InputError);
    CHECK_THROWS_AS(ob::game::dumpGerstner(def, float(G), t, n, -1.0f, out), ob::InputError);
    def.waves.push_back({2.0f, 0.0f, 0.6f, 0.0f});  // k·a = 1.2
    try {
        ob::game::dumpGerstner(def, float(G), t, n, extent, out);
        FAIL("no InputError");
    } catch (const ob::InputError& e) {
        CHECK(contains(e.what(), "gerstner.waves[8]"));
    }
}

TEST_CASE("Gerstner: the [gerstner] section reads [Min2023]'s wave list and the generation keys through describe()", "[gerstner]") {
    GerstnerScene scene;
    CHECK(loadGerstner("", scene).empty());  // every key optional: no waves, nothing generated
    CHECK(scene.gerstner.waves.empty());
    CHECK(scene.gerstner.count == 0);
    const std::string text =
        "[gerstner]\n"
        "count = 6\nseed = 9\nmin_wavelength = 300.0\nmax_wavelength = 2000.0\namplitude_scale = 0.5\n"
        "steepness_warning = 0.9\n"
        "[[gerstner.waves]]\nkx = 0.3\nkz = -0.46\namplitude = 0.2\n"
        "[[gerstner.waves]]\nkx = 0.17\nkz = 0.3\namplitude = 0.3\nphase = -1.0\n";
    REQUIRE(loadGerstner(text, scene).empty());
    const GerstnerDef& d = scene.gerstner;
    REQUIRE(d.waves.size() == 2);
    CHECK(d.waves[0].kz == -0.46f);
    CHECK(d.waves[0].phase == 0.0f);
    CHECK(d.waves[1].phase == -1.0f);
    CHECK(d.count == 6);
    CHECK(d.seed == 9);
    CHECK(d.min_wavelength == 300.0f);
    CHECK(d.max_wavelength == 2000.0f);
    CHECK(d.amplitude_scale == 0.5f);
    CHECK(d.steepness_warning == 0.9f);
    const std::vector<std::string> errors = loadGerstner("[[gerstner.waves]]\nkx = 0.1\nheight = 2\n[gerstner]\ncount = 99\n", scene);
    REQUIRE(errors.size() == 2);
    CHECK(contains(errors[0] + errors[1], "gerstner.waves[0].height: unknown key"));
    CHECK(contains(errors[0] + errors[1], "gerstner.count: must be in [0, 64], got 99"));
}
