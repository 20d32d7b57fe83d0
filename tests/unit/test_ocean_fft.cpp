// Spectral ocean, FFT side: the CPU maps against a direct DFT of eq. 1 in double, single-mode
// waves against their closed forms (eq. 3, 6, 7), Parseval, the foam Jacobian, the dump.
#include "core/npy.h"
#include "ocean/ocean_fft_cpu.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <cstring>
#include <memory>
#include <numbers>
#include <vector>

using namespace ob::ocean;
using cd = std::complex<double>;

namespace {

constexpr double PI = std::numbers::pi;
const cd I(0.0, 1.0);

// Reference fields by eq. 1 written plainly: f(X) = Σ_{n,m ∈ [−N/2, N/2)} F(K) exp(iK·X) at
// X = (i·L/N, j·L/N), with h̃(K,t) from eq. 2–3 and the channel spectra of eq. 6–7.
struct Reference {
    int n;
    std::vector<cd> h, dx, dz, sx, sz, dxx, dzz, dxz;  // [j][i], complex: imaginary parts ~ 0
};

Reference directDft(const CascadeSpectrum& s, double t) {
    const int N = s.resolution();
    const double L = s.patchSize(), g = s.gravity();
    const auto neg = [N](int q) { return q == -N / 2 ? q : -q; };  // −K on the periodic grid
    Reference r{N, {}, {}, {}, {}, {}, {}, {}, {}};
    for (auto* v : {&r.h, &r.dx, &r.dz, &r.sx, &r.sz, &r.dxx, &r.dzz, &r.dxz}) v->assign(size_t(N) * N, 0.0);
    for (int m = -N / 2; m < N / 2; ++m)
        for (int n = -N / 2; n < N / 2; ++n) {
            const double kx = 2 * PI * n / L, kz = 2 * PI * m / L, k = std::hypot(kx, kz);
            const double w = std::sqrt(g * k);
            const cd ht = cd(s.h0(n, m)) * std::exp(I * (w * t)) + std::conj(cd(s.h0(neg(n), neg(m)))) * std::exp(-I * (w * t));
            const double ik = k > 0 ? 1.0 / k : 0.0;
            for (int j = 0; j < N; ++j)
                for (int i = 0; i < N; ++i) {
                    const double x = i * L / N, z = j * L / N;
                    const cd e = ht * std::exp(I * (kx * x + kz * z));
                    const size_t p = size_t(j) * N + i;
                    r.h[p] += e;
                    r.dx[p] += -I * kx * ik * e;
                    r.dz[p] += -I * kz * ik * e;
                    r.sx[p] += I * kx * e;
                    r.sz[p] += I * kz * e;
                    r.dxx[p] += I * kx * (-I * kx * ik) * e;  // ∂/∂x of Dx
                    r.dzz[p] += I * kz * (-I * kz * ik) * e;
                    r.dxz[p] += I * kz * (-I * kx * ik) * e;
                }
        }
    return r;
}

double maxAbs(const std::vector<cd>& v) {
    double m = 0;
    for (const cd& x : v) m = std::max(m, std::abs(x));
    return m;
}

// max |got − Re(want)| relative to max |want|, and max |Im(want)| likewise.
void checkChannel(const float* got, size_t stride, const std::vector<cd>& want, const char* name) {
    const double scale = std::max(maxAbs(want), 1e-30);
    double err = 0, imag = 0;
    for (size_t p = 0; p < want.size(); ++p) {
        err = std::max(err, std::abs(double(got[p * stride]) - want[p].real()));
        imag = std::max(imag, std::abs(want[p].imag()));
    }
    INFO("channel " << name << ": max |FFT − DFT| / max = " << err / scale << ", max |Im DFT| / max = " << imag / scale);
    CHECK(err / scale < 2e-5);
    CHECK(imag / scale < 1e-9);  // Hermitian spectrum: every field is real
}

OceanDef roughSea(int n) {
    OceanDef def;
    def.resolution = n;
    def.patch_size = 40.0f;
    def.wind_speed = 6.0f;
    def.wind_direction = {0.8f, 0.6f};
    def.small_wave_cutoff = 0.01f;
    def.choppiness = 1.5f;
    def.seed = 9;
    return def;
}

// One wave: h̃0(K) = a at K = 2π(n, m)/L, nothing else. With eq. 1–2 this is
// h = 2|a| cos θ, θ = K·X + ωt + arg a (a wave travelling toward −K at ω/k).
struct SingleMode {
    int n, m;
    std::complex<float> a;
};

std::unique_ptr<OceanFftCpu> singleModeOcean(int N, float L, const SingleMode& mode, float choppiness = 1.0f) {
    OceanDef def;
    def.resolution = N;
    def.patch_size = L;
    def.choppiness = choppiness;
    auto ocean = std::make_unique<OceanFftCpu>(def);
    ocean->spectrum(0).clear();
    ocean->spectrum(0).setH0(mode.n, mode.m, mode.a);
    return ocean;
}

} // namespace

