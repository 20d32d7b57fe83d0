// Composite water query: inversion of the horizontal displacement (Newton or fixed point),
// then height, slope-form normal (docs/references.md#composite-ocean) and Eulerian vertical velocity at the rest point.
#include "water/composite_water.h"

#include "core/parallel.h"
#include "ocean/ocean_fft_cpu.h"
#include "ocean/spectrum.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <utility>

namespace ob::water {

namespace {

// Newton steps need a well-conditioned J = ∂(x, z)/∂(α, β); below this det (a fold is near)
// the plain fixed-point step is taken instead.
constexpr float NEWTON_MIN_DET = 0.1f;
// det J or Gerstner n.y below this is treated as this (folded or folding surface), so a
// slope stays finite.
constexpr float MIN_DET = 1e-3f;
// Relative part of the stopping tolerance: a float world coordinate is exact to ~1.2e-7·|x|.
constexpr float RELATIVE_TOLERANCE = 4e-7f;
// Points per block of sampleBatch (Gerstner sums vectorised over them).
constexpr size_t BATCH = 64;

} // namespace

CompositeWater::CompositeWater(std::span<const ocean::GerstnerWave> waves, float gravity,
                               const ocean::OceanFftCpu* fft, CompositeSettings settings)
    : m_gerstner(waves, gravity), m_fft(fft), m_settings(settings) {
    assert(m_settings.maxIterations >= 1);
    if (!m_fft) return;
    const size_t count = size_t(m_fft->resolution()) * size_t(m_fft->resolution());
    m_cascades.resize(size_t(m_fft->cascadeCount()));
    for (int c = 0; c < m_fft->cascadeCount(); ++c) {
        Cascade& cas = m_cascades[size_t(c)];
        cas.invCell = float(m_fft->resolution() / m_fft->patchSize(c));
        for (auto& frame : cas.frames) frame.assign(3 * count, 0.0f);
        cas.rate.assign(4 * count, 0.0f);
    }
    measureWavenumbers();
}

void CompositeWater::measureWavenumbers() {
    if (!m_fft) return;
    for (int c = 0; c < m_fft->cascadeCount(); ++c) {
        // k_c = Σ k·ω²|h̃0|² / Σ ω²|h̃0|²: the wavenumber the cascade's velocity variance is centred on.
        const ocean::CascadeSpectrum& spectrum = m_fft->spectrum(c);
        const int n = spectrum.resolution();
        double weighted = 0.0, total = 0.0;
        for (int j = -n / 2; j < n / 2; ++j)
            for (int i = -n / 2; i < n / 2; ++i) {
                const double k = std::hypot(spectrum.waveNumber(i), spectrum.waveNumber(j));
                const double w = spectrum.omega(i, j);
                const double e = w * w * double(std::norm(spectrum.h0(i, j)));
                weighted += k * e;
                total += e;
            }
        m_cascades[size_t(c)].k = total > 0.0 ? float(weighted / total) : float(2.0 * M_PI / m_fft->patchSize(c));
    }
}

void CompositeWater::setRipple(RippleHook hook) { m_ripple = std::move(hook); }

void CompositeWater::setCurrent(CurrentHook hook) { m_current = std::move(hook); }

int CompositeWater::fftRateOrder() const { return m_fft ? std::max(m_frameCount - 1, 0) : 0; }

// --- update: time, and the FFT frame ring behind the rates --------------------------------

void CompositeWater::setWaves(std::span<const ocean::GerstnerWave> waves, float gravity) {
    const double t = m_gerstner.time();
    m_gerstner = ocean::GerstnerField(waves, gravity);
    m_gerstner.setTime(t);
}

void CompositeWater::update(double t) {
    m_gerstner.setTime(t);
    if (!m_fft) return;
    assert(std::abs(m_fft->time() - t) <= 1e-6 * std::max(1.0, std::abs(t)));
    recordFrame();
}

void CompositeWater::recordFrame() {
    const double tf = m_fft->time();
    if (m_frameCount > 0) {
        if (tf == m_frameTimes[size_t(m_newest)]) return;     // same maps as last time
        if (tf < m_frameTimes[size_t(m_newest)]) m_frameCount = 0;  // time went back: restart
    }
    const int slot = (m_newest + 1) % 3;
    const size_t count = size_t(m_fft->resolution()) * size_t(m_fft->resolution());
    for (size_t c = 0; c < m_cascades.size(); ++c) {
        float* frame = m_cascades[c].frames[size_t(slot)].data();
        std::memcpy(frame, m_fft->channel(int(c), ocean::OceanChannel::Height), count * sizeof(float));
        std::memcpy(frame + count, m_fft->channel(int(c), ocean::OceanChannel::DispX), count * sizeof(float));
        std::memcpy(frame + 2 * count, m_fft->channel(int(c), ocean::OceanChannel::DispZ), count * sizeof(float));
    }
    m_frameTimes[size_t(slot)] = tf;
    m_newest = slot;
    m_frameCount = std::min(m_frameCount + 1, 3);

    // Backward differences at the newest time t0 from t1 = t0 − h1, t2 = t1 − h2:
    // f'(t0) ≈ c0·f0 + c1·f1 + c2·f2, c0 = 1/h1 + 1/(h1+h2), c1 = −(h1+h2)/(h1·h2),
    // c2 = h1/(h2·(h1+h2)) (uniform h: 3/2h, −2/h, 1/2h); first order with two frames.
    const int s0 = m_newest, s1 = (m_newest + 2) % 3, s2 = (m_newest + 1) % 3;
    float c0 = 0.0f, c1 = 0.0f, c2 = 0.0f;
    if (m_frameCount == 2) {
        const double h1 = m_frameTimes[size_t(s0)] - m_frameTimes[size_t(s1)];
        c0 = float(1.0 / h1);
        c1 = -c0;
    } else if (m_frameCount == 3) {
        const double h1 = m_frameTimes[size_t(s0)] - m_frameTimes[size_t(s1)];
        const double h2 = m_frameTimes[size_t(s1)] - m_frameTimes[size_t(s2)];
        c0 = float(1.0 / h1 + 1.0 / (h1 + h2));
        c1 = float(-(h1 + h2) / (h1 * h2));
        c2 = float(h1 / (h2 * (h1 + h2)));
    }
    for (Cascade& cas : m_cascades) {
        const float* f0 = cas.frames[size_t(s0)].data();
        const float* f1 = cas.frames[size_t(s1)].data();
        const float* f2 = cas.frames[size_t(s2)].data();
        float* rate = cas.rate.data();
        for (size_t p = 0; p < count; ++p)
            for (size_t k = 0; k < 3; ++k) {
                const size_t q = k * count + p;
                rate[4 * p + k] = c0 * f0[q] + c1 * f1[q] + c2 * f2[q];
            }
    }
}

// --- FFT layer ------------------------------------------------------------------------

// Bilinear weights on cascade c's periodic tile (point (i, j) sits at X = (i, j)·L/N) and the
// gradient of the interpolant, per metre.
struct CompositeWater::Bilinear {
    size_t p00, p10, p01, p11;
    float fx, fz, w00, w10, w01, w11, invCell;

