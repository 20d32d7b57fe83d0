// Wave spectra, seeded h̃0(K) and the vectorised synthesis of h̃(K,t): docs/references.md#spectral-ocean eq. 2–7,
// [Lee2007] §2.1, [CodingTower]; JONSWAP after Hasselmann et al. 1973 (formulas in spectrum.h).
#include "core/error.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "ocean/fast_trig.h"
#include "ocean/spectrum.h"
#include "ocean/velocity_bands.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>


namespace ob::ocean {

namespace {

constexpr double PI = std::numbers::pi;
constexpr double TWO_PI = 2.0 * std::numbers::pi;
constexpr double INV_TWO_PI = 1.0 / TWO_PI;
// Adding and subtracting 1.5·2^52 rounds a double of magnitude < 2^51 to the nearest integer
// with plain arithmetic, which vectorises where std::nearbyint does not (SSE2).
constexpr double ROUND_MAGIC = 6755399441055744.0;
// Inner loops run on blocks of a compile-time length so that GCC's -O2 ("very cheap")
// vectoriser takes them; N ≥ 16 rows are whole blocks, smaller ones take the scalar tail.
constexpr int SPECTRUM_BLOCK = 16;

[[maybe_unused]] bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// Signed wave index of FFT-order position r in [0, N).
int signedIndex(int r, int n) { return r < n / 2 ? r : r - n; }

// sin and cos of ω·t, |error| < 1e-6 (float rounding): the phase is reduced in double to
// r ∈ [−π, π], then halfAngleSinCos (ocean/fast_trig.h).
[[gnu::always_inline]] inline void phaseSinCos(double omega, double t, float& s, float& c) {
    const double x = omega * t;
    const double turns = (x * INV_TWO_PI + ROUND_MAGIC) - ROUND_MAGIC;
    const float u = 0.5f * float(x - turns * TWO_PI);
    halfAngleSinCos(u, s, c);
}

// sin ωt and cos ωt for the columns n = 0 … N/2 of one |m| row of the quarter grid: ω
// depends on |kx| and |kz| only, so one quarter serves all four sign combinations.
OB_VECTOR_KERNEL
void phaseRow(const double* __restrict omega, float* __restrict sinOut, float* __restrict cosOut,
              double t, int count) {
    int base = 0;
    for (; base + SPECTRUM_BLOCK <= count; base += SPECTRUM_BLOCK)
        for (int q = 0; q < SPECTRUM_BLOCK; ++q) phaseSinCos(omega[base + q], t, sinOut[base + q], cosOut[base + q]);
    for (int i = base; i < count; ++i) phaseSinCos(omega[i], t, sinOut[i], cosOut[i]);
}

// One mode: h̃ (eq. 2) from the precomputed coefficients and sin/cos ωt, then the four packed
// products (PackedSpectra); o* point at interleaved (re, im) pairs.
[[gnu::always_inline]] inline void synthMode(
    const float* __restrict sinWt, const float* __restrict cosWt, const float* __restrict kxs,
    const float* __restrict invKs, const float* __restrict cosRe, const float* __restrict sinRe,
    const float* __restrict cosIm, const float* __restrict sinIm, float* __restrict o0,
    float* __restrict o1, float* __restrict o2, float* __restrict o3, float kz, int i) {
    const float s = sinWt[i], c = cosWt[i];
    const float hr = cosRe[i] * c + sinRe[i] * s;
    const float hi = cosIm[i] * c + sinIm[i] * s;
    const float kx = kxs[i];
    const float invK = invKs[i];
    const float ux = kx * invK;    // kx/k
    const float uz = kz * invK;    // kz/k
    const float dxz = kx * uz;     // kx·kz/k
    const float dxx = kx * ux;     // kx²/k
    const float dzz = kz * uz;     // kz²/k
    // h̃·(1 + i·kx·kz/k)
    o0[2 * i] = hr - hi * dxz;
    o0[2 * i + 1] = hi + hr * dxz;
    // h̃·(kz − i·kx)/k = −i(kx/k)h̃ + i·(−i(kz/k)h̃)
    o1[2 * i] = hr * uz + hi * ux;
    o1[2 * i + 1] = hi * uz - hr * ux;
    // h̃·(−kz + i·kx) = i·kx·h̃ + i·(i·kz·h̃)
    o2[2 * i] = -hr * kz - hi * kx;
    o2[2 * i + 1] = hr * kx - hi * kz;
    // h̃·(kx²/k + i·kz²/k)
    o3[2 * i] = hr * dxx - hi * dzz;
    o3[2 * i + 1] = hi * dxx + hr * dzz;
}

OB_VECTOR_KERNEL
void synthRow(const float* __restrict sinWt, const float* __restrict cosWt,
              const float* __restrict kx, const float* __restrict invK,
              const float* __restrict cosRe, const float* __restrict sinRe,
              const float* __restrict cosIm, const float* __restrict sinIm, float* __restrict o0,
              float* __restrict o1, float* __restrict o2, float* __restrict o3, float kz, int count) {
    int base = 0;
    for (; base + SPECTRUM_BLOCK <= count; base += SPECTRUM_BLOCK)
        for (int q = 0; q < SPECTRUM_BLOCK; ++q)
            synthMode(sinWt, cosWt, kx, invK, cosRe, sinRe, cosIm, sinIm, o0, o1, o2, o3, kz, base + q);
    for (int i = base; i < count; ++i)
        synthMode(sinWt, cosWt, kx, invK, cosRe, sinRe, cosIm, sinIm, o0, o1, o2, o3, kz, i);
}

} // namespace

// --- noise -----------------------------------------------------------------------------

GaussianRng::GaussianRng(std::uint64_t seed) : m_state(seed) {}

std::uint64_t GaussianRng::nextBits() {
    return splitmix64(m_state);
}

double GaussianRng::next() {
    if (m_hasSpare) {
        m_hasSpare = false;
        return m_spare;
    }
    // u1 ∈ (0, 1] (log is finite), u2 ∈ [0, 1), 53 random bits each.
    const double u1 = double((nextBits() >> 11) + 1) * 0x1.0p-53;
    const double u2 = double(nextBits() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double a = TWO_PI * u2;
    m_spare = r * std::sin(a);
    m_hasSpare = true;
    return r * std::cos(a);
}

std::complex<double> modeNoise(std::uint64_t seed, int cascade, int n, int m) {
    const std::uint64_t key = (std::uint64_t(std::uint32_t(n)) << 32) | std::uint32_t(m);
    GaussianRng rng(mix64(mix64(seed ^ (0xD1B54A32D192ED03ull * std::uint64_t(cascade + 1))) ^ key));
    const double xr = rng.next();
    const double xi = rng.next();
    return {xr, xi};
}

// --- spectra ---------------------------------------------------------------------------

SpectrumParams spectrumParams(const OceanDef& def) {
    SpectrumParams p;
    p.kind = def.spectrum;
    p.amplitude = def.amplitude;
    p.windSpeed = def.wind_speed;
    p.gravity = def.gravity;
    const double wx = def.wind_direction.x;
    const double wz = def.wind_direction.y;
    const double wl = std::sqrt(wx * wx + wz * wz);
    if (wl > 0.0) {
        p.windX = wx / wl;
        p.windZ = wz / wl;
    }
    p.largestWave = p.windSpeed * p.windSpeed / p.gravity;
    p.cutoff = def.small_wave_cutoff > 0.0f ? double(def.small_wave_cutoff) : 0.001 * p.largestWave;
    p.gamma = def.peak_enhancement;
    if (p.windSpeed > 0.0 && def.fetch > 0.0f) {
        const double v = p.windSpeed, f = def.fetch, g = p.gravity;
        p.alpha = 0.076 * std::pow(v * v / (f * g), 0.22);
        p.omegaPeak = 22.0 * std::cbrt(g * g / (v * f));
    }
    return p;
}

double phillips(double kx, double kz, double dk, const SpectrumParams& p) {
    const double k2 = kx * kx + kz * kz;
    if (k2 <= 0.0 || p.largestWave <= 0.0) return 0.0;
    const double kDotW = (kx * p.windX + kz * p.windZ);
    const double cos2 = kDotW * kDotW / k2;  // (K̂·ŵ)²
    const double kl = k2 * p.largestWave * p.largestWave;
    return p.amplitude * dk * dk * std::exp(-1.0 / kl) / (k2 * k2) * cos2 *
           std::exp(-k2 * p.cutoff * p.cutoff);
}

double jonswapFrequency(double omega, const SpectrumParams& p) {
    if (omega <= 0.0 || p.omegaPeak <= 0.0) return 0.0;
    const double g = p.gravity;
    const double wp = p.omegaPeak;
    const double sigma = omega <= wp ? 0.07 : 0.09;
    const double d = (omega - wp) / (sigma * wp);
    const double r = std::exp(-0.5 * d * d);
    const double ratio = wp / omega;
    const double ratio2 = ratio * ratio;
    const double w2 = omega * omega;
    return p.alpha * g * g / (w2 * w2 * omega) * std::exp(-1.25 * ratio2 * ratio2) * std::pow(p.gamma, r);
}

double jonswap(double kx, double kz, double dk, const SpectrumParams& p) {
    const double k2 = kx * kx + kz * kz;
    if (k2 <= 0.0) return 0.0;
    const double k = std::sqrt(k2);
    // The h̃0(K) wave travels toward −K (eq. 1–2), so the spreading looks at −K̂·ŵ.
    const double cosTheta = -(kx * p.windX + kz * p.windZ) / k;
    if (cosTheta <= 0.0) return 0.0;
    const double spread = 2.0 / PI * cosTheta * cosTheta;
    const double omega = std::sqrt(p.gravity * k);
    const double dOmegaDk = p.gravity / (2.0 * omega);
    const double sK = jonswapFrequency(omega, p) * dOmegaDk * spread / k;
    return 0.5 * sK * dk * dk * std::exp(-k2 * p.cutoff * p.cutoff);
}

double modeVariance(double kx, double kz, double dk, const SpectrumParams& p) {
    return p.kind == SpectrumKind::Jonswap ? jonswap(kx, kz, dk, p) : phillips(kx, kz, dk, p);
}

// --- cascades --------------------------------------------------------------------------

double cascadeSlopeVariance(const OceanDef& def, int cascade) {
    const SpectrumParams params = spectrumParams(def);
    const WaveBand band = cascadeBand(def, cascade);
    const double dk = TWO_PI / cascadePatchSize(def, cascade);
    const int half = def.resolution / 2;
    double sum = 0.0;
    for (int m = -half + 1; m < half; ++m)
        for (int n = -half + 1; n < half; ++n) {
            const double kx = dk * n, kz = dk * m, k2 = kx * kx + kz * kz;
            if (k2 < band.kMin * band.kMin || k2 >= band.kMax * band.kMax) continue;
            sum += k2 * (modeVariance(kx, kz, dk, params) + modeVariance(-kx, -kz, dk, params));
        }
    return sum;
}

std::array<double, 2> stokesDrift(const OceanDef& def) {
    const SpectrumParams params = spectrumParams(def);
    const int half = def.resolution / 2;
    double ux = 0.0, uz = 0.0;
    for (int c = 0; c < def.cascades; ++c) {
        const WaveBand band = cascadeBand(def, c);
        const double dk = TWO_PI / cascadePatchSize(def, c);
        for (int m = -half + 1; m < half; ++m)
            for (int n = -half + 1; n < half; ++n) {
                const double kx = dk * n, kz = dk * m, k2 = kx * kx + kz * kz;
                if (m < 0 || (m == 0 && n <= 0)) continue;  // K and −K together: an even spectrum sums to 0 exactly
                if (k2 < band.kMin * band.kMin || k2 >= band.kMax * band.kMax) continue;
                const double k = std::sqrt(k2), omega = std::sqrt(params.gravity * k);
                // ω·k·a²/|K| of the wave toward −K less that of the wave toward +K, times −K
                const double drift = 4.0 * omega * (modeVariance(kx, kz, dk, params) - modeVariance(-kx, -kz, dk, params));
                ux -= drift * kx, uz -= drift * kz;
            }
    }
    return {ux, uz};
}

double cascadePatchSize(const OceanDef& def, int cascade) {
    const double phi2 = std::numbers::phi * std::numbers::phi;
    return double(def.patch_size) / std::pow(phi2, cascade);
}

WaveBand cascadeBand(const OceanDef& def, int cascade) {
    const auto boundary = [&](int c) {  // between cascades c and c + 1
        return std::min(6.0 * TWO_PI / cascadePatchSize(def, c + 1),
                        PI * def.resolution / cascadePatchSize(def, c));
    };
    WaveBand band;
    band.kMin = cascade > 0 ? boundary(cascade - 1) : 0.0;
    band.kMax = cascade + 1 < def.cascades ? boundary(cascade) : std::numeric_limits<double>::infinity();
    return band;
}

// --- CascadeSpectrum -------------------------------------------------------------------

CascadeSpectrum::CascadeSpectrum(int resolution, double patchSize, double gravity)
    : m_n(resolution), m_patchSize(patchSize), m_gravity(gravity) {
    assert(isPowerOfTwo(resolution) && resolution >= 4);
    assert(patchSize > 0.0 && gravity > 0.0);
    const size_t count = size_t(m_n) * size_t(m_n);
    m_h0.assign(count, {0.0f, 0.0f});
    const int quarter = m_n / 2 + 1;
    m_omega.resize(size_t(quarter) * quarter);
    m_invK.resize(size_t(quarter) * quarter);
    m_k.resize(m_n);
    m_cosRe.assign(count, 0.0f);
    m_sinRe.assign(count, 0.0f);
    m_cosIm.assign(count, 0.0f);
    m_sinIm.assign(count, 0.0f);
    for (int r = 0; r < m_n; ++r) m_k[r] = float(waveNumber(signedIndex(r, m_n)));
    for (int m = 0; m < quarter; ++m) {
        for (int n = 0; n < quarter; ++n) {
            const double kx = waveNumber(n), kz = waveNumber(m);
            const double k = std::sqrt(kx * kx + kz * kz);
            m_omega[size_t(m) * quarter + n] = std::sqrt(m_gravity * k);
            m_invK[size_t(m) * quarter + n] = k > 0.0 ? float(1.0 / k) : 0.0f;
        }
    }
}

CascadeSpectrum::CascadeSpectrum(const OceanDef& def, int cascade)
    : CascadeSpectrum(def.resolution, cascadePatchSize(def, cascade), def.gravity) {
    const SpectrumParams params = spectrumParams(def);
    const WaveBand band = cascadeBand(def, cascade);
    const double dk = TWO_PI / m_patchSize;
    const int half = m_n / 2;
    // Rows in parallel (a live change of the sea builds a whole spectrum in one step): every
    // mode is a pure function of (seed, cascade, n, m), so the split changes no bit.
    parallelFor(-half + 1, half, 16, [&](int mBegin, int mEnd) {
        for (int m = mBegin; m < mEnd; ++m) {
            for (int n = -half + 1; n < half; ++n) {
                const double kx = waveNumber(n);
                const double kz = waveNumber(m);
                const double k = std::sqrt(kx * kx + kz * kz);
                if (k < band.kMin || k >= band.kMax) continue;
                const double ph = modeVariance(kx, kz, dk, params);
                if (ph <= 0.0) continue;
                const std::complex<double> xi = modeNoise(def.seed, cascade, n, m);
                m_h0[index(n, m)] = std::complex<float>(xi * std::sqrt(ph / 2.0));
            }
        }
    });
    parallelFor(0, m_n, 16, [&](int rowBegin, int rowEnd) {
        for (size_t idx = size_t(rowBegin) * m_n; idx < size_t(rowEnd) * m_n; ++idx) refreshMode(idx);
    });
}

double CascadeSpectrum::waveNumber(int n) const { return TWO_PI * n / m_patchSize; }

size_t CascadeSpectrum::index(int n, int m) const {
    assert(n >= -m_n / 2 && n < m_n / 2 && m >= -m_n / 2 && m < m_n / 2);
    const int col = n < 0 ? n + m_n : n;
    const int row = m < 0 ? m + m_n : m;
    return size_t(row) * m_n + col;
}

std::complex<float> CascadeSpectrum::h0(int n, int m) const { return m_h0[index(n, m)]; }

void CascadeSpectrum::setH0(int n, int m, std::complex<float> value) {
    assert(n > -m_n / 2 && m > -m_n / 2);
    m_h0[index(n, m)] = value;
    refreshMode(index(n, m));
    refreshMode(index(-n, -m));
}

void CascadeSpectrum::clear() {
    std::fill(m_h0.begin(), m_h0.end(), std::complex<float>(0.0f, 0.0f));
    for (size_t idx = 0; idx < m_h0.size(); ++idx) refreshMode(idx);
}

void CascadeSpectrum::blend(const CascadeSpectrum& from, const CascadeSpectrum& to, float s) {
    assert(from.m_n == m_n && to.m_n == m_n && from.m_patchSize == m_patchSize && to.m_patchSize == m_patchSize);
    if (s <= 0.0f || s >= 1.0f) {
        const CascadeSpectrum& whole = s <= 0.0f ? from : to;
        m_h0 = whole.m_h0;
        m_cosRe = whole.m_cosRe;
        m_sinRe = whole.m_sinRe;
        m_cosIm = whole.m_cosIm;
        m_sinIm = whole.m_sinIm;
        return;
    }
    const float r = 1.0f - s;
    for (size_t i = 0; i < m_h0.size(); ++i) m_h0[i] = r * from.m_h0[i] + s * to.m_h0[i];
    const auto mix = [&](std::vector<float>& out, const std::vector<float>& a, const std::vector<float>& b) {
        for (size_t i = 0; i < out.size(); ++i) out[i] = r * a[i] + s * b[i];
    };
    mix(m_cosRe, from.m_cosRe, to.m_cosRe);
    mix(m_sinRe, from.m_sinRe, to.m_sinRe);
    mix(m_cosIm, from.m_cosIm, to.m_cosIm);
    mix(m_sinIm, from.m_sinIm, to.m_sinIm);
}

double CascadeSpectrum::omega(int n, int m) const {
    assert(n >= -m_n / 2 && n < m_n / 2 && m >= -m_n / 2 && m < m_n / 2);
    return m_omega[size_t(std::abs(m)) * (m_n / 2 + 1) + size_t(std::abs(n))];
}

std::complex<double> CascadeSpectrum::hTilde(int n, int m, double t) const {
    const std::complex<double> a(m_h0[index(n, m)]);
    const int nm = n == -m_n / 2 ? n : -n;  // −(−N/2) aliases to −N/2 (always 0 there)
    const int mm = m == -m_n / 2 ? m : -m;
    const std::complex<double> b(m_h0[index(nm, mm)]);
    const double w = omega(n, m);
    return a * std::polar(1.0, w * t) + std::conj(b) * std::polar(1.0, -w * t);
}

void CascadeSpectrum::refreshMode(size_t idx) {
    const int row = int(idx / m_n);
    const int col = int(idx % m_n);
    const size_t mirror = size_t((m_n - row) % m_n) * m_n + size_t((m_n - col) % m_n);
    const float a = m_h0[idx].real(), b = m_h0[idx].imag();
    const float p = m_h0[mirror].real(), q = -m_h0[mirror].imag();  // conj(h̃0(−K))
    m_cosRe[idx] = a + p;
    m_sinRe[idx] = q - b;
    m_cosIm[idx] = b + q;
    m_sinIm[idx] = a - p;
}

int CascadeSpectrum::rowPairCount() const { return m_n / 2 + 1; }

void CascadeSpectrum::synthesize(double t, int pairBegin, int pairEnd, const PackedSpectra& out) const {
    assert(pairBegin >= 0 && pairEnd <= rowPairCount() && pairBegin <= pairEnd);
    const int quarter = m_n / 2 + 1;
    // sin ωt, cos ωt, 1/k along a whole row, filled from the quarter by |n| (scratch).
    std::vector<float> rowSin(m_n), rowCos(m_n), rowInvK(m_n);
    for (int m = pairBegin; m < pairEnd; ++m) {
        const size_t q = size_t(m) * quarter;
        phaseRow(m_omega.data() + q, rowSin.data(), rowCos.data(), t, quarter);
        std::copy_n(m_invK.data() + q, quarter, rowInvK.data());
        for (int c = quarter; c < m_n; ++c) {
            rowSin[c] = rowSin[m_n - c];
            rowCos[c] = rowCos[m_n - c];
            rowInvK[c] = rowInvK[m_n - c];
        }
        // Rows m and −m (FFT-order rows m and N − m; rows 0 and N/2 stand alone).
        const int rows[2] = {m, (m_n - m) % m_n};
        for (int k = 0; k < (rows[1] == rows[0] ? 1 : 2); ++k) {
            const int row = rows[k];
            const size_t off = size_t(row) * m_n;
            synthRow(rowSin.data(), rowCos.data(), m_k.data(), rowInvK.data(), m_cosRe.data() + off,
                     m_sinRe.data() + off, m_cosIm.data() + off, m_sinIm.data() + off,
                     out.heightDxz + 2 * off, out.dispXZ + 2 * off, out.slopeXZ + 2 * off,
                     out.dxxDzz + 2 * off, m_k[row], m_n);
        }
    }
}

// ∂h̃/∂t = ω·(sinRe·cos − cosRe·sin, sinIm·cos − cosIm·sin) from the eq. 2 coefficients along
// a row, with (1 − kx/k) and kz/k: what every velocity band of the row multiplies.
OB_VECTOR_KERNEL
void rateRow(const float* __restrict sinWt, const float* __restrict cosWt, const float* __restrict omega,
             const float* __restrict kx, const float* __restrict invK, const float* __restrict cosRe,
             const float* __restrict sinRe, const float* __restrict cosIm, const float* __restrict sinIm,
             float* __restrict dr, float* __restrict di, float* __restrict oneMinusUx, float* __restrict uz, float kz,
             int count) {
    for (int i = 0; i < count; ++i) {
        const float s = sinWt[i], c = cosWt[i], w = omega[i];
        dr[i] = w * (sinRe[i] * c - cosRe[i] * s);
        di[i] = w * (sinIm[i] * c - cosIm[i] * s);
        oneMinusUx[i] = 1.0f - kx[i] * invK[i];
        uz[i] = kz * invK[i];
    }
}

// Band b's (w_b, u_b) pair: Ŵ_b·(1 − kx/k) = Ŵ_b + i·(i·(kx/k)·Ŵ_b), Ŵ_b = g_b·∂h̃/∂t.
OB_VECTOR_KERNEL
void bandRow(const float* __restrict g, const float* __restrict dr, const float* __restrict di,
             const float* __restrict oneMinusUx, float* __restrict out, int count) {
    for (int i = 0; i < count; ++i) {
        const float f = g[i] * oneMinusUx[i];
        out[2 * i] = f * dr[i];
        out[2 * i + 1] = f * di[i];
    }
}

// Bands a and c's v pair: (kz/k)·(i·Ŵ_a − Ŵ_c) = i·(kz/k)·Ŵ_a + i·(i·(kz/k)·Ŵ_c).
OB_VECTOR_KERNEL
void bandPairRow(const float* __restrict ga, const float* __restrict gc, const float* __restrict dr,
                 const float* __restrict di, const float* __restrict uz, float* __restrict out, int count) {
    for (int i = 0; i < count; ++i) {
        out[2 * i] = uz[i] * (-gc[i] * dr[i] - ga[i] * di[i]);
        out[2 * i + 1] = uz[i] * (ga[i] * dr[i] - gc[i] * di[i]);
    }
}

void CascadeSpectrum::synthesizeVelocity(double t, int pairBegin, int pairEnd, const VelocityBands& bands,
                                         float* const* out) const {
    const int mapped = bands.mappedBands();
    if (mapped == 0) return;
    const int quarter = m_n / 2 + 1;
    const size_t plane = size_t(quarter) * size_t(quarter);
    assert(bands.quarter == quarter && pairBegin >= 0 && pairEnd <= rowPairCount());
    // Along a whole row, mirrored from the quarter by |n| (scratch): sin, cos, ω, 1/k, each
    // band's weight, then the row's rate terms.
    std::vector<float> scratch(size_t(m_n) * size_t(8 + mapped) + size_t(m_n));
    float* rowSin = scratch.data();
    float *rowCos = rowSin + m_n, *rowOmega = rowCos + m_n, *rowInvK = rowOmega + m_n, *dr = rowInvK + m_n;
    float *di = dr + m_n, *oneMinusUx = di + m_n, *uz = oneMinusUx + m_n, *zero = uz + m_n, *rowG = zero + m_n;
    const auto mirror = [&](float* row) {
        for (int c = quarter; c < m_n; ++c) row[c] = row[m_n - c];
    };
    for (int m = pairBegin; m < pairEnd; ++m) {
        const size_t q = size_t(m) * quarter;
        phaseRow(m_omega.data() + q, rowSin, rowCos, t, quarter);
        for (int c = 0; c < quarter; ++c) rowOmega[c] = float(m_omega[q + c]);
        std::copy_n(m_invK.data() + q, quarter, rowInvK);
        for (float* row : {rowSin, rowCos, rowOmega, rowInvK}) mirror(row);
        for (int b = 0; b < mapped; ++b) {
            float* g = rowG + size_t(b) * m_n;
            std::copy_n(bands.weights.data() + size_t(b) * plane + q, quarter, g);
            mirror(g);
        }
        const int rows[2] = {m, (m_n - m) % m_n};
        for (int r = 0; r < (rows[1] == rows[0] ? 1 : 2); ++r) {
            const size_t off = size_t(rows[r]) * m_n;
            rateRow(rowSin, rowCos, rowOmega, m_k.data(), rowInvK, m_cosRe.data() + off, m_sinRe.data() + off,
                    m_cosIm.data() + off, m_sinIm.data() + off, dr, di, oneMinusUx, uz, m_k[rows[r]], m_n);
            for (int b = 0; b < mapped; ++b) bandRow(rowG + size_t(b) * m_n, dr, di, oneMinusUx, out[b] + 2 * off, m_n);
            for (int b = 0; b < mapped; b += 2)
                bandPairRow(rowG + size_t(b) * m_n, b + 1 < mapped ? rowG + size_t(b + 1) * m_n : zero, dr, di, uz,
                            out[mapped + b / 2] + 2 * off, m_n);
        }
    }
}

void validateOceanDef(const OceanDef& def, int maxResolution) {
    std::string problems;
    const auto check = [&](bool ok, const char* key, const std::string& what) {
        if (!ok) problems += std::string(problems.empty() ? "" : "\n") + "ocean." + key + ": " + what;
    };
    const int n = def.resolution;
    check(n >= 4 && n <= maxResolution && (n & (n - 1)) == 0, "resolution",
          "must be a power of two in [4, " + std::to_string(maxResolution) + "], got " + std::to_string(n));
    check(def.cascades >= 1 && def.cascades <= 4, "cascades", "must be in [1, 4], got " + std::to_string(def.cascades));
    check(def.patch_size > 0.0f, "patch_size", "must be > 0 metres");
    check(def.gravity > 0.0f, "gravity", "must be > 0 m/s²");
    check(def.wind_speed >= 0.0f, "wind_speed", "must be >= 0 m/s");
    check(def.wind_direction.x != 0.0f || def.wind_direction.y != 0.0f, "wind_direction", "must not be [0, 0]");
    if (!problems.empty()) throw InputError(problems);
}

} // namespace ob::ocean
