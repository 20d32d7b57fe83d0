// `oceanbox dump ocean`: the contract of the .npy (shape, channel order, layout) checked
// against spectral identities computed independently here with FFTW.
#include "core/npy.h"
#include "support/test_support.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <fftw3.h>
#include <vector>

using namespace ob;

namespace {

// d/dx (axis = 0) or d/dz (axis = 1) of a periodic N×N field of side L, by FFT: multiply
// the spectrum by i·k (Nyquist mode dropped), row j along z, column i along x.
std::vector<float> spectralDerivative(const std::vector<float>& f, int n, double L, int axis) {
    std::vector<std::complex<double>> a(size_t(n * n));
    for (size_t i = 0; i < a.size(); ++i) a[i] = f[i];
    auto* p = reinterpret_cast<fftw_complex*>(a.data());
    fftw_plan fwd = fftw_plan_dft_2d(n, n, p, p, FFTW_FORWARD, FFTW_ESTIMATE);
    fftw_plan inv = fftw_plan_dft_2d(n, n, p, p, FFTW_BACKWARD, FFTW_ESTIMATE);
    fftw_execute(fwd);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int m = axis == 0 ? i : j;
            int freq = m < n / 2 ? m : m - n;
            double k = 2.0 * M_PI * freq / L;
            if (m == n / 2) k = 0.0;
            a[size_t(j * n + i)] *= std::complex<double>(0.0, k) / double(n * n);
        }
    fftw_execute(inv);
    fftw_destroy_plan(fwd);
    fftw_destroy_plan(inv);
    std::vector<float> out(a.size());
    for (size_t i = 0; i < a.size(); ++i) out[i] = float(a[i].real());
    return out;
}

// Runs `dump ocean` on the default scene at time t with extra flags; returns [N, N, 5].
NpyArray dumpAt(double t, const std::string& flags) {
    std::string out = test::tempPath("ocean_t.npy");
    auto r = test::runOceanbox("dump ocean config/scenes/default.toml --time " + std::to_string(t) + " --out " + out + " " + flags);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return readNpy(out);
}

// Channel c of a dump as a complex spectrum: forward FFT (FFTW), divided by N² so that
// entry K is h̃(K) of eq. 1.
std::vector<std::complex<double>> spectrumOf(const NpyArray& a, int n, int c) {
    std::vector<std::complex<double>> s(size_t(n * n));
    for (size_t p = 0; p < s.size(); ++p) s[p] = a.data[p * 5 + size_t(c)];
    auto* ptr = reinterpret_cast<fftw_complex*>(s.data());
    fftw_plan plan = fftw_plan_dft_2d(n, n, ptr, ptr, FFTW_FORWARD, FFTW_ESTIMATE);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    for (auto& v : s) v /= double(n * n);
    return s;
}

} // namespace

TEST_CASE("dump ocean writes [N, N, 5] whose slope channels are the spectral derivatives of h", "[dump]") {
    const int n = 32;
    const double L = 100.0;
    std::string out = test::tempPath("ocean.npy");
    auto r = test::runOceanbox("dump ocean config/scenes/default.toml --time 3.5 --out " + out +
                               " --set ocean.resolution=32 --set ocean.patch_size=100 --set ocean.backend=cpu");
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    NpyArray a = readNpy(out);
    REQUIRE(a.shape == std::vector<size_t>{size_t(n), size_t(n), 5});
    std::vector<float> h(size_t(n * n)), sx(h.size()), sz(h.size());
    double mean = 0.0, rms = 0.0;
    for (size_t p = 0; p < h.size(); ++p) {
        h[p] = a.data[p * 5 + 0];
        sx[p] = a.data[p * 5 + 3];
        sz[p] = a.data[p * 5 + 4];
        mean += h[p];
        rms += double(h[p]) * h[p];
    }
    rms = std::sqrt(rms / double(h.size()));
    REQUIRE(rms > 1e-3);                              // a real sea, not a flat one
    CHECK(std::abs(mean / double(h.size())) < 1e-4 * rms + 1e-6);  // Ph(0) = 0: no mean level
    std::vector<float> dx = spectralDerivative(h, n, L, 0), dz = spectralDerivative(h, n, L, 1);
    double err = 0.0, scale = 0.0;
    for (size_t p = 0; p < h.size(); ++p) {
        err = std::max(err, double(std::abs(dx[p] - sx[p]) + std::abs(dz[p] - sz[p])));
        scale = std::max(scale, double(std::abs(sx[p]) + std::abs(sz[p])));
    }
    CHECK(err < 1e-3 * scale);
}