    Bilinear(float alpha, float beta, float inverseCell, int n) : invCell(inverseCell) {
        const long long mask = n - 1;
        const float u = alpha * invCell, v = beta * invCell;
        const float fu = std::floor(u), fv = std::floor(v);
        fx = u - fu;
        fz = v - fv;
        const long long iu = (long long)fu, iv = (long long)fv;
        const size_t i0 = size_t(iu & mask), i1 = size_t((iu + 1) & mask);
        const size_t j0 = size_t(iv & mask) * size_t(n), j1 = size_t((iv + 1) & mask) * size_t(n);
        p00 = j0 + i0;
        p10 = j0 + i1;
        p01 = j1 + i0;
        p11 = j1 + i1;
        w00 = (1 - fx) * (1 - fz);
        w10 = fx * (1 - fz);
        w01 = (1 - fx) * fz;
        w11 = fx * fz;
    }
    float value(const float* map, size_t stride, size_t k) const {
        return w00 * map[stride * p00 + k] + w10 * map[stride * p10 + k] + w01 * map[stride * p01 + k] +
               w11 * map[stride * p11 + k];
    }
    glm::vec2 gradient(const float* map, size_t stride, size_t k) const {
        const float v00 = map[stride * p00 + k], v10 = map[stride * p10 + k];
        const float v01 = map[stride * p01 + k], v11 = map[stride * p11 + k];
        return {((1 - fz) * (v10 - v00) + fz * (v11 - v01)) * invCell,
                ((1 - fx) * (v01 - v00) + fx * (v11 - v10)) * invCell};
    }
};

// Stage 1, every iteration: λ·D and the gradient of the bilinear λ·D (Newton's J).
float CompositeWater::lambda(WaterLayers layers) const {
    const float l = m_fft ? m_fft->lambda() : 0.0f;
    return layers.orbital ? std::clamp(l, -1.0f, 1.0f) : l;
}

void CompositeWater::addDisplacement(float alpha, float beta, FftTerms& t, float lambda) const {
    if (!m_fft) return;
    for (size_t c = 0; c < m_cascades.size(); ++c) {
        const Bilinear b(alpha, beta, m_cascades[c].invCell, m_fft->resolution());
        const float* disp = m_fft->packed(int(c), 1);  // (Dx, Dz) pairs
        const glm::vec2 gx = b.gradient(disp, 2, 0), gz = b.gradient(disp, 2, 1);
        t.dx += lambda * b.value(disp, 2, 0);
        t.dz += lambda * b.value(disp, 2, 1);
        t.jxx += lambda * gx.x;
        t.jxz += lambda * gx.y;
        t.jzx += lambda * gz.x;
        t.jzz += lambda * gz.y;
    }
}

// Stage 2, once at the rest point found: height, slopes, analytic ∂D, rates.
void CompositeWater::addSurface(float alpha, float beta, FftTerms& t, float lambda) const {
    if (!m_fft) return;
    const bool rates = m_frameCount >= 2;
    for (size_t c = 0; c < m_cascades.size(); ++c) {
        const Cascade& cas = m_cascades[c];
        const Bilinear b(alpha, beta, cas.invCell, m_fft->resolution());
        const int ci = int(c);
        const float* hDxz = m_fft->packed(ci, 0);  // (h, ∂Dx/∂z) pairs
        const float* slope = m_fft->packed(ci, 2); // (∂h/∂x, ∂h/∂z)
        const float* dd = m_fft->packed(ci, 3);    // (∂Dx/∂x, ∂Dz/∂z)
        const glm::vec2 gh = b.gradient(hDxz, 2, 0);
        t.h += b.value(hDxz, 2, 0);
        t.hx += gh.x;
        t.hz += gh.y;
        t.sx += b.value(slope, 2, 0);
        t.sz += b.value(slope, 2, 1);
        t.dxz += lambda * b.value(hDxz, 2, 1);
        t.dxx += lambda * b.value(dd, 2, 0);
        t.dzz += lambda * b.value(dd, 2, 1);
        if (rates) {
            const float ut = b.value(cas.rate.data(), 4, 1), vt = b.value(cas.rate.data(), 4, 2);
            t.ht += b.value(cas.rate.data(), 4, 0);
            t.ut -= ut;  // eq. 7's D points against the orbit (the surface drawn moves by λ·D, λ = −choppiness)
            t.vt -= vt;
            t.dxt += lambda * ut;
            t.dzt += lambda * vt;
        }
    }
}

CompositeWater::FftTerms CompositeWater::fftTerms(float alpha, float beta) const {
    FftTerms t;
    addDisplacement(alpha, beta, t, lambda({}));
    addSurface(alpha, beta, t, lambda({}));
    return t;
}

// --- inversion and the sample ---------------------------------------------------------

// Residual of rest point `rest` for target (x, z); returns true when within tolerance, else
// (if move) moves rest one Newton or fixed-point step.
bool CompositeWater::step(const Eval& e, float x, float z, glm::vec2& rest, float& residual, float looser) const {
    const float rx = rest.x + e.g.dx + e.f.dx - x;
    const float rz = rest.y + e.g.dz + e.f.dz - z;
    residual = std::sqrt(rx * rx + rz * rz);
    const float tolerance =
        std::max({m_settings.tolerance, looser, RELATIVE_TOLERANCE * std::max(std::abs(x), std::abs(z))});
    if (residual <= tolerance) return true;
    if (m_settings.inversion == CompositeSettings::Inversion::Newton) {
        // J = ∂(x, z)/∂(α, β) of the surface as sampled: [[axx, axz], [azx, azz]].
        const float axx = 1.0f - e.g.pxx + e.f.jxx, axz = -e.g.pxz + e.f.jxz;
        const float azx = -e.g.pxz + e.f.jzx, azz = 1.0f - e.g.pzz + e.f.jzz;
        const float det = axx * azz - axz * azx;
        if (det > NEWTON_MIN_DET) {
            rest.x -= (azz * rx - axz * rz) / det;
            rest.y -= (axx * rz - azx * rx) / det;
            return false;
        }
    }
    rest.x -= rx;  // α ← x − D(α)
    rest.y -= rz;
    return false;
}

WaterSample CompositeWater::finish(const Eval& e, float x, float z, WaterLayers layers) const {
    const ocean::GerstnerSums& g = e.g;
    const FftTerms& f = e.f;
    WaterSample s;
    s.height = g.y + f.h;

    // ∂height/∂t at fixed (x, z) = ∂y/∂t − s·∂D/∂t at the rest point, s = J^-T ∇_α y the world
    // slope of the surface as sampled (J = ∂(x, z)/∂(α, β) = [[axx, axz], [azx, azz]]).
    {
        const float axx = 1.0f - g.pxx + f.jxx, axz = -g.pxz + f.jxz;
        const float azx = -g.pxz + f.jzx, azz = 1.0f - g.pzz + f.jzz;
        const float det = std::max(axx * azz - axz * azx, MIN_DET);
        const float yx = -g.qx + f.hx, yz = -g.qz + f.hz;  // ∇_α y
        const float sx = (azz * yx - azx * yz) / det, sz = (axx * yz - axz * yx) / det;
        s.verticalVelocity = g.vy + f.ht - (sx * (g.vx + f.dxt) + sz * (g.vz + f.dzt));
    }
    // The particle's own velocity (bounded at folds, unlike the Eulerian rate above).
    s.velocity = {g.vx + f.ut, g.vy + f.ht, g.vz + f.vt};
    if (layers.currents && m_current) {
        const glm::vec2 u = m_current(x, z);
        s.velocity.x += u.x;
        s.velocity.z += u.y;
    }

    glm::vec2 slope;
    if (m_settings.normal == CompositeSettings::Normal::Exact) {
        // J^-T ∇_α y with the FFT's analytic derivative maps (J symmetric then).
        const float jxx = 1.0f - g.pxx + f.dxx, jxz = -g.pxz + f.dxz, jzz = 1.0f - g.pzz + f.dzz;
        const float det = std::max(jxx * jzz - jxz * jxz, MIN_DET);
        const float yx = -g.qx + f.sx, yz = -g.qz + f.sz;
        slope = glm::vec2{(jzz * yx - jxz * yz) / det, (jxx * yz - jxz * yx) / det};
    } else {  // docs/references.md#composite-ocean: Gerstner world slope (−n.xz/n.y) + FFT slope maps
        const glm::vec3 n = g.normalRaw();
        const float ny = std::max(n.y, MIN_DET);
        slope = glm::vec2{-n.x / ny + f.sx, -n.z / ny + f.sz};
    }

    if (layers.ripples && m_ripple.height) {
        s.height += m_ripple.height(x, z);
        if (m_ripple.slope) {
            slope += m_ripple.slope(x, z);
        } else {
            const float d = m_ripple.slopeStep;
            slope += glm::vec2{m_ripple.height(x + d, z) - m_ripple.height(x - d, z),
                               m_ripple.height(x, z + d) - m_ripple.height(x, z - d)} / (2.0f * d);
        }
        if (m_ripple.rate) {
            const float w = m_ripple.rate(x, z);
            s.verticalVelocity += w;
            s.velocity.y += w;
        }
        if (m_ripple.horizontalVelocity) {
            const glm::vec2 u = m_ripple.horizontalVelocity(x, z);
            s.velocity.x += u.x;
            s.velocity.z += u.y;
        }
    }
    const float inv = 1.0f / std::sqrt(slope.x * slope.x + 1.0f + slope.y * slope.y);
    s.normal = {-slope.x * inv, inv, -slope.y * inv};
    return s;
}

RestPoint CompositeWater::restPoint(float x, float z) const {
    RestPoint r;
    r.rest = {x, z};
    for (r.iterations = 1;; ++r.iterations) {
        Eval e{m_gerstner.sums(r.rest.x, r.rest.y), {}};
        addDisplacement(r.rest.x, r.rest.y, e.f, lambda({}));
        glm::vec2 moved = r.rest;
        if (step(e, x, z, moved, r.residual) || r.iterations >= m_settings.maxIterations) return r;
        r.rest = moved;
    }
}

// Finds the rest point under (x, z) of the layers asked; done(eval with the surface terms, α, β).
template <class Done>
void CompositeWater::invert(float x, float z, WaterLayers layers, Done&& done) const {
    glm::vec2 rest{x, z};
    for (int it = 1;; ++it) {
        Eval e{layers.gerstner ? m_gerstner.sums(rest.x, rest.y) : ocean::GerstnerSums{}, {}};
        if (layers.fft) addDisplacement(rest.x, rest.y, e.f, lambda(layers));
        glm::vec2 moved = rest;
        float residual;
        if (step(e, x, z, moved, residual) || it >= m_settings.maxIterations) {
            if (layers.fft) addSurface(rest.x, rest.y, e.f, lambda(layers));
            done(e, rest.x, rest.y);
            return;
        }
        rest = moved;
    }
}

WaterSample CompositeWater::sample(float x, float z, WaterLayers layers) const {
    WaterSample s;
    invert(x, z, layers, [&](const Eval& e, float, float) { s = finish(e, x, z, layers); });
    return s;
}

glm::vec3 CompositeWater::velocityBelow(const Eval& e, float alpha, float beta, glm::vec3 p, WaterLayers layers) const {
    glm::vec3 u(0.0f);
    float surface = e.g.y + e.f.h;
    if (layers.ripples && m_ripple.height) surface += m_ripple.height(p.x, p.z);
    const float depth = std::max(surface - p.y, 0.0f);
    // Where each part's e^{kz} counts z from. A Lagrangian part (Gerstner; the cascades at
    // choppiness ≥ 1) moves a particle of rest depth b on an orbit scaled by e^{−k·b}, and
    // the particle under the surface by `depth` has b ≈ depth. An Eulerian part (the
    // ripples; the cascades at choppiness 0) has its velocity field e^{kz} with z from its
    // own mean level, so a point on a crest of height η reads e^{k·η} (linear theory's
    // extrapolation, which gives the Stokes drift its second half, ⟨ζ·∂u/∂z⟩).
    const float lagrangian = std::min(std::abs(lambda(layers)), 1.0f);
    const float ripple = layers.ripples && m_ripple.height ? m_ripple.height(p.x, p.z) : 0.0f;
    const float eulerianZ = (1.0f - lagrangian) * e.f.h + ripple - depth;  // z of the Eulerian parts, m
    if (layers.gerstner) u += m_gerstner.velocity(alpha, beta, depth);
    if (layers.fft && m_fft && m_frameCount >= 2) {
        const float z = lagrangian * -depth + (1.0f - lagrangian) * eulerianZ;
        for (size_t c = 0; c < m_cascades.size(); ++c) u += cascadeVelocity(int(c), alpha, beta, z);
    }
    if (layers.ripples && m_ripple.height) {
        const float decay = m_ripple.wavenumber ? std::exp(m_ripple.wavenumber() * eulerianZ) : 1.0f;
        const glm::vec2 h = m_ripple.horizontalVelocity ? m_ripple.horizontalVelocity(p.x, p.z) : glm::vec2(0.0f);
        const float w = m_ripple.rate ? m_ripple.rate(p.x, p.z) : 0.0f;
        u += decay * glm::vec3(h.x, w, h.y);
    }
    if (layers.currents && m_current) {
        const glm::vec2 c = m_current(p.x, p.z);
        u += glm::vec3(c.x, 0.0f, c.y);
    }
    return u;
}

// Cascade c's velocity at rest point (α, β), z metres above its mean level (≤ 0 below). Below:
// per band, Σ_b e^{k_b·z}·U_b = e^{k_B·z}·U + Σ_{b<B} (e^{k_b·z} − e^{k_B·z})·U_b with U the whole
// cascade's velocity (the rates) and U_b the maps of the bands that have them (the last band is
// U less the others), exact at z = 0. Above (an Eulerian crest), and without band maps: the
// whole cascade × e^{k_c·z}, linear theory's extrapolation with its mean wavenumber.
glm::vec3 CompositeWater::cascadeVelocity(int c, float alpha, float beta, float z) const {
    const Cascade& cas = m_cascades[size_t(c)];
    const Bilinear b(alpha, beta, cas.invCell, m_fft->resolution());
    const glm::vec3 whole(-b.value(cas.rate.data(), 4, 1), b.value(cas.rate.data(), 4, 0), -b.value(cas.rate.data(), 4, 2));
    const ocean::VelocityBands& bands = m_fft->velocityBands(c);
    const int mapped = bands.mappedBands();
    if (z > 0.0f || (mapped > 0 && !m_fft->velocityPacked(c, 0))) return std::exp(cas.k * z) * whole;
    const float top = std::exp(bands.k[size_t(mapped)] * z);
    glm::vec3 u = top * whole;
    for (int band = 0; band < mapped; ++band) {
        const float* wu = m_fft->velocityPacked(c, band);             // (w_b, u_b)
        const float* v = m_fft->velocityPacked(c, mapped + band / 2);  // (v_2j, v_2j+1)
        const float weight = std::exp(bands.k[size_t(band)] * z) - top;
        u += weight * glm::vec3(b.value(wu, 2, 1), b.value(wu, 2, 0), b.value(v, 2, size_t(band % 2)));
    }
    return u;
}

glm::vec3 CompositeWater::velocityAt(glm::vec3 p, WaterLayers layers) const {
    glm::vec3 u(0.0f);
    invert(p.x, p.z, layers, [&](const Eval& e, float alpha, float beta) { u = velocityBelow(e, alpha, beta, p, layers); });
    return u;
}

WaterSample CompositeWater::sampleBelow(glm::vec3 p, WaterLayers layers) const {
    WaterSample s;
    invert(p.x, p.z, layers, [&](const Eval& e, float alpha, float beta) {
        s = finish(e, p.x, p.z, layers);
        s.velocity = velocityBelow(e, alpha, beta, p, layers);
    });
    return s;
}

// Inverts the displacement at every point, 64 at a time, the Gerstner sums vectorised over the
// points still moving; calls finish(index, eval at the rest point, rest α, β) once per point.
template <class Finish>
void CompositeWater::invertBatch(std::span<const glm::vec2> points, Finish&& finish, const glm::vec2* guess,
                                 float tolerance) const {
    float alpha[BATCH], beta[BATCH];
    glm::vec2 rest[BATCH];
    size_t active[BATCH];
    ocean::GerstnerSums sums[BATCH];
    for (size_t base = 0; base < points.size(); base += BATCH) {
        const size_t n = std::min(BATCH, points.size() - base);
        size_t live = n;
        for (size_t i = 0; i < n; ++i) {
            rest[i] = guess ? guess[base + i] : points[base + i];
            active[i] = i;
        }
        // Every round evaluates the points still moving, Gerstner sums vectorised over them.
        for (int it = 1; live > 0; ++it) {
            for (size_t k = 0; k < live; ++k) {
                alpha[k] = rest[active[k]].x;
                beta[k] = rest[active[k]].y;
            }
            m_gerstner.sums(alpha, beta, live, sums);
            size_t still = 0;
            for (size_t k = 0; k < live; ++k) {
                const size_t i = active[k];
                const glm::vec2 target = points[base + i];
                Eval e{sums[k], {}};
                addDisplacement(alpha[k], beta[k], e.f, lambda({}));
                glm::vec2 moved = rest[i];
                float residual;
                if (step(e, target.x, target.y, moved, residual, tolerance) || it >= m_settings.maxIterations) {
                    finish(base + i, e, alpha[k], beta[k]);
                } else {
                    rest[i] = moved;
                    active[still++] = i;
                }
            }
            live = still;
        }
    }
}

void CompositeWater::sampleBatch(std::span<const glm::vec2> points, std::span<WaterSample> out) const {
    assert(points.size() == out.size());
    invertBatch(points, [&](size_t i, Eval& e, float alpha, float beta) {
        addSurface(alpha, beta, e.f, lambda({}));
        out[i] = finish(e, points[i].x, points[i].y);
    });
}

void CompositeWater::horizontalVelocityBatch(std::span<const glm::vec2> points, std::span<glm::vec2> out) const {
    horizontalVelocityBatch(points, out, {}, 0.0f);
}

void CompositeWater::horizontalVelocityBatch(std::span<const glm::vec2> points, std::span<glm::vec2> out,
                                             std::span<glm::vec2> rest, float tolerance) const {
    assert(points.size() == out.size());
    assert(rest.empty() || rest.size() == points.size());
    const bool rates = m_fft && m_frameCount >= 2;
    const float lambda = m_fft ? m_fft->lambda() : 0.0f;
    // Blocks of BATCH points over the pool: every point is independent, so any split gives the same bits.
    const int blocks = int((points.size() + BATCH - 1) / BATCH);
    parallelFor(0, blocks, 2, [&](int lo, int hi) {
        const size_t begin = size_t(lo) * BATCH, end = std::min(points.size(), size_t(hi) * BATCH);
        invertBatch(points.subspan(begin, end - begin), [&](size_t i, Eval& e, float alpha, float beta) {
            glm::vec2 u(e.g.vx, e.g.vz);
            if (rates)
                for (const Cascade& cas : m_cascades) {
                    const Bilinear b(alpha, beta, cas.invCell, m_fft->resolution());
                    u += lambda * glm::vec2(b.value(cas.rate.data(), 4, 1), b.value(cas.rate.data(), 4, 2));
                }
            const glm::vec2 x = points[begin + i];
            if (m_ripple.horizontalVelocity) u += m_ripple.horizontalVelocity(x.x, x.y);
            if (m_current) u += m_current(x.x, x.y);
            out[begin + i] = u;
            if (!rest.empty()) rest[begin + i] = glm::vec2(alpha, beta);
        }, rest.empty() ? nullptr : rest.data() + begin, tolerance);
    });
}

glm::vec3 CompositeWater::displace(float alpha, float beta) const {
    const ocean::GerstnerSums g = m_gerstner.sums(alpha, beta);
    const FftTerms f = fftTerms(alpha, beta);
    glm::vec3 p{alpha + g.dx + f.dx, g.y + f.h, beta + g.dz + f.dz};
    if (m_ripple.height) p.y += m_ripple.height(p.x, p.z);
    return p;
}

void primeAt(ocean::OceanFftCpu* fft, CompositeWater& water, double t, double step) {
    for (int k = 2; k >= 0; --k) {
        const double tk = t - k * step;
        if (fft) fft->update(tk);
        water.update(tk);
    }
}

} // namespace ob::water
