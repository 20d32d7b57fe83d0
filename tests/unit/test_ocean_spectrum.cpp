// Spectral ocean, spectrum side: noise (eq. 4), Phillips (eq. 5), JONSWAP, h̃(K,t) (eq. 2–3),
// cascades. Every expectation comes from the formulas of docs/references.md#spectral-ocean, written out here.
#include "ocean/spectrum.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

using namespace ob::ocean;

namespace {

constexpr double PI = std::numbers::pi;

// Phillips eq. 5 per mode, as documented: A·Δk²·exp(−1/(k L_w)²)/k⁴·(K̂·ŵ)²·exp(−k²l²).
double phillipsRef(double kx, double kz, double L, const OceanDef& def) {
    const double k2 = kx * kx + kz * kz;
    if (k2 == 0.0) return 0.0;
    const double g = def.gravity, v = def.wind_speed;
    const double lw = v * v / g;
    const double l = def.small_wave_cutoff > 0 ? double(def.small_wave_cutoff) : 0.001 * lw;
    const double wl = std::hypot(double(def.wind_direction.x), double(def.wind_direction.y));
    const double c = (kx * def.wind_direction.x + kz * def.wind_direction.y) / (std::sqrt(k2) * wl);
    const double dk = 2 * PI / L;
    return def.amplitude * dk * dk * std::exp(-1.0 / (k2 * lw * lw)) / (k2 * k2) * c * c * std::exp(-k2 * l * l);
}

// JONSWAP S(ω) (Hasselmann 1973) from the fetch formulas, m²·s.
double jonswapRef(double w, const OceanDef& def) {
    const double g = def.gravity, v = def.wind_speed, f = def.fetch, gamma = def.peak_enhancement;
    const double alpha = 0.076 * std::pow(v * v / (f * g), 0.22);
    const double wp = 22.0 * std::pow(g * g / (v * f), 1.0 / 3.0);
    const double sigma = w <= wp ? 0.07 : 0.09;
    const double r = std::exp(-(w - wp) * (w - wp) / (2 * sigma * sigma * wp * wp));
    return alpha * g * g / std::pow(w, 5) * std::exp(-1.25 * std::pow(wp / w, 4)) * std::pow(gamma, r);
}

} // namespace

TEST_CASE("SplitMix64 reproduces the reference stream of Steele et al. (seed 0)", "[ocean][spectrum]") {
    // First outputs of the published splitmix64.c seeded with 0.
    GaussianRng rng(0);
    CHECK(rng.nextBits() == 0xE220A8397B1DCDAFull);
    CHECK(rng.nextBits() == 0x6E789E6AA1B965F4ull);
    CHECK(rng.nextBits() == 0x06C45D188009454Full);
}

TEST_CASE("Gaussian noise has mean 0, variance 1 and the normal 1-sigma mass over 10^6 samples", "[ocean][spectrum]") {
    GaussianRng rng(12345);
    const int count = 1000000;
    double sum = 0, sum2 = 0, sum4 = 0;
    int inside = 0;
    for (int i = 0; i < count; ++i) {
        const double x = rng.next();
        sum += x;
        sum2 += x * x;
        sum4 += x * x * x * x;
        inside += std::abs(x) < 1.0;
    }
    const double mean = sum / count;
    const double var = sum2 / count - mean * mean;
    CHECK(std::abs(mean) < 5e-3);                              // 5 standard errors
    CHECK(std::abs(var - 1.0) < 7e-3);                         // SE = sqrt(2/n) = 1.4e-3
    CHECK(std::abs(sum4 / count - 3.0) < 0.03);                // kurtosis of a normal
    CHECK(std::abs(double(inside) / count - 0.682689) < 3e-3); // erf(1/√2)
}

TEST_CASE("Gaussian noise is reproducible for a seed and differs between seeds", "[ocean][spectrum]") {
    GaussianRng a(77), b(77), c(78);
    bool differs = false;
    for (int i = 0; i < 1000; ++i) {
        const double x = a.next();
        REQUIRE(x == b.next());
        differs |= x != c.next();
    }
    CHECK(differs);
    CHECK(modeNoise(5, 0, 3, -4) == modeNoise(5, 0, 3, -4));
    CHECK(modeNoise(5, 0, 3, -4) != modeNoise(5, 0, -4, 3));
    CHECK(modeNoise(5, 0, 3, -4) != modeNoise(5, 1, 3, -4));
    CHECK(modeNoise(5, 0, 3, -4) != modeNoise(6, 0, 3, -4));
}