TEST_CASE("dump ocean rejects bad input with exit 2 naming the key", "[dump]") {
    std::string out = test::tempPath("bad.npy");
    auto r = test::runOceanbox("dump ocean config/scenes/default.toml --out " + out + " --set ocean.resolution=100");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("ocean.resolution: must be a power of two in [16, 2048], got 100") != std::string::npos);
    r = test::runOceanbox("dump waves config/scenes/default.toml --out " + out);
    CHECK(r.exitCode == 2);
    r = test::runOceanbox("dump ocean config/scenes/default.toml --out /no/such/dir/o.npy");
    CHECK(r.exitCode == 2);
    CHECK(r.output.find("cannot write output '/no/such/dir/o.npy'") != std::string::npos);
}

TEST_CASE("dispersion: every mode of dumped heights obeys h(K,t+d) + h(K,t-d) = 2 cos(w(k) d) h(K,t), w = sqrt(g k)", "[dump]") {
    const int n = 32;
    const double L = 64.0, g = 9.81, t = 4.0, d = 0.37;
    const std::string flags = "--set ocean.resolution=32 --set ocean.patch_size=64 --set ocean.wind_speed=8 --set ocean.cascades=1";
    auto before = spectrumOf(dumpAt(t - d, flags), n, 0);
    auto now = spectrumOf(dumpAt(t, flags), n, 0);
    auto after = spectrumOf(dumpAt(t + d, flags), n, 0);
    double peak = 0.0;
    for (auto& v : now) peak = std::max(peak, std::abs(v));
    int checked = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            size_t p = size_t(j * n + i);
            if (std::abs(now[p]) < 1e-3 * peak) continue;  // modes the spectrum left empty
            int fx = i < n / 2 ? i : i - n, fz = j < n / 2 ? j : j - n;
            double k = 2.0 * M_PI / L * std::sqrt(double(fx * fx + fz * fz));
            std::complex<double> lhs = before[p] + after[p], rhs = 2.0 * std::cos(std::sqrt(g * k) * d) * now[p];
            INFO("mode " << fx << ", " << fz);
            CHECK(std::abs(lhs - rhs) < 2e-4 * peak);
            ++checked;
        }
    CHECK(checked > 50);
}

TEST_CASE("dumped displacement is the spectral transform -iK/k of the dumped heights (eq. 7)", "[dump]") {
    const int n = 32;
    NpyArray a = dumpAt(2.5, "--set ocean.resolution=32 --set ocean.patch_size=100 --set ocean.cascades=1");
    auto h = spectrumOf(a, n, 0), dx = spectrumOf(a, n, 1), dz = spectrumOf(a, n, 2);
    double peak = 0.0, err = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            size_t p = size_t(j * n + i);
            int fx = i < n / 2 ? i : i - n, fz = j < n / 2 ? j : j - n;
            if (i == n / 2 || j == n / 2 || (fx == 0 && fz == 0)) continue;
            double k = std::sqrt(double(fx * fx + fz * fz));
            std::complex<double> ex = std::complex<double>(0.0, -fx / k) * h[p], ez = std::complex<double>(0.0, -fz / k) * h[p];
            err = std::max(err, std::abs(ex - dx[p]) + std::abs(ez - dz[p]));
            peak = std::max(peak, std::abs(h[p]));
        }
    CHECK(err < 1e-4 * peak);
}

TEST_CASE("dump ocean gives the same field on the cpu and gpu backends (within 1e-4 of the RMS)", "[dump]") {
    for (double t : {0.0, 3.3, 250.0}) {
        const std::string flags = "--set ocean.resolution=64 --set ocean.cascades=2 --set ocean.backend=";
        NpyArray cpu = dumpAt(t, flags + "cpu"), gpu = dumpAt(t, flags + "gpu");
        REQUIRE(cpu.shape == gpu.shape);
        for (int c = 0; c < 5; ++c) {
            double rms = 0.0, err = 0.0;
            for (size_t p = 0; p < cpu.data.size() / 5; ++p) {
                rms += double(cpu.data[p * 5 + size_t(c)]) * cpu.data[p * 5 + size_t(c)];
                err = std::max(err, double(std::abs(cpu.data[p * 5 + size_t(c)] - gpu.data[p * 5 + size_t(c)])));
            }
            rms = std::sqrt(rms / double(cpu.data.size() / 5));
            INFO("t " << t << " channel " << c);
            CHECK(err <= 1e-4 * rms);
        }
    }
}
