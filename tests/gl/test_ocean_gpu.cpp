// GPU spectral ocean (OceanFftGpu → OceanTextures) against FFTW (OceanFftCpu with the same
// def and seed), against a direct DFT of eq. 1 in double, and against the closed form of a
// single wave (eq. 2, 3, 6, 7); the CPU upload path (timings: tests/bench/bench_ocean.cpp).
#include "gfx/gl.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/sea_fade.h"
#include "ocean/gpu/ocean_fft_gpu.h"
#include "ocean/gpu/ocean_textures.h"
#include "platform/platform.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

using namespace ob;
using namespace ob::ocean;
using cd = std::complex<double>;

namespace {

// Float tolerance, relative to the peak of each channel (peak |J − 1| for the Jacobian): both
// backends round an O(N² log N) float computation (FFTW ~1e-7·sqrt(log2 N) rms; the radix-2/4
// DIT here up to log2 N roundings per output) from inputs that agree to float rounding. The
// worst error measured is 1.3e-6 at N ≤ 256 and 4e-6 at N = 2048; 2e-5 keeps a margin of 5–15
// and still catches a wrong index, sign, twiddle or phase (errors of order 1) and a phase
// formed in float (4e-4 at t = 1000 s).
constexpr double REL_TOL = 2e-5;

std::unique_ptr<platform::Platform> glContext() {
    gfx::requestDebugOutput(true);
    return platform::createHeadlessPlatform({16, 16});
}

// The GPU maps of one update(), read back: [layer][j][i][rgba].
struct GpuMaps {
    int n = 0;
    std::vector<float> displacement, slopes;
    // Channel ch of cascade c at texel p = j·N + i, in OceanChannel terms.
    float at(int c, OceanChannel ch, size_t p) const {
        const size_t base = (size_t(c) * size_t(n) * size_t(n) + p) * 4;
        switch (ch) {
        case OceanChannel::DispX: return displacement[base];
        case OceanChannel::Height: return displacement[base + 1];
        case OceanChannel::DispZ: return displacement[base + 2];
        case OceanChannel::Jacobian: return displacement[base + 3];
        case OceanChannel::SlopeX: return slopes[base];
        case OceanChannel::SlopeZ: return slopes[base + 1];
        }
        return 0.0f;
    }
};

GpuMaps readMaps(const OceanTextures& textures) {
    return {textures.resolution(), textures.readDisplacement(), textures.readSlopes()};
}

constexpr OceanChannel CHANNELS[OCEAN_CHANNEL_COUNT] = {OceanChannel::Height, OceanChannel::DispX,
                                                        OceanChannel::DispZ, OceanChannel::SlopeX,
                                                        OceanChannel::SlopeZ, OceanChannel::Jacobian};
const char* channelName(OceanChannel ch) {
    static const char* NAMES[] = {"h", "Dx", "Dz", "dh/dx", "dh/dz", "J"};
    return NAMES[int(ch)];
}

// Largest |gpu − reference| over a channel and the channel's scale (peak |value|, or peak
// |J − 1| for the Jacobian, which sits near 1).
struct Deviation {
    double maxError = 0.0, scale = 0.0;
};

template <class Reference>
Deviation deviation(const GpuMaps& gpu, int c, OceanChannel ch, Reference reference) {
    Deviation d;
    const double offset = ch == OceanChannel::Jacobian ? 1.0 : 0.0;
    for (size_t p = 0; p < size_t(gpu.n) * size_t(gpu.n); ++p) {
        const double ref = reference(p);
        d.scale = std::max(d.scale, std::abs(ref - offset));
        d.maxError = std::max(d.maxError, std::abs(double(gpu.at(c, ch, p)) - ref));
    }
    return d;
}

void checkDeviation(const Deviation& d, const char* what, OceanChannel ch, int c, double t) {
    INFO(what << ": cascade " << c << ", channel " << channelName(ch) << ", t = " << t << " s: max |error| "
              << d.maxError << ", scale " << d.scale << ", relative " << d.maxError / d.scale);
    CHECK(d.scale > 0.0);
    CHECK(d.maxError <= REL_TOL * d.scale);
}

// Eq. 1 written plainly in double for one cascade: f(X) = Σ_K F(K) exp(iK·X), X = (i·L/N,
// j·L/N), over every K of the grid, with h̃(K,t) from CascadeSpectrum::hTilde (eq. 2–3) and
// the channel spectra iK·h̃ (eq. 6), −i(K/k)·h̃ (eq. 7) and the derivatives of D; J from them.
struct DirectMaps {
    int n = 0;
    std::vector<double> channels[OCEAN_CHANNEL_COUNT];
};

DirectMaps directDft(const CascadeSpectrum& s, double t, double lambda) {
    const int N = s.resolution();
    const cd I(0.0, 1.0);
    DirectMaps out;
    out.n = N;
    for (auto& ch : out.channels) ch.assign(size_t(N) * N, 0.0);
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            cd h, dx, dz, sx, sz, dxx, dzz, dxz;
            for (int m = -N / 2; m < N / 2; ++m)
                for (int n = -N / 2; n < N / 2; ++n) {
                    const double kx = s.waveNumber(n), kz = s.waveNumber(m);
                    const double k = std::sqrt(kx * kx + kz * kz);
                    const double x = i * s.patchSize() / N, z = j * s.patchSize() / N;
                    const cd ht = s.hTilde(n, m, t) * std::exp(I * (kx * x + kz * z));
                    h += ht;
                    sx += I * kx * ht;
                    sz += I * kz * ht;
                    if (k > 0.0) {
                        dx += -I * (kx / k) * ht;
                        dz += -I * (kz / k) * ht;
                        dxx += (kx * kx / k) * ht;  // ∂/∂x of −i(kx/k)e^{iK·X} = (kx²/k)e^{iK·X}
                        dzz += (kz * kz / k) * ht;
                        dxz += (kx * kz / k) * ht;
                    }
                }
            const size_t p = size_t(j) * N + i;
            out.channels[int(OceanChannel::Height)][p] = h.real();
            out.channels[int(OceanChannel::DispX)][p] = dx.real();
            out.channels[int(OceanChannel::DispZ)][p] = dz.real();
            out.channels[int(OceanChannel::SlopeX)][p] = sx.real();
            out.channels[int(OceanChannel::SlopeZ)][p] = sz.real();
            out.channels[int(OceanChannel::Jacobian)][p] =
                (1.0 + lambda * dxx.real()) * (1.0 + lambda * dzz.real()) - std::pow(lambda * dxz.real(), 2);
        }
    return out;
}