TEST_CASE("FFT maps equal a direct DFT of eq. 1 for all channels and the Jacobian (N = 8, 16)", "[ocean][fft]") {
    for (int n : {8, 16}) {
        OceanDef def = roughSea(n);
        def.cascades = 2;
        def.amplitude = 0.05f;
        OceanFftCpu ocean(def);
        for (double t : {0.0, 3.7, 1000.3}) {
            ocean.update(t);
            for (int c = 0; c < ocean.cascadeCount(); ++c) {
                INFO("N = " << n << ", t = " << t << ", cascade " << c);
                const Reference r = directDft(ocean.spectrum(c), t);
                REQUIRE(maxAbs(r.h) > 0);
                checkChannel(ocean.channel(c, OceanChannel::Height), 1, r.h, "h");
                checkChannel(ocean.channel(c, OceanChannel::DispX), 1, r.dx, "Dx");
                checkChannel(ocean.channel(c, OceanChannel::DispZ), 1, r.dz, "Dz");
                checkChannel(ocean.channel(c, OceanChannel::SlopeX), 1, r.sx, "dh/dx");
                checkChannel(ocean.channel(c, OceanChannel::SlopeZ), 1, r.sz, "dh/dz");
                checkChannel(ocean.packed(c, 0) + 1, 2, r.dxz, "dDx/dz");
                checkChannel(ocean.packed(c, 3), 2, r.dxx, "dDx/dx");
                checkChannel(ocean.packed(c, 3) + 1, 2, r.dzz, "dDz/dz");
                const double lambda = -def.choppiness;
                std::vector<cd> jac(r.h.size());
                for (size_t p = 0; p < jac.size(); ++p) {
                    const double a = 1 + lambda * r.dxx[p].real(), b = 1 + lambda * r.dzz[p].real(), x = lambda * r.dxz[p].real();
                    jac[p] = a * b - x * x;
                }
                checkChannel(ocean.channel(c, OceanChannel::Jacobian), 1, jac, "J");
            }
        }
    }
}

TEST_CASE("A single mode is a cosine travelling at the phase speed ω/k = sqrt(g/k) (eq. 1–3)", "[ocean][fft]") {
    const int N = 64;
    const float L = 100.0f;
    const SingleMode mode{3, 2, {0.3f, -0.4f}};  // |a| = 0.5: amplitude 1 m
    const auto oceanPtr = singleModeOcean(N, L, mode);
    OceanFftCpu& ocean = *oceanPtr;
    const double kx = 2 * PI * mode.n / L, kz = 2 * PI * mode.m / L, k = std::hypot(kx, kz);
    const double c = std::sqrt(9.81f / k);  // phase speed, m/s
    const double amp = 2 * std::abs(cd(mode.a)), phase0 = std::arg(cd(mode.a));
    for (double t : {0.0, 4.3}) {
        ocean.update(t);
        const float* h = ocean.channel(0, OceanChannel::Height);
        double err = 0;
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i) {
                // The crest line moved by c·t along −K̂: h(X, t) = h(X + K̂·c·t, 0).
                const double x = i * L / N + kx / k * c * t, z = j * L / N + kz / k * c * t;
                err = std::max(err, std::abs(h[j * N + i] - amp * std::cos(kx * x + kz * z + phase0)));
            }
        INFO("t = " << t);
        CHECK(err < 1e-5 * amp);
    }
}

TEST_CASE("Slopes of a single mode equal the analytic derivative of its cosine (eq. 6)", "[ocean][fft]") {
    const int N = 32;
    const float L = 50.0f;
    const SingleMode mode{-2, 5, {0.1f, 0.25f}};
    const auto oceanPtr = singleModeOcean(N, L, mode);
    OceanFftCpu& ocean = *oceanPtr;
    const double t = 2.2;
    ocean.update(t);
    const double kx = 2 * PI * mode.n / L, kz = 2 * PI * mode.m / L, k = std::hypot(kx, kz);
    const double amp = 2 * std::abs(cd(mode.a)), phase0 = std::arg(cd(mode.a)), w = std::sqrt(9.81f * k);
    const float* sx = ocean.channel(0, OceanChannel::SlopeX);
    const float* sz = ocean.channel(0, OceanChannel::SlopeZ);
    double err = 0;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const double theta = kx * i * L / N + kz * j * L / N + w * t + phase0;
            err = std::max(err, std::abs(sx[j * N + i] + amp * kx * std::sin(theta)));
            err = std::max(err, std::abs(sz[j * N + i] + amp * kz * std::sin(theta)));
        }
    CHECK(err < 1e-5 * amp * k);
}