TEST_CASE("Phillips: Ph(0) = 0, equals eq. 5 and vanishes perpendicular to the wind", "[ocean][spectrum]") {
    OceanDef def;
    def.wind_direction = {1.0f, 1.0f};
    def.small_wave_cutoff = 0.05f;
    const SpectrumParams p = spectrumParams(def);
    const double L = 250.0, dk = 2 * PI / L;
    CHECK(phillips(0.0, 0.0, dk, p) == 0.0);
    // K ⟂ ŵ: (K̂·ŵ)² = 0 exactly.
    CHECK(phillips(0.3, -0.3, dk, p) == 0.0);
    CHECK(phillips(-1.7, 1.7, dk, p) == 0.0);
    for (double kx : {-0.9, -0.05, 0.02, 0.4, 3.0})
        for (double kz : {-0.7, 0.0, 0.1, 1.3})
            CHECK(phillips(kx, kz, dk, p) == Approx(phillipsRef(kx, kz, L, def)).epsilon(1e-12));
    // Symmetric in K → −K: waves run with and against the wind (|K̂·ŵ|²).
    CHECK(phillips(0.2, 0.1, dk, p) == Approx(phillips(-0.2, -0.1, dk, p)).epsilon(1e-14));
}

TEST_CASE("Phillips: the sea's variance Σ 2·Ph equals the continuous integral A·π·L_w²", "[ocean][spectrum]") {
    // ∫ exp(−1/(k L_w)²)/k⁴ (K̂·ŵ)² d²K = π·L_w²/2, and each mode is a wave of variance 2·Ph.
    OceanDef def;
    def.wind_speed = 8.0f;
    const SpectrumParams p = spectrumParams(def);
    const double lw = p.largestWave;
    const double L = 50.0 * lw;
    const int n = 256;
    const double dk = 2 * PI / L;
    double variance = 0;
    for (int m = -n / 2 + 1; m < n / 2; ++m)
        for (int q = -n / 2 + 1; q < n / 2; ++q) variance += 2.0 * phillips(q * dk, m * dk, dk, p);
    CHECK(variance == Approx(def.amplitude * PI * lw * lw).epsilon(0.02));
}

TEST_CASE("JONSWAP: S(ω) follows Hasselmann's formulas and peaks at ωp", "[ocean][spectrum]") {
    OceanDef def;
    def.spectrum = SpectrumKind::Jonswap;
    def.wind_speed = 10.0f;
    def.fetch = 100000.0f;
    const SpectrumParams p = spectrumParams(def);
    // α = 0.076 (V²/(F g))^0.22, ωp = 22 (g²/(V F))^(1/3) for V = 10 m/s, F = 100 km.
    CHECK(p.alpha == Approx(0.01006).epsilon(2e-3));
    CHECK(p.omegaPeak == Approx(1.0084).epsilon(2e-3));
    for (double w : {0.5, 0.9, 1.0, 1.1, 2.0, 5.0})
        CHECK(jonswapFrequency(w, p) == Approx(jonswapRef(w, def)).epsilon(1e-9));
    double best = 0, bestW = 0;
    for (double w = 0.5; w < 3.0; w += 1e-4) {
        const double s = jonswapFrequency(w, p);
        if (s > best) best = s, bestW = w;
    }
    CHECK(bestW == Approx(p.omegaPeak).epsilon(1e-3));
}

TEST_CASE("JONSWAP: the wavenumber spectrum (Jacobian dω/dk, cos² spreading) keeps ∫S(ω)dω", "[ocean][spectrum]") {
    OceanDef def;
    def.spectrum = SpectrumKind::Jonswap;
    const SpectrumParams p = spectrumParams(def);
    // ∫S(ω)dω by Simpson's rule.
    double expected = 0;
    const double w0 = 0.2, w1 = 12.0;
    const int steps = 200000;
    const double h = (w1 - w0) / steps;
    for (int i = 0; i <= steps; ++i) {
        const double weight = (i == 0 || i == steps) ? 1 : (i % 2 ? 4 : 2);
        expected += weight * jonswapRef(w0 + i * h, def);
    }
    expected *= h / 3;
    const double L = 2000.0;
    const int n = 1024;  // kmax = π N / L = 1.6 rad/m, ω = 4 ωp
    const double dk = 2 * PI / L;
    double variance = 0;
    for (int m = -n / 2 + 1; m < n / 2; ++m)
        for (int q = -n / 2 + 1; q < n / 2; ++q) variance += 2.0 * jonswap(q * dk, m * dk, dk, p);
    CHECK(variance == Approx(expected).epsilon(0.03));
}

