// Gerstner waves: validation, spectrum-derived generation (after Thon et al. 2000) and the
// vectorised evaluation of docs/references.md#gerstner-waves ([Lee2007] eq. 8, [Min2023] §2; normal from ∂r/∂β × ∂r/∂α).
#include "core/simd.h"
#include "ocean/fast_trig.h"
#include "ocean/gerstner.h"

#include "core/log.h"
#include "ocean/spectrum.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <numbers>


namespace ob::ocean {

namespace {

constexpr double PI_D = std::numbers::pi;
constexpr double TAU = 2.0 * std::numbers::pi;
// SIMD width the kernels are written for: inner loops have this compile-time length so
// GCC's -O2 ("very cheap") vectoriser takes them (8 floats = one AVX2 register).
constexpr int LANES = 8;

// --- sin/cos ----------------------------------------------------------------------------

// sin θ and cos θ, branch-free so a loop of them vectorises; |error| < 1e-6 for |θ| < 4e5.
// θ is reduced to r ∈ [−π, π] with a two-part 2π (Cody–Waite: turns·C1 is exact for
// |turns| < 2^16), then the half angle u = r/2 goes through the Taylor polynomials of
// spectrum.cpp (first omitted terms < 6e-8) and the double-angle formulas.
constexpr float INV_TWO_PI_F = float(1.0 / TAU);
constexpr float ROUND_MAGIC_F = 12582912.0f;            // 1.5·2^23: (x + M) − M rounds |x| < 2^22
constexpr float TWO_PI_HI = 6.28125f;                   // 201/32, 8 significant bits
constexpr float TWO_PI_LO = float(TAU - 6.28125);    // 1.9353072e-3

[[gnu::always_inline]] inline void sinCos(float theta, float& s, float& c) {
    const float turns = (theta * INV_TWO_PI_F + ROUND_MAGIC_F) - ROUND_MAGIC_F;
    const float r = (theta - turns * TWO_PI_HI) - turns * TWO_PI_LO;
    const float u = 0.5f * r;
    halfAngleSinCos(u, s, c);
}

// --- kernels ----------------------------------------------------------------------------

// The SoA wave coefficients a kernel reads.
struct WaveArrays {
    const float *kx, *kz, *psi;
    const float *ax, *az, *a;
    const float *pxx, *pxz, *pzz;
    const float *qx, *qz;
    const float *wa, *wax, *waz;
};

// Twelve accumulators, one per GerstnerSums field, LANES wide.
struct Acc {
    float dx[LANES], dz[LANES], y[LANES];
    float pxx[LANES], pxz[LANES], pzz[LANES];
    float qx[LANES], qz[LANES];
    float vy[LANES], vx[LANES], vz[LANES];
};

// One wave's terms into lane q: θ from (α, β); coefficient index m. The first wave of a
// kernel assigns (so the accumulators need no zeroing pass), later ones add.
template <bool FIRST>
[[gnu::always_inline]] inline void accumulate(Acc& acc, int q, const WaveArrays& w, int m, float alpha, float beta) {
    const float theta = w.kx[m] * alpha + w.kz[m] * beta - w.psi[m];
    float s, c;
    sinCos(theta, s, c);
    const auto put = [](float& target, float value) {
        if constexpr (FIRST) target = value;
        else target += value;
    };
    put(acc.dx[q], -w.ax[m] * s);
    put(acc.dz[q], -w.az[m] * s);
    put(acc.y[q], w.a[m] * c);
    put(acc.pxx[q], w.pxx[m] * c);
    put(acc.pxz[q], w.pxz[m] * c);
    put(acc.pzz[q], w.pzz[m] * c);
    put(acc.qx[q], w.qx[m] * s);
    put(acc.qz[q], w.qz[m] * s);
    put(acc.vy[q], w.wa[m] * s);
    put(acc.vx[q], w.wax[m] * c);
    put(acc.vz[q], w.waz[m] * c);
}

// One point, vectorised over the waves: lane q takes waves q, q + LANES, … (padded count).
OB_VECTOR_KERNEL
void sumsOverWaves(const WaveArrays& w, int padded, float alpha, float beta, GerstnerSums* out) {
    assert(padded >= LANES && padded % LANES == 0);
    Acc acc;
    for (int q = 0; q < LANES; ++q) accumulate<true>(acc, q, w, q, alpha, beta);
    for (int base = LANES; base < padded; base += LANES)
        for (int q = 0; q < LANES; ++q) accumulate<false>(acc, q, w, base + q, alpha, beta);
    // Pairwise (tree) reduction of the lanes: three dependent adds instead of seven.
    const auto reduce = [](const float* f) {
        static_assert(LANES == 8);
        return ((f[0] + f[4]) + (f[2] + f[6])) + ((f[1] + f[5]) + (f[3] + f[7]));
    };
    GerstnerSums r;
    r.dx = reduce(acc.dx);
    r.dz = reduce(acc.dz);
    r.y = reduce(acc.y);
    r.pxx = reduce(acc.pxx);
    r.pxz = reduce(acc.pxz);
    r.pzz = reduce(acc.pzz);
    r.qx = reduce(acc.qx);
    r.qz = reduce(acc.qz);
    r.vy = reduce(acc.vy);
    r.vx = reduce(acc.vx);
    r.vz = reduce(acc.vz);
    *out = r;
}

// LANES points at once, vectorised over the points: every wave's coefficients broadcast.
// Wave m goes through the lanes in the same order as a scalar loop would (bit-equal lanes).
OB_VECTOR_KERNEL
void sumsOverPoints(const WaveArrays& w, int count, const float* __restrict alpha,
                    const float* __restrict beta, GerstnerSums* __restrict out) {
    assert(count >= 1);
    Acc acc;
    float a[LANES], b[LANES];
    for (int q = 0; q < LANES; ++q) {
        a[q] = alpha[q];
        b[q] = beta[q];
    }
    for (int q = 0; q < LANES; ++q) accumulate<true>(acc, q, w, 0, a[q], b[q]);
    for (int m = 1; m < count; ++m)
        for (int q = 0; q < LANES; ++q) accumulate<false>(acc, q, w, m, a[q], b[q]);
    for (int q = 0; q < LANES; ++q) {
        GerstnerSums& r = out[q];
        r.dx = acc.dx[q];
        r.dz = acc.dz[q];
        r.y = acc.y[q];
        r.pxx = acc.pxx[q];
        r.pxz = acc.pxz[q];
        r.pzz = acc.pzz[q];
        r.qx = acc.qx[q];
        r.qz = acc.qz[q];
        r.vy = acc.vy[q];
        r.vx = acc.vx[q];
        r.vz = acc.vz[q];
    }
}

GerstnerPoint toPoint(const GerstnerSums& s, float alpha, float beta) {
    GerstnerPoint p;
    p.position = {alpha + s.dx, s.y, beta + s.dz};
    p.normal = s.normal();
    p.verticalVelocity = s.vy;
    p.displacement = {s.dx, s.dz};
    return p;
}

// --- generation -------------------------------------------------------------------------

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
    char buffer[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    return buffer;
}

// Variance density F per d²K (m⁴) of waves travelling toward the angle `rel` from the wind
// with wave number k: 2·Ph/Δk² (spectrum.h), with Ph(K) + Ph(−K) folded onto the downwind
// half plane (Phillips is symmetric; JONSWAP's h̃0(K) travels toward −K, so its term is
// Ph(−K) and Ph(K) = 0 there).
struct TravelSpectrum {
    SpectrumParams p;
    double windAngle = 0.0;