TEST_CASE("Slopes agree with central finite differences of h on a fine grid (band-limited sea)", "[ocean][fft]") {
    OceanDef def;
    def.resolution = 256;
    def.patch_size = 100.0f;
    OceanFftCpu ocean(def);
    CascadeSpectrum& s = ocean.spectrum(0);
    s.clear();
    ob::ocean::GaussianRng rng(4);
    for (int m = -4; m <= 4; ++m)
        for (int n = -4; n <= 4; ++n)
            if (n || m) s.setH0(n, m, {float(0.1 * rng.next()), float(0.1 * rng.next())});
    ocean.update(1.3);
    const int N = def.resolution;
    const double dx = def.patch_size / N;
    const float* h = ocean.channel(0, OceanChannel::Height);
    const float* sx = ocean.channel(0, OceanChannel::SlopeX);
    const float* sz = ocean.channel(0, OceanChannel::SlopeZ);
    double err = 0, scale = 0;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const auto at = [&](int a, int b) { return double(h[((b + N) % N) * N + (a + N) % N]); };
            const double fx = (at(i + 1, j) - at(i - 1, j)) / (2 * dx);
            const double fz = (at(i, j + 1) - at(i, j - 1)) / (2 * dx);
            err = std::max({err, std::abs(fx - sx[j * N + i]), std::abs(fz - sz[j * N + i])});
            scale = std::max({scale, std::abs(double(sx[j * N + i])), std::abs(double(sz[j * N + i]))});
        }
    // Central differences err by (k·Δx)²/6 ≈ 0.2 % at the highest mode kept (|n| = 4·√2).
    CHECK(err < 5e-3 * scale);
}

TEST_CASE("Choppy displacement D points along K with the sign of eq. 7: D = (K/k)·2|a|·sin θ", "[ocean][fft]") {
    const int N = 32;
    const float L = 64.0f;
    const SingleMode mode{4, -3, {0.2f, 0.1f}};
    const auto oceanPtr = singleModeOcean(N, L, mode);
    OceanFftCpu& ocean = *oceanPtr;
    const double t = 0.9;
    ocean.update(t);
    const double kx = 2 * PI * mode.n / L, kz = 2 * PI * mode.m / L, k = std::hypot(kx, kz);
    const double amp = 2 * std::abs(cd(mode.a)), phase0 = std::arg(cd(mode.a)), w = std::sqrt(9.81f * k);
    const float* dx = ocean.channel(0, OceanChannel::DispX);
    const float* dz = ocean.channel(0, OceanChannel::DispZ);
    double err = 0;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const double theta = kx * i * L / N + kz * j * L / N + w * t + phase0;
            err = std::max(err, std::abs(dx[j * N + i] - kx / k * amp * std::sin(theta)));
            err = std::max(err, std::abs(dz[j * N + i] - kz / k * amp * std::sin(theta)));
            // Parallel to K: D × K = 0.
            err = std::max(err, std::abs(dx[j * N + i] * kz - dz[j * N + i] * kx) / k);
        }
    CHECK(err < 1e-5 * amp);
}

TEST_CASE("Parseval: the patch's mean square height equals Σ|h̃(K,t)|² (eq. 1 without 1/NM)", "[ocean][fft]") {
    OceanDef def = roughSea(64);
    OceanFftCpu ocean(def);
    for (double t : {0.0, 7.5}) {
        ocean.update(t);
        const int N = def.resolution;
        const float* h = ocean.channel(0, OceanChannel::Height);
        double ms = 0;
        for (int p = 0; p < N * N; ++p) ms += double(h[p]) * h[p];
        ms /= N * N;
        // h̃(K,t) from eq. 2 and ω = sqrt(g k), written out.
        const CascadeSpectrum& s = ocean.spectrum(0);
        double spectral = 0;
        for (int m = -N / 2 + 1; m < N / 2; ++m)
            for (int n = -N / 2 + 1; n < N / 2; ++n) {
                const double w = std::sqrt(def.gravity * 2 * PI / def.patch_size * std::hypot(n, m));
                const cd ht = cd(s.h0(n, m)) * std::exp(I * (w * t)) + std::conj(cd(s.h0(-n, -m))) * std::exp(-I * (w * t));
                spectral += std::norm(ht);
            }
        REQUIRE(spectral > 0);
        CHECK(ms == Approx(spectral).epsilon(1e-4));
    }
}

TEST_CASE("Jacobian: J = 1 for a flat sea", "[ocean][fft]") {
    OceanDef def;
    def.resolution = 32;
    def.choppiness = 3.0f;
    def.wind_speed = 0.0f;  // no wind, no waves
    OceanFftCpu ocean(def);
    ocean.update(12.0);
    const float* jac = ocean.channel(0, OceanChannel::Jacobian);
    const float* h = ocean.channel(0, OceanChannel::Height);
    for (int p = 0; p < 32 * 32; ++p) {
        REQUIRE(h[p] == 0.0f);
        REQUIRE(jac[p] == 1.0f);
    }
}