TEST_CASE("JONSWAP: waves travel downwind only and none perpendicular to the wind", "[ocean][spectrum]") {
    OceanDef def;
    def.spectrum = SpectrumKind::Jonswap;
    def.wind_direction = {0.0f, 1.0f};
    const SpectrumParams p = spectrumParams(def);
    const double dk = 2 * PI / 250.0;
    // h̃0(K) feeds the wave travelling toward −K (eq. 1–2): nonzero only for K·ŵ < 0.
    CHECK(jonswap(0.0, -0.1, dk, p) > 0.0);
    CHECK(jonswap(0.0, 0.1, dk, p) == 0.0);
    CHECK(jonswap(0.1, 0.0, dk, p) == 0.0);
    CHECK(jonswap(-0.1, 0.0, dk, p) == 0.0);
    CHECK(jonswap(0.0, 0.0, dk, p) == 0.0);
}

TEST_CASE("Dispersion: ω(k) = sqrt(g·k) for every mode (eq. 3)", "[ocean][spectrum]") {
    const CascadeSpectrum s(16, 40.0, 9.81);
    for (int m = -8; m < 8; ++m)
        for (int n = -8; n < 8; ++n) {
            const double k = 2 * PI / 40.0 * std::hypot(n, m);
            CHECK(s.omega(n, m) == Approx(std::sqrt(9.81 * k)).epsilon(1e-12));
        }
}

TEST_CASE("h̃(K,t) is Hermitian: conj(h̃(K,t)) = h̃(−K,t) at every K and t (eq. 2)", "[ocean][spectrum]") {
    OceanDef def;
    def.resolution = 32;
    def.patch_size = 60.0f;
    const CascadeSpectrum s(def, 0);
    for (double t : {0.0, 0.37, 11.0, 5000.5})
        for (int m = -15; m < 16; ++m)
            for (int n = -15; n < 16; ++n) {
                const auto a = std::conj(s.hTilde(n, m, t));
                const auto b = s.hTilde(-n, -m, t);
                REQUIRE(std::abs(a - b) <= 1e-12 * (1.0 + std::abs(a)));
            }
}

TEST_CASE("h̃0 = ξ·sqrt(Ph/2) (eq. 4): zero at K = 0, on the Nyquist row and column", "[ocean][spectrum]") {
    OceanDef def;
    def.resolution = 16;
    def.patch_size = 30.0f;
    def.amplitude = 0.5f;
    const CascadeSpectrum s(def, 0);
    CHECK(s.h0(0, 0) == std::complex<float>(0, 0));
    for (int i = -8; i < 8; ++i) {
        CHECK(s.h0(-8, i) == std::complex<float>(0, 0));
        CHECK(s.h0(i, -8) == std::complex<float>(0, 0));
    }
    // A mode is ξ·sqrt(Ph/2) with ξ the mode's own noise.
    const double L = def.patch_size;
    const double kx = 2 * PI * 3 / L, kz = 2 * PI * -2 / L;
    const std::complex<double> expected = modeNoise(def.seed, 0, 3, -2) * std::sqrt(phillipsRef(kx, kz, L, def) / 2);
    CHECK(double(s.h0(3, -2).real()) == Approx(expected.real()).epsilon(1e-6));
    CHECK(double(s.h0(3, -2).imag()) == Approx(expected.imag()).epsilon(1e-6));
}

TEST_CASE("A mode's h̃0 does not depend on the resolution (same sea at any N)", "[ocean][spectrum]") {
    OceanDef a, b;
    a.resolution = 32;
    b.resolution = 128;
    const CascadeSpectrum sa(a, 0), sb(b, 0);
    for (int m = -15; m < 16; ++m)
        for (int n = -15; n < 16; ++n) REQUIRE(sa.h0(n, m) == sb.h0(n, m));
}

TEST_CASE("Averaged over seeds, the mean square height Σ|h̃(K,t)|² approaches Σ 2·Ph(K)", "[ocean][spectrum]") {
    // E|h̃(K,t)|² = Ph(K) + Ph(−K) (eq. 2, independent ξ) = 2·Ph(K) for Phillips.
    OceanDef def;
    def.resolution = 32;
    def.patch_size = 100.0f;
    def.wind_speed = 6.0f;
    const int half = def.resolution / 2;
    double theory = 0;
    for (int m = -half + 1; m < half; ++m)
        for (int n = -half + 1; n < half; ++n)
            theory += 2.0 * phillipsRef(2 * PI * n / def.patch_size, 2 * PI * m / def.patch_size, def.patch_size, def);
    const int seeds = 400;
    double sum = 0, sum2 = 0;
    for (int seed = 0; seed < seeds; ++seed) {
        def.seed = 1000 + seed;
        const CascadeSpectrum s(def, 0);
        double ms = 0;
        for (int m = -half; m < half; ++m)
            for (int n = -half; n < half; ++n) ms += std::norm(s.hTilde(n, m, 2.5));
        sum += ms;
        sum2 += ms * ms;
    }
    const double mean = sum / seeds;
    const double stdErr = std::sqrt((sum2 / seeds - mean * mean) / seeds);
    CHECK(std::abs(mean - theory) < 4 * stdErr);
    CHECK(mean == Approx(theory).epsilon(0.1));
}

