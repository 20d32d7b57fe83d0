// The dispersive ripple field (docs/references.md#dispersive-ripples) against theory: one Fourier mode follows
// cos(K·X)·cos(ωt) with deep-water capillary-gravity dispersion; the discrete energy is
// conserved without damping and decays at the documented rate with it; a drop's ring train
// has the Cauchy–Poisson wavenumber g·t²/(4r²). The reference ω and the energy are computed
// here (double-precision FFTW), not taken from the solver.
#include "core/parallel.h"
#include "core/thread_choice.h"
#include "interaction/ewave/ewave_field.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <fftw3.h>
#include <numbers>
#include <vector>

using ob::interaction::RippleBoundary;
using ob::interaction::EWaveField;

namespace {

constexpr double PI = std::numbers::pi;

// Deep water, capillary-gravity: ω² = g·k + (σ/ρ)·k³ with a default [environment]'s g = 9.81 m/s²,
// σ = 0.074 N/m and ρ = 1025 kg/m³ (a field's medium until told otherwise).
double omegaOf(double k) { return std::sqrt(9.81 * k + 0.074 / 1025.0 * k * k * k); }

// Σ over every mode K of the periodic grid of (|v̂|² + ω(|K|)²·|ĥ|²) / (rows·cols)²: twice the
// discrete wave energy per unit density (kinetic + potential), in double precision.
double energy(const EWaveField& f) {
    const int rows = f.rows(), cols = f.cols();
    const size_t n = size_t(rows) * size_t(cols);
    std::vector<std::complex<double>> h(n), v(n);
    for (size_t i = 0; i < n; ++i) {
        h[i] = f.heightState()[i];
        v[i] = f.velocityState()[i];
    }
    for (auto* a : {&h, &v}) {
        auto* p = reinterpret_cast<fftw_complex*>(a->data());
        fftw_plan plan = fftw_plan_dft_2d(rows, cols, p, p, FFTW_FORWARD, FFTW_ESTIMATE);
        fftw_execute(plan);
        fftw_destroy_plan(plan);
    }
    double e = 0.0;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const int jj = j <= rows / 2 ? j : j - rows, ii = i <= cols / 2 ? i : i - cols;
            const double kz = 2 * PI * jj / (rows * double(f.cellSize())), kx = 2 * PI * ii / (cols * double(f.cellSize()));
            const double w = omegaOf(std::hypot(kx, kz));
            const size_t m = size_t(j) * size_t(cols) + size_t(i);
            e += std::norm(v[m]) + w * w * std::norm(h[m]);
        }
    return e / (double(n) * double(n));
}

void setMode(EWaveField& f, int mx, int mz) {
    const int rows = f.rows(), cols = f.cols();
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x) {
            f.editHeight()[size_t(z) * cols + x] = float(std::cos(2 * PI * (double(mx) * x / cols + double(mz) * z / rows)));
            f.editVelocity()[size_t(z) * cols + x] = 0.0f;
        }
}

} // namespace

TEST_CASE("ewave: one Fourier mode evolves as cos(K·X)·cos(ωt) from the longest to the Nyquist mode", "[ewave]") {
    const int n = 32;
    for (double cell : {0.01, 0.1, 1.0, 10.0}) {
        EWaveField f(n, n, float(cell), RippleBoundary::Periodic);
        for (double hz : {30.0, 60.0, 240.0}) {
            const int steps = 40;
            const float dt = float(1.0 / hz);
            // Modes along x, along z and diagonal: the longest (1), short ones and Nyquist (n/2).
            const int modes[][2] = {{1, 0}, {0, 1}, {1, 1}, {3, 2}, {n / 4, 0}, {n / 2 - 1, 0}, {n / 2, 0}, {0, n / 2}, {n / 2, n / 2}};
            for (const auto& m : modes) {
                setMode(f, m[0], m[1]);
                for (int s = 0; s < steps; ++s) f.step(dt);
                const double k = 2 * PI / (n * cell) * std::hypot(m[0], m[1]);
                const double t = steps * double(dt);  // the step the solver took, in float
                const double c = std::cos(omegaOf(k) * t);
                double err = 0.0;
                for (int z = 0; z < n; ++z)
                    for (int x = 0; x < n; ++x) {
                        const double want = std::cos(2 * PI * (double(m[0]) * x / n + double(m[1]) * z / n)) * c;
                        err = std::max(err, std::abs(f.heightState()[size_t(z) * n + x] - want));
                    }
                INFO("cell " << cell << " m, " << hz << " Hz, mode (" << m[0] << ", " << m[1] << "), k = " << k
                             << " rad/m, ωt = " << omegaOf(k) * t);
                CHECK(err <= 1e-4);  // relative to the mode's amplitude, 1
            }
        }
    }
}