// One h̃0 mode a at wave index (n0, m0) of an N-point, L-metre tile, every other mode 0:
// eq. 2 gives h̃(K) = a·e^{iωt}, h̃(−K) = conj(a)·e^{−iωt}, so h = 2|a|cos ψ, ψ = K·X + ωt + arg a,
// and eq. 6–7 give the closed forms below. Checks every channel at each t.
void checkSingleMode(int N, int n0, int m0, std::complex<float> a, std::initializer_list<double> times) {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    OceanDef def;
    def.resolution = N;
    def.wind_speed = 0.0f;  // calm: the constructor's own spectrum is replaced below anyway
    OceanFftGpu gpu(def);
    OceanTextures textures(N, 1);
    const double L = 20.0, g = 9.81;
    CascadeSpectrum spectrum(N, L, g);
    spectrum.setH0(n0, m0, a);
    gpu.setSpectrum(0, spectrum);
    const double kx = 2.0 * std::numbers::pi * n0 / L, kz = 2.0 * std::numbers::pi * m0 / L, k = std::hypot(kx, kz);
    const double omega = std::sqrt(g * k), amp = 2.0 * std::abs(std::complex<double>(a));
    const double phase0 = std::arg(std::complex<double>(a)), lambda = gpu.lambda();
    const size_t points = size_t(N) * size_t(N);
    std::vector<double> cosPsi(points), sinPsi(points);
    for (double t : times) {
        gpu.update(t, textures);
        const GpuMaps maps = readMaps(textures);
        for (size_t p = 0; p < points; ++p) {
            // ψ reduced in long double (ωt ≈ 1.1e3 rad at t = 1000 s).
            const long double x = (long double)(p % size_t(N)) * L / N, z = (long double)(p / size_t(N)) * L / N;
            const double psi = double(std::fmod(kx * x + kz * z + (long double)omega * t + phase0,
                                                2.0L * 3.14159265358979323846264338327950288L));
            cosPsi[p] = std::cos(psi);
            sinPsi[p] = std::sin(psi);
        }
        const auto expected = [&](OceanChannel ch, size_t p) {
            const double c = cosPsi[p], s = sinPsi[p];
            switch (ch) {
            case OceanChannel::Height: return amp * c;
            case OceanChannel::DispX: return amp * (kx / k) * s;  // −i(kx/k)·h̃ + c.c. = 2|a|(kx/k) sin ψ
            case OceanChannel::DispZ: return amp * (kz / k) * s;
            case OceanChannel::SlopeX: return -amp * kx * s;      // ∂h/∂x
            case OceanChannel::SlopeZ: return -amp * kz * s;
            case OceanChannel::Jacobian:
                return (1.0 + lambda * amp * kx * kx / k * c) * (1.0 + lambda * amp * kz * kz / k * c) -
                       std::pow(lambda * amp * kx * kz / k * c, 2);
            }
            return 0.0;
        };
        for (OceanChannel ch : CHANNELS) {
            INFO("N = " << N << ", mode (" << n0 << ", " << m0 << ")");
            checkDeviation(deviation(maps, 0, ch, [&](size_t p) { return expected(ch, p); }), "GPU vs closed form",
                           ch, 0, t);
        }
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

} // namespace

TEST_CASE("OceanTextures holds the CPU backend's channels unchanged, one layer per cascade", "[ocean_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    OceanDef def;
    def.resolution = 32;
    def.cascades = 2;
    OceanFftCpu cpu(def, 1);
    cpu.update(7.3);
    OceanTextures textures(def.resolution, def.cascades);
    CHECK(textures.mipLevels() == 6);
    textures.upload(cpu);
    textures.generateMipmaps();
    const GpuMaps maps = readMaps(textures);
    for (int c = 0; c < def.cascades; ++c)
        for (OceanChannel ch : CHANNELS) {
            const float* expected = cpu.channel(c, ch);
            size_t mismatches = 0;
            for (size_t p = 0; p < size_t(def.resolution) * def.resolution; ++p)
                mismatches += maps.at(c, ch, p) != expected[p];
            INFO("cascade " << c << ", channel " << channelName(ch));
            CHECK(mismatches == 0);
        }
    for (size_t p = 0; p < maps.slopes.size(); p += 4) {
        REQUIRE(maps.slopes[p + 2] == maps.displacement[p + 3]);  // J in both maps
        REQUIRE(maps.slopes[p + 3] == Approx(maps.slopes[p] * maps.slopes[p] + maps.slopes[p + 1] * maps.slopes[p + 1]).margin(1e-6));
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("the CPU backend's texels made beside its update draw as its maps uploaded and mipmapped by the driver", "[ocean_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    OceanDef def;
    def.resolution = 32;
    def.cascades = 2;
    OceanFftCpu cpu(def, 1);
    cpu.setMakeTexels(true);
    cpu.update(7.3);
    REQUIRE(cpu.texels() != nullptr);
    // The reference: level 0 from the channels, levels 1… by glGenerateTextureMipmap.
    OceanTextures driver(def.resolution, def.cascades), texels(def.resolution, def.cascades);
    driver.upload(cpu);
    driver.generateMipmaps();
    texels.upload(*cpu.texels());
    const auto read = [](const gfx::Texture& t, int level, int n, int layers) {
        std::vector<float> out(size_t(n) * size_t(n) * size_t(layers) * 4);
        glGetTextureImage(t.id(), level, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
        return out;
    };
    for (int level = 0; level < driver.mipLevels(); ++level) {
        const int n = def.resolution >> level;
        for (bool slopes : {false, true}) {
            const auto expected = read(slopes ? driver.slopes() : driver.displacement(), level, n, def.cascades);
            const auto actual = read(slopes ? texels.slopes() : texels.displacement(), level, n, def.cascades);
            double peak = 0.0, worst = 0.0;
            for (size_t p = 0; p < expected.size(); ++p) {
                peak = std::max(peak, double(std::abs(expected[p])));
                worst = std::max(worst, double(std::abs(actual[p] - expected[p])));
            }
            INFO("level " << level << (slopes ? ", slopes" : ", displacement") << ": worst " << worst << " of peak " << peak);
            if (level == 0) CHECK(worst == 0.0);  // the channels themselves
            else CHECK(worst <= 1e-6 * peak);     // a 2 × 2 mean, rounded in another order
        }
    }
    // The grid's reach from the extremes the texels' pass found: the same floats as a scan of the maps.
    OceanFftCpu plain(def, 1);
    plain.update(7.3);
    const DisplacementBounds made = cpu.displacementBounds(), scanned = plain.displacementBounds();
    CHECK(made.up == scanned.up);
    CHECK(made.down == scanned.down);
    CHECK(made.horizontal == scanned.horizontal);
    CHECK(made.up > 0.0f);
    // Off again: no texels after the next update.
    cpu.setMakeTexels(false);
    cpu.update(8.0);
    CHECK(cpu.texels() == nullptr);
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("the GPU inverse FFT of an N = 8 spectrum equals a direct DFT of eq. 1 in double for every channel",
          "[ocean_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    OceanDef def;
    def.resolution = 8;
    def.choppiness = 1.3f;
    OceanFftGpu gpu(def);
    OceanTextures textures(def.resolution, 1);
    // Every mode but the Nyquist row and column set by hand: h̃0(K) and h̃0(−K) independent.
    CascadeSpectrum spectrum(def.resolution, 12.0, 9.81);
    GaussianRng rng(42);
    for (int m = -3; m < 4; ++m)
        for (int n = -3; n < 4; ++n) spectrum.setH0(n, m, {float(0.1 * rng.next()), float(0.1 * rng.next())});
    gpu.setSpectrum(0, spectrum);
    for (double t : {0.0, 7.3, 1000.0}) {
        gpu.update(t, textures);
        const GpuMaps maps = readMaps(textures);
        const DirectMaps direct = directDft(spectrum, t, gpu.lambda());
        for (OceanChannel ch : CHANNELS)
            checkDeviation(deviation(maps, 0, ch, [&](size_t p) { return direct.channels[int(ch)][p]; }),
                           "GPU vs direct DFT", ch, 0, t);
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("one h̃0 mode gives h = 2|a|cos(K·X + ωt + arg a) with ω = sqrt(gk) and its eq. 6–7 derivatives (N = 8)",
          "[ocean_gpu]") {
    // K off the axes and not symmetric: a swapped x/z, sign or conjugate shows.
    checkSingleMode(8, 3, -1, {0.3f, -0.4f}, {0.0, 7.3, 1000.0});
}

TEST_CASE("the largest resolution, N = 2048 (one row fills 16 KiB of shared memory, odd log2 N), transforms a "
          "single wave exactly",
          "[ocean_gpu]") {
    checkSingleMode(2048, 37, -501, {-0.02f, 0.015f}, {7.3, 1000.0});
}

TEST_CASE("the GPU backend reproduces the CPU (FFTW) maps of every channel and both cascades at N = 16, 64, 256 "
          "and t = 0, 7.3, 1000 s",
          "[ocean_gpu]") {
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    const int n = GENERATE(16, 64, 256);
    OceanDef def;
    def.resolution = n;
    def.cascades = 2;
    def.seed = 7;
    OceanFftCpu cpu(def, 1);
    OceanFftGpu gpu(def);
    OceanTextures textures(n, def.cascades);
    REQUIRE(gpu.lambda() == cpu.lambda());
    for (int c = 0; c < def.cascades; ++c) REQUIRE(gpu.patchSize(c) == cpu.patchSize(c));
    for (double t : {0.0, 7.3, 1000.0}) {
        cpu.update(t);
        gpu.update(t, textures);
        const GpuMaps maps = readMaps(textures);
        for (int c = 0; c < def.cascades; ++c)
            for (OceanChannel ch : CHANNELS) {
                const float* expected = cpu.channel(c, ch);
                INFO("N = " << n);
                checkDeviation(deviation(maps, c, ch, [&](size_t p) { return double(expected[p]); }),
                               "GPU vs FFTW", ch, c, t);
            }
    }
    CHECK(gfx::glErrorCount() == errorsBefore);
}

TEST_CASE("the GPU backend rejects a resolution its shared-memory FFT cannot hold, naming the key", "[ocean_gpu]") {
    auto context = glContext();
    OceanDef def;
    def.resolution = 4096;
    CHECK_THROWS_WITH(OceanFftGpu(def), Catch::Contains("ocean.resolution"));
}

TEST_CASE("a live change of the sea reaches the GPU backend: mid-fade and after it, its maps are the CPU's",
          "[ocean_gpu][sea_live]") {
    // What view/water_view.cpp does each step of a fade: the CPU's blended h̃0 and λ handed to
    // the GPU FFT (setSpectrum, setLambda), which then synthesises the same sea.
    auto context = glContext();
    const int errorsBefore = gfx::glErrorCount();
    OceanDef def;
    def.resolution = 64;
    def.cascades = 2;
    def.wind_speed = 8.0f;
    OceanDef storm = def;
    storm.wind_speed = 20.0f;
    storm.wind_direction = {0.0f, 1.0f};
    storm.choppiness = 1.6f;
    OceanFftCpu cpu(def, 1);
    OceanFftGpu gpu(def);
    OceanTextures textures(def.resolution, def.cascades);
    const SeaFade fade(cpu, {}, storm, GerstnerDef{}, 1.0);
    for (double t : {2.0, 3.5}) {
        fade.apply(cpu, t);
        for (int c = 0; c < def.cascades; ++c) gpu.setSpectrum(c, cpu.spectrum(c));
        gpu.setLambda(cpu.lambda());
        cpu.update(t);
        gpu.update(t, textures);
        const GpuMaps maps = readMaps(textures);
        for (int c = 0; c < def.cascades; ++c)
            for (OceanChannel ch : CHANNELS) {
                const float* expected = cpu.channel(c, ch);
                checkDeviation(deviation(maps, c, ch, [&](size_t p) { return double(expected[p]); }), "GPU vs FFTW in a fade", ch, c, t);
            }
    }
    CHECK(gpu.lambda() == -storm.choppiness);
    CHECK(gfx::glErrorCount() == errorsBefore);
}