TEST_CASE("Jacobian: J = 1 − choppiness·k·A·cos θ for one wave, < 1 at the sharpened crest", "[ocean][fft]") {
    const int N = 64;
    const float L = 64.0f;
    const SingleMode mode{4, 0, {0.6f, 0.0f}};  // crest at x = 0 (θ = 0) at t = 0
    const float choppiness = 2.0f;
    const auto oceanPtr = singleModeOcean(N, L, mode, choppiness);
    OceanFftCpu& ocean = *oceanPtr;
    ocean.update(0.0);
    const double k = 2 * PI * mode.n / L, amp = 2 * 0.6;  // k·A = 0.47
    const float* jac = ocean.channel(0, OceanChannel::Jacobian);
    const float* dx = ocean.channel(0, OceanChannel::DispX);
    double err = 0;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) err = std::max(err, std::abs(jac[j * N + i] - (1 - choppiness * k * amp * std::cos(k * i * L / N))));
    CHECK(err < 1e-5);
    CHECK(jac[0] == Approx(1 - choppiness * k * amp).epsilon(1e-5));  // crest: 0.06
    CHECK(jac[0] < 1.0f);
    CHECK(jac[N / 8] > 1.0f);  // trough (θ = π at i = N/8): stretched
    // λ = −choppiness pulls the neighbours of a crest toward it: X + λD moves x = +δ back.
    CHECK(ocean.lambda() * dx[1] < 0.0f);
    CHECK(ocean.lambda() * dx[N - 1] > 0.0f);
}

TEST_CASE("update() gives bit-identical maps on 1 and 2 threads", "[ocean][fft]") {
    OceanDef def = roughSea(256);
    def.cascades = 2;
    OceanFftCpu one(def, 1), two(def, 2);
    one.update(5.25);
    two.update(5.25);
    const size_t bytes = size_t(256) * 256 * sizeof(float);
    for (int c = 0; c < 2; ++c)
        for (int ch = 0; ch < OCEAN_CHANNEL_COUNT; ++ch)
            CHECK(std::memcmp(one.channel(c, OceanChannel(ch)), two.channel(c, OceanChannel(ch)), bytes) == 0);
    for (int c = 0; c < 2; ++c)  // the velocity bands' maps
        for (int k = 0; k < one.velocityBands(c).transforms(); ++k)
            CHECK(std::memcmp(one.velocityPacked(c, k), two.velocityPacked(c, k), 2 * bytes) == 0);
}

// Not a test: the update's stages with and without the velocity bands, one 256² cascade (the
// default tile), medians of 21 updates. build/bin/tests_unit "[.ocean_stages]" -s
TEST_CASE("ocean update stages with and without the velocity bands", "[.ocean_stages]") {
    OceanDef def;
    for (const bool bands : {false, true}) {
        OceanFftCpu ocean(def, 1);
        ocean.setVelocityBands(bands);
        std::vector<double> stage[3];
        for (int i = 0; i < 21; ++i) {
            ocean.update(i / 60.0);
            const OceanFftCpu::StageMs& ms = ocean.lastStageMs();
            stage[0].push_back(ms.synthesis), stage[1].push_back(ms.transforms), stage[2].push_back(ms.unpack);
        }
        for (auto& s : stage) std::sort(s.begin(), s.end());
        std::printf("bands %s (%d transforms): synthesis %.3f ms, transforms %.3f ms, unpack %.3f ms\n", bands ? "on" : "off",
                    OCEAN_PACKED_TRANSFORMS + (bands ? ocean.velocityBands(0).transforms() : 0), stage[0][10], stage[1][10],
                    stage[2][10]);
    }
}

TEST_CASE("The dump layout: element [j, i, :] = (h, Dx, Dz, dh/dx, dh/dz) at X = (iL/N, jL/N)", "[ocean][fft]") {
    // What `dump ocean` writes (its file: tests/gl/test_dump_tools.cpp).
    OceanDef def = roughSea(16);
    OceanFftCpu ocean(def);
    ocean.update(2.0);
    std::vector<float> dump(16 * 16 * OCEAN_DUMP_CHANNELS);
    ocean.fillDump(0, dump.data());
    const Reference r = directDft(ocean.spectrum(0), 2.0);
    const std::vector<cd>* want[5] = {&r.h, &r.dx, &r.dz, &r.sx, &r.sz};
    const char* names[5] = {"h", "Dx", "Dz", "dh/dx", "dh/dz"};
    for (int ch = 0; ch < 5; ++ch) checkChannel(dump.data() + ch, 5, *want[ch], names[ch]);
}