TEST_CASE("ewave: without damping the discrete energy is constant over 10,000 steps", "[ewave]") {
    const int n = 64;
    EWaveField f(n, n, 0.25f, RippleBoundary::Periodic);
    // Two Gaussian bumps in h (σ 3 and 2 cells) and a pair of opposite ones in v (no mean: a
    // mean v would raise the whole level forever): many modes at once.
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            auto g = [&](double cx, double cz, double s) { return std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / (2 * s * s)); };
            f.editHeight()[size_t(z) * n + x] = float(0.1 * g(20, 30, 3) - 0.05 * g(45, 12, 2));
            f.editVelocity()[size_t(z) * n + x] = 0.2 * (g(40, 40, 4) - g(12, 50, 4));
        }
    const double e0 = energy(f);
    double worst = 0.0;
    for (int block = 0; block < 10; ++block) {
        for (int s = 0; s < 1000; ++s) f.step(1.0f / 60.0f);
        worst = std::max(worst, std::abs(energy(f) / e0 - 1.0));
    }
    INFO("largest relative energy change " << worst);
    CHECK(worst <= 1e-5);
}

TEST_CASE("ewave: with damping the energy decays as exp(−2t/τ − 4νk²t)", "[ewave]") {
    const int n = 64;
    SECTION("decay time τ: every mode's energy falls as exp(−2t/τ)") {
        EWaveField f(n, n, 0.25f, RippleBoundary::Periodic);
        f.setDamping(2.0f, 0.0f);
        for (int z = 0; z < n; ++z)
            for (int x = 0; x < n; ++x)
                f.editHeight()[size_t(z) * n + x] = float(std::exp(-((x - 32.0) * (x - 32.0) + (z - 20.0) * (z - 20.0)) / 18.0));
        const double e0 = energy(f);
        const int steps = 180;  // 3 s at 60 Hz
        for (int s = 0; s < steps; ++s) f.step(1.0f / 60.0f);
        const double t = steps * double(1.0f / 60.0f);
        CHECK(energy(f) / e0 == Approx(std::exp(-2.0 * t / 2.0)).epsilon(1e-4));
    }
    SECTION("viscosity ν: a mode of wavenumber k falls as exp(−4νk²t), at any step rate") {
        for (double hz : {30.0, 240.0}) {
            EWaveField f(n, n, 0.25f, RippleBoundary::Periodic);
            f.setDamping(0.0f, 2e-3f);
            setMode(f, 8, 0);
            const double k = 2 * PI / (n * 0.25) * 8;
            const double e0 = energy(f);
            const int steps = int(2 * hz);  // 2 s
            for (int s = 0; s < steps; ++s) f.step(float(1.0 / hz));
            const double t = steps * double(float(1.0 / hz));
            CHECK(energy(f) / e0 == Approx(std::exp(-4.0 * 2e-3 * k * k * t)).epsilon(1e-4));
        }
    }
}

