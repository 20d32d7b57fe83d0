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