TEST_CASE("Cascades: tiles L/φ^(2c) with wave bands that partition k", "[ocean][spectrum]") {
    OceanDef def;
    def.cascades = 4;
    def.resolution = 64;
    const double phi2 = std::numbers::phi * std::numbers::phi;
    for (int c = 0; c < 4; ++c) CHECK(cascadePatchSize(def, c) == Approx(def.patch_size / std::pow(phi2, c)));
    CHECK(cascadeBand(def, 0).kMin == 0.0);
    CHECK(std::isinf(cascadeBand(def, 3).kMax));
    for (int c = 0; c < 3; ++c) {
        CHECK(cascadeBand(def, c).kMax == cascadeBand(def, c + 1).kMin);
        CHECK(cascadeBand(def, c).kMax > cascadeBand(def, c).kMin);
        // The coarser tile represents its whole band: the boundary is below its Nyquist.
        CHECK(cascadeBand(def, c).kMax <= PI * def.resolution / cascadePatchSize(def, c));
    }
}

TEST_CASE("Cascades together sample one spectrum: their variances add up to A·π·L_w²", "[ocean][spectrum]") {
    OceanDef def;
    def.cascades = 3;
    def.resolution = 256;
    def.wind_speed = 12.0f;
    def.patch_size = 1000.0f;
    const SpectrumParams p = spectrumParams(def);
    double variance = 0;
    for (int c = 0; c < def.cascades; ++c) {
        const CascadeSpectrum s(def, c);
        const WaveBand band = cascadeBand(def, c);
        const double dk = 2 * PI / s.patchSize();
        for (int m = -127; m < 128; ++m)
            for (int n = -127; n < 128; ++n) {
                const double k = dk * std::hypot(n, m);
                if (k >= band.kMin && k < band.kMax) variance += 2.0 * phillips(n * dk, m * dk, dk, p);
            }
    }
    CHECK(variance == Approx(def.amplitude * PI * p.largestWave * p.largestWave).epsilon(0.03));
}

TEST_CASE("Stokes drift: Phillips' waves both ways drift 0, JONSWAP's is the deep-water integral (2/g)·∫ω³S(ω)dω·8/(3π) down-wind",
          "[ocean][spectrum][wind]") {
    // A wave of amplitude a drifts its surface by ω·k·a² (deep water, Stokes 1847), a² = 2·S(ω)dω
    // per band: U_s = ∫2·ω·k·S(ω)dω = (2/g)·∫ω³S(ω)dω, times ⟨cos θ⟩ = ∫(2/π)·cos³θ dθ = 8/(3π)
    // of the cos² spreading, toward ŵ. The modes end at |kx|, |kz| < π·N/L (ω ≈ 4·ωp).
    OceanDef def;
    def.wind_direction = {1.0f, 0.6f};
    const std::array<double, 2> phillips = stokesDrift(def);
    CHECK(phillips[0] == 0.0);
    CHECK(phillips[1] == 0.0);
    def.spectrum = SpectrumKind::Jonswap;
    def.patch_size = 2000.0f;
    def.resolution = 1024;
    def.cascades = 1;
    const double g = def.gravity, kMax = PI * def.resolution / def.patch_size, w1 = std::sqrt(g * kMax), w0 = 0.2;
    double integral = 0;
    const int steps = 20000;
    const double h = (w1 - w0) / steps;
    for (int i = 0; i <= steps; ++i) {
        const double w = w0 + i * h, weight = (i == 0 || i == steps) ? 1 : (i % 2 ? 4 : 2);
        integral += weight * w * w * w * jonswapRef(w, def);
    }
    const double expected = 2.0 / g * integral * h / 3 * 8.0 / (3.0 * PI);
    const std::array<double, 2> u = stokesDrift(def);
    const double wl = std::hypot(1.0, 0.6);
    const double along = (u[0] * 1.0 + u[1] * 0.6) / wl, across = (-u[0] * 0.6 + u[1] * 1.0) / wl;
    INFO("Stokes drift along the wind " << along << " m/s (integral " << expected << "), across " << across);
    CHECK(along == Approx(expected).epsilon(0.05));
    CHECK(std::abs(across) < 0.01 * along);
}