TEST_CASE("ewave: a drop's ring train has the Cauchy–Poisson wavenumber k = g·t²/(4r²)", "[ewave]") {
    // A narrow Gaussian drop (σ = 0.03 m) at the centre of a 512² field of 0.02 m cells; the
    // crossings of h = 0 along the +x ray give the local wavenumber: between crossings r_a < r_b
    // the phase g·t²/(4r) advances by π, so k = π/(r_b − r_a) at r = √(r_a·r_b) (the
    // point where the law's k averages over the interval). Checked where the grid resolves the
    // train and the law holds: at least 4 cells per half wave (k <= k_Nyquist/4), the gravity
    // range ((σ/ρ)·k²/g <= 0.5 %: capillarity speeds shorter waves up), far field (k·r >= 5),
    // outside the absorbing band.
    const int n = 512;
    const double cell = 0.02, sigma = 0.03;
    EWaveField f(n, n, float(cell), RippleBoundary::Absorbing, 24);
    const int c = n / 2;
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const double r2 = (double(x - c) * (x - c) + double(z - c) * (z - c)) * cell * cell;
            f.editHeight()[size_t(z) * n + x] = float(1e-3 * std::exp(-r2 / (2 * sigma * sigma)));
        }
    const float dt = 1.0f / 60.0f;
    int stepped = 0;
    for (double tWanted : {3.0, 4.0}) {
        while (stepped * double(dt) < tWanted - 1e-9) {
            f.step(dt);
            ++stepped;
        }
        const double t = stepped * double(dt);
        const double q = 9.81 * t * t / 4.0;
        std::vector<double> crossings;
        const double* row = f.heightState().data() + size_t(c) * n;
        for (int x = c + 1; x < n - 40; ++x)
            if ((row[x] > 0.0f) != (row[x + 1] > 0.0f))
                crossings.push_back((x - c + row[x] / (row[x] - row[x + 1])) * cell);
        int checked = 0;
        for (size_t i = 0; i + 1 < crossings.size(); ++i) {
            const double ra = crossings[i], rb = crossings[i + 1];
            const double r = std::sqrt(ra * rb), kTheory = q / (r * r), kMeasured = PI / (rb - ra);
            if (kTheory > PI / cell / 4.0 || 0.074 / 1025.0 * kTheory * kTheory / 9.81 > 0.005 || kTheory * r < 5.0) continue;
            INFO("t = " << t << " s, r = " << r << " m: k measured " << kMeasured << ", theory " << kTheory << " rad/m");
            CHECK(kMeasured == Approx(kTheory).epsilon(0.05));
            ++checked;
        }
        INFO("t = " << t << " s: " << crossings.size() << " crossings");
        CHECK(checked >= 4);
    }
}

TEST_CASE("ewave: scrolling moves h and v by whole cells, and the absorbing band keeps waves from wrapping", "[ewave]") {
    SECTION("scroll") {
        EWaveField f(16, 16, 0.5f, RippleBoundary::Fixed);  // new cells at 0, the volume recounted
        f.editHeight()[5 * 16 + 7] = 1.0;
        f.editVelocity()[5 * 16 + 7] = 2.0;
        f.scroll(2, -1);  // the value at (x+2, z−1) moves to (x, z)
        CHECK(f.heightAt(5, 6) == 1.0f);
        CHECK(f.height()[6 * 16 + 5] == 1.0f);
        CHECK(f.velocityAt(5, 6) == 2.0f);
        CHECK(f.heightAt(7, 5) == 0.0f);
    }
    SECTION("scroll keeps the volume (periodic, absorbing)") {
        // The bump moves; the 31 new cells come in at the mean level 1/256 (the far field the
        // sponge relaxes to) and the volume they add is taken back evenly: the bump stands 1
        // above the old cells, the new ones 1/256, and Σh stays 1 (docs/ewave.md#levels).
        EWaveField f(16, 16, 0.5f, RippleBoundary::Periodic);
        f.editHeight()[5 * 16 + 7] = 1.0;
        f.scroll(2, -1);
        CHECK(f.heightAt(5, 6) - f.heightAt(7, 5) == Approx(1.0f));
        double sum = 0.0;
        for (double h : f.heightState()) sum += h;
        CHECK(sum == Approx(1.0).epsilon(1e-15));
        CHECK(f.volume() == 1.0);
        CHECK(f.heightAt(15, 3) - f.heightAt(7, 5) == Approx(1.0f / 256.0f));  // a new cell and an old one
    }
    SECTION("absorbing") {
        // A bump left alone: periodic keeps its energy, absorbing loses nearly all of it once
        // the rings have crossed the band (0.25 m cells, 128², 30 s).
        double remaining[2];
        int idx = 0;
        for (RippleBoundary b : {RippleBoundary::Periodic, RippleBoundary::Absorbing}) {
            EWaveField f(128, 128, 0.25f, b, 24);
            for (int z = 0; z < 128; ++z)
                for (int x = 0; x < 128; ++x)
                    f.editHeight()[size_t(z) * 128 + x] = float(0.1 * std::exp(-((x - 64.0) * (x - 64.0) + (z - 64.0) * (z - 64.0)) / 8.0));
            const double e0 = energy(f);
            for (int s = 0; s < 1800; ++s) f.step(1.0f / 60.0f);
            remaining[idx++] = energy(f) / e0;
        }
        CHECK(remaining[0] == Approx(1.0).epsilon(1e-4));
        CHECK(remaining[1] < 0.05);
    }
}