    explicit TravelSpectrum(const OceanDef& ocean) : p(spectrumParams(ocean)), windAngle(std::atan2(p.windZ, p.windX)) {}

    double density(double k, double rel) const {
        if (std::abs(rel) >= 0.5 * PI_D) return 0.0;
        const double angle = windAngle + rel;
        const double kx = k * std::cos(angle), kz = k * std::sin(angle);
        return 2.0 * (modeVariance(kx, kz, 1.0, p) + modeVariance(-kx, -kz, 1.0, p));
    }
};

constexpr int ANGLES = 64;         // angular cells over (−π/2, π/2)
constexpr int RADII = 32;          // log-k quadrature points per bin
constexpr int TAIL_SAMPLES = 512;  // log-k points of the auto band search
constexpr double TAIL_SPAN = 1e-4; // the search looks down to kMax·TAIL_SPAN
constexpr double TAIL_FRACTION = 0.005;

// Variance of the cells (θ_j, [lnk0, lnk1]) of the travel spectrum, midpoint rule in ln k
// (∫ F k dk = ∫ F k² d ln k) and θ.
void cellVariance(const TravelSpectrum& s, double lnk0, double lnk1, double* out /*ANGLES*/) {
    const double dln = (lnk1 - lnk0) / RADII, dth = PI_D / ANGLES;
    for (int j = 0; j < ANGLES; ++j) out[j] = 0.0;
    for (int r = 0; r < RADII; ++r) {
        const double k = std::exp(lnk0 + (r + 0.5) * dln);
        for (int j = 0; j < ANGLES; ++j)
            out[j] += s.density(k, -0.5 * PI_D + (j + 0.5) * dth) * k * k * dln * dth;
    }
}

double uniform(GaussianRng& rng) { return double(rng.nextBits() >> 11) * 0x1.0p-53; }

} // namespace

// --- GerstnerSums -----------------------------------------------------------------------

glm::vec3 GerstnerSums::normalRaw() const {
    const float ax = 1.0f - pxx, az = 1.0f - pzz;  // ∂x/∂α, ∂z/∂β
    return {qz * pxz + qx * az, ax * az - pxz * pxz, pxz * qx + qz * ax};
}

glm::vec3 GerstnerSums::normal() const {
    const glm::vec3 n = normalRaw();
    return n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
}

glm::vec2 GerstnerSums::slope() const {
    const glm::vec3 n = normalRaw();
    return {-n.x / n.y, -n.z / n.y};
}

// --- validation -------------------------------------------------------------------------

double steepnessSum(std::span<const GerstnerWave> waves) {
    double sum = 0.0;
    for (const GerstnerWave& w : waves) sum += std::hypot(double(w.kx), double(w.kz)) * double(w.amplitude);
    return sum;
}

std::vector<std::string> validate(const GerstnerDef& def, const OceanDef* ocean, std::vector<std::string>* warnings) {
    std::vector<std::string> errors;
    for (size_t i = 0; i < def.waves.size(); ++i) {
        const GerstnerWave& w = def.waves[i];
        const double k = std::hypot(double(w.kx), double(w.kz));
        const double ka = k * w.amplitude;
        if (!(k > 0.0))
            errors.push_back(format("gerstner.waves[%zu]: wave vector [kx, kz] = [%g, %g]: a wave needs a non-zero wave vector (rad/m)",
                                    i, double(w.kx), double(w.kz)));
        else if (!(ka < 1.0))
            errors.push_back(format("gerstner.waves[%zu]: k·a = %.3g ≥ 1: the surface would self-intersect (k = %.3g rad/m, a = %g m)",
                                    i, ka, k, double(w.amplitude)));
    }
    if (def.min_wavelength > 0.0f && def.max_wavelength > 0.0f && !(def.max_wavelength > def.min_wavelength))
        errors.push_back(format("gerstner.max_wavelength: %g m must be longer than gerstner.min_wavelength (%g m)",
                                double(def.max_wavelength), double(def.min_wavelength)));

    std::vector<GerstnerWave> all = def.waves;
    if (ocean && def.count > 0 && errors.empty()) {
        const GerstnerBand band = generationBand(def, *ocean);
        if (!(band.kMin < band.kMax)) {
            errors.push_back(format("gerstner.max_wavelength: %g m must be longer than the shortest generated wave (%g m)",
                                    TAU / band.kMin, TAU / band.kMax));
        } else {
            const std::vector<GerstnerWave> generated = generateWaves(def, *ocean);
            for (size_t i = 0; i < generated.size(); ++i) {
                const double k = std::hypot(double(generated[i].kx), double(generated[i].kz));
                const double ka = k * generated[i].amplitude;
                if (!(ka < 1.0))
                    errors.push_back(format("gerstner.count: generated wave %zu (wavelength %.4g m): k·a = %.3g ≥ 1: the surface "
                                            "would self-intersect (lower gerstner.amplitude_scale)", i, TAU / k, ka));
            }
            all.insert(all.end(), generated.begin(), generated.end());
        }
    }
    const double sum = steepnessSum(all);
    if (errors.empty() && sum >= def.steepness_warning) {
        const std::string warning = format("gerstner: Σ k·a = %.3g ≥ %g (gerstner.steepness_warning): where the crests of "
                                           "several waves meet, the surface can self-intersect", sum, double(def.steepness_warning));
        logWarn("%s", warning.c_str());
        if (warnings) warnings->push_back(warning);
    }
    return errors;
}

// --- generation -------------------------------------------------------------------------

GerstnerBand generationBand(const GerstnerDef& def, const OceanDef& ocean) {
    GerstnerBand band;
    const double minWavelength = def.min_wavelength > 0.0f ? double(def.min_wavelength)
                                                           : std::sqrt(PI_D) * double(ocean.patch_size);
    band.kMax = TAU / minWavelength;
    if (def.max_wavelength > 0.0f) {
        band.kMin = TAU / double(def.max_wavelength);
        return band;
    }
    // Auto: the radial variance profile from kMax down to kMax·TAIL_SPAN (log grid); kMin is
    // the smallest k with at most TAIL_FRACTION of that variance below it, and at most kMax/2
    // (an octave at least, so the waves differ in length).
    const TravelSpectrum s(ocean);
    const double lnHi = std::log(band.kMax), lnLo = std::log(band.kMax * TAIL_SPAN);
    const double dln = (lnHi - lnLo) / TAIL_SAMPLES, dth = PI_D / ANGLES;
    std::vector<double> profile(TAIL_SAMPLES);  // variance of log cell i (i = 0 lowest k)
    double total = 0.0;
    for (int i = 0; i < TAIL_SAMPLES; ++i) {
        const double k = std::exp(lnLo + (i + 0.5) * dln);
        double v = 0.0;
        for (int j = 0; j < ANGLES; ++j) v += s.density(k, -0.5 * PI_D + (j + 0.5) * dth);
        profile[size_t(i)] = v * dth * k * k * dln;
        total += profile[size_t(i)];
    }
    double below = 0.0;
    int cut = 0;
    if (total > 0.0)
        while (cut < TAIL_SAMPLES && below + profile[size_t(cut)] <= TAIL_FRACTION * total) below += profile[size_t(cut++)];
    band.kMin = std::min(std::exp(lnLo + cut * dln), 0.5 * band.kMax);
    return band;
}

std::vector<GerstnerWave> generateWaves(const GerstnerDef& def, const OceanDef& ocean) {
    std::vector<GerstnerWave> waves;
    if (def.count <= 0) return waves;
    const GerstnerBand band = generationBand(def, ocean);
    if (!(band.kMin > 0.0 && band.kMin < band.kMax)) return waves;
    const TravelSpectrum s(ocean);
    GaussianRng rng(mix64(def.seed ^ 0x6A09E667F3BCC909ull));  // stream apart from the FFT's noise
    const double lnLo = std::log(band.kMin);
    const double width = (std::log(band.kMax) - lnLo) / def.count;
    const double dth = PI_D / ANGLES;
    double cells[ANGLES];
    for (int m = 0; m < def.count; ++m) {
        // --- variance of bin m, per angular cell
        const double ln0 = lnLo + m * width;
        cellVariance(s, ln0, ln0 + width, cells);
        double variance = 0.0;
        for (double c : cells) variance += c;
        // --- wave number, direction (inverse CDF over the cells, linear inside one), phase
        const double k = std::exp(ln0 + uniform(rng) * width);
        const double target = uniform(rng) * variance;
        double rel = 0.0;  // downwind when the bin holds no energy
        if (variance > 0.0) {
            double cumulative = 0.0;
            int j = 0;
            while (j < ANGLES - 1 && cumulative + cells[j] < target) cumulative += cells[j++];
            const double frac = cells[j] > 0.0 ? std::clamp((target - cumulative) / cells[j], 0.0, 1.0) : 0.5;
            rel = -0.5 * PI_D + (j + frac) * dth;
        }
        const double angle = s.windAngle + rel;
        GerstnerWave w;
        w.kx = float(k * std::cos(angle));
        w.kz = float(k * std::sin(angle));
        w.amplitude = float(def.amplitude_scale * std::sqrt(2.0 * variance));
        w.phase = float(TAU * uniform(rng));
        waves.push_back(w);
    }
    return waves;
}

std::vector<GerstnerWave> resolveWaves(const GerstnerDef& def, const OceanDef& ocean) {
    std::vector<GerstnerWave> waves = def.waves;
    const std::vector<GerstnerWave> generated = generateWaves(def, ocean);
    waves.insert(waves.end(), generated.begin(), generated.end());
    return waves;
}

// --- GerstnerField ----------------------------------------------------------------------

GerstnerField::GerstnerField(std::span<const GerstnerWave> waves, float gravity) {
    assert(gravity > 0.0f);
    for (const GerstnerWave& w : waves) {
        const double k = std::hypot(double(w.kx), double(w.kz));
        if (!(k > 0.0)) continue;
        const double a = w.amplitude, ux = w.kx / k, uz = w.kz / k;
        const double omega = std::sqrt(double(gravity) * k);
        m_kx.push_back(w.kx);
        m_kz.push_back(w.kz);
        m_psi.push_back(0.0f);
        m_omega.push_back(float(omega));
        m_k.push_back(float(k));
        m_ax.push_back(float(ux * a));
        m_az.push_back(float(uz * a));
        m_a.push_back(float(a));
        m_pxx.push_back(float(w.kx * ux * a));
        m_pxz.push_back(float(w.kx * uz * a));
        m_pzz.push_back(float(w.kz * uz * a));
        m_qx.push_back(float(w.kx * a));
        m_qz.push_back(float(w.kz * a));
        m_wa.push_back(float(omega * a));
        m_wax.push_back(float(omega * ux * a));
        m_waz.push_back(float(omega * uz * a));
        m_omegaD.push_back(omega);
        m_phaseD.push_back(w.phase);
    }
    m_count = int(m_kx.size());
    // Zero-amplitude padding to whole LANES blocks: every coefficient 0, so it adds nothing.
    m_padded = (m_count + LANES - 1) / LANES * LANES;
    for (auto* v : {&m_kx, &m_kz, &m_psi, &m_omega, &m_ax, &m_az, &m_a, &m_pxx, &m_pxz, &m_pzz, &m_qx, &m_qz,
                    &m_wa, &m_wax, &m_waz})
        v->resize(size_t(m_padded), 0.0f);
    setTime(0.0);
}

void GerstnerField::setTime(double t) {
    m_time = t;
    for (int m = 0; m < m_count; ++m)
        m_psi[size_t(m)] = float(std::remainder(m_omegaD[size_t(m)] * t + m_phaseD[size_t(m)], TAU));
}

GerstnerSums GerstnerField::sums(float alpha, float beta) const {
    GerstnerSums out;
    if (m_count == 0) return out;
    const WaveArrays w{m_kx.data(), m_kz.data(), m_psi.data(), m_ax.data(), m_az.data(), m_a.data(),
                       m_pxx.data(), m_pxz.data(), m_pzz.data(), m_qx.data(), m_qz.data(),
                       m_wa.data(), m_wax.data(), m_waz.data()};
    sumsOverWaves(w, m_padded, alpha, beta, &out);
    return out;
}

void GerstnerField::sums(const float* alpha, const float* beta, size_t count, GerstnerSums* out) const {
    if (m_count == 0) {
        std::fill(out, out + count, GerstnerSums{});
        return;
    }
    const WaveArrays w{m_kx.data(), m_kz.data(), m_psi.data(), m_ax.data(), m_az.data(), m_a.data(),
                       m_pxx.data(), m_pxz.data(), m_pzz.data(), m_qx.data(), m_qz.data(),
                       m_wa.data(), m_wax.data(), m_waz.data()};
    size_t p = 0;
    for (; p + LANES <= count; p += LANES) sumsOverPoints(w, m_count, alpha + p, beta + p, out + p);
    if (p < count) {  // tail: a zero-padded block, only the real points copied out
        float a[LANES] = {}, b[LANES] = {};
        GerstnerSums tail[LANES];
        std::copy(alpha + p, alpha + count, a);
        std::copy(beta + p, beta + count, b);
        sumsOverPoints(w, m_count, a, b, tail);
        std::copy(tail, tail + (count - p), out + p);
    }
}

glm::vec3 GerstnerField::velocity(float alpha, float beta, float depth) const {
    const float d = std::max(depth, 0.0f);
    glm::vec3 u(0.0f);
    for (int m = 0; m < m_count; ++m) {
        const size_t i = size_t(m);
        const float theta = m_kx[i] * alpha + m_kz[i] * beta - m_psi[i];
        const float decay = std::exp(-m_k[i] * d);
        const float c = std::cos(theta) * decay, s = std::sin(theta) * decay;
        u += glm::vec3(m_wax[i] * c, m_wa[i] * s, m_waz[i] * c);
    }
    return u;
}

GerstnerPoint GerstnerField::evaluate(float alpha, float beta) const { return toPoint(sums(alpha, beta), alpha, beta); }

void GerstnerField::evaluate(const float* alpha, const float* beta, size_t count, GerstnerPoint* out) const {
    constexpr size_t CHUNK = 256;
    GerstnerSums s[CHUNK];
    for (size_t p = 0; p < count; p += CHUNK) {
        const size_t n = std::min(CHUNK, count - p);
        sums(alpha + p, beta + p, n, s);
        for (size_t q = 0; q < n; ++q) out[p + q] = toPoint(s[q], alpha[p + q], beta[p + q]);
    }
}

} // namespace ob::ocean