TEST_CASE("ewave: many sources add Σ accel·dt·(1 − r²/R²)² per cell, the same bits on any worker count", "[ewave][parallel]") {
    // 3,000 sources (radius 1.5–20 cells, some clipped by the edges, sub-cell centres) on a
    // 96 × 128 field: enough footprint for the row bands to be split over the workers. The
    // reference is the biweight summed here per cell and source, in double. The field sums the
    // shares in float (u = 2^-24): per cell, n shares s_i of amplitudes a_i = accel·dt, each
    // weight (q − dx²)² off by at most 4u·|a_i| (q and dx² rounded, about 1) and each share and
    // sum rounded, so by recursive summation's bound (Higham, Accuracy and Stability, §4.2)
    // |error| ≤ u·(4·Σ|a_i| + (n + 1)·Σ|s_i|).
    const int rows = 96, cols = 128;
    std::vector<ob::interaction::EWaveSource> sources(3000);
    uint32_t state = 12345;
    auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / float(1 << 24); };
    for (auto& s : sources) {
        s.gx = -5.0f + 138.0f * next();
        s.gz = -5.0f + 106.0f * next();
        s.radiusCells = 1.5f + 18.5f * next();
        s.accel = 20.0f * next() - 10.0f;
    }
    const float dt = 1.0f / 60.0f;
    std::vector<double> want(size_t(rows) * cols, 0.0), bound(want.size(), 0.0), shares(want.size(), 0.0);
    std::vector<int> count(want.size(), 0);
    for (const auto& s : sources)
        for (int z = 0; z < rows; ++z)
            for (int x = 0; x < cols; ++x) {
                const double r2 = (x - double(s.gx)) * (x - double(s.gx)) + (z - double(s.gz)) * (z - double(s.gz));
                const double R2 = double(s.radiusCells) * double(s.radiusCells);
                if (r2 >= R2) continue;
                const size_t i = size_t(z) * cols + x;
                const double a = double(s.accel) * double(dt), share = a * (1 - r2 / R2) * (1 - r2 / R2);
                want[i] += share;
                shares[i] += std::abs(share);
                bound[i] += 4.0 * std::abs(a);
                ++count[i];
            }
    const double u = std::ldexp(1.0, -24);
    for (size_t i = 0; i < want.size(); ++i) bound[i] = u * (bound[i] + (count[i] + 1) * shares[i]) + 1e-300;
    double peak = 0.0;
    for (double w : want) peak = std::max(peak, std::abs(w));
    std::vector<double> first;
    ob::setThreadMeasuring(false);  // every worker count splits, whatever this machine measured
    for (int workers : {1, 2, 3}) {
        ob::setWorkerCount(workers);
        EWaveField f(rows, cols, 0.25f);
        f.addSources(sources, dt);
        double err = 0.0, worst = 0.0;  // the largest error, and the largest error / bound
        for (size_t i = 0; i < want.size(); ++i) {
            const double e = std::abs(f.velocityState()[i] - want[i]);
            err = std::max(err, e);
            worst = std::max(worst, e / bound[i]);
        }
        INFO(workers << " workers: largest error " << err << " of a peak " << peak << ", at most " << worst << " of its bound");
        CHECK(worst <= 1.0);
        std::vector<double> v(f.velocityState().begin(), f.velocityState().end());
        if (first.empty())
            first = v;
        else
            CHECK(v == first);
    }
    ob::setWorkerCount(0);
    ob::setThreadMeasuring(true);
}
