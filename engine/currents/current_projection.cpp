// The current layer's pressure projection: spectral on the periodic patch, MIC(0)-PCG with walls
// (law and discretisation in current_projection.h).
#include "currents/current_projection.h"

#include "core/error.h"
#include "core/fftw_wisdom.h"
#include "core/parallel.h"
#include "core/scrolling_grid.h"
#include "core/simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fftw3.h>
#include <numbers>
#include <string>

namespace ob::currents {

namespace {

// MIC(0)'s modification weight and its safeguard (the factor falls back to the diagonal where
// the modified pivot is below SAFETY × the diagonal).
constexpr double MIC_TAU = 0.97;
constexpr double MIC_SAFETY = 0.25;
// Rows whose recurrences the preconditioner's sweeps run side by side (forwardRows).
constexpr int SWEEP_ROWS = 4;

float* allocFloat(size_t count) {
    float* p = fftwf_alloc_real(count);
    if (!p) throw RuntimeError("out of memory for the current layer's projection");
    std::memset(p, 0, count * sizeof(float));
    return p;
}

inline int wrap(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

// Σ a·b in double over count values, in sixteen interleaved partial sums (a fixed order: the same
// bits every run), so the adds' latency does not bound the loop.
OB_VECTOR_KERNEL double dot(const float* __restrict a, const float* __restrict b, size_t count) {
    constexpr size_t LANES = 16;
    double lane[LANES] = {};
    size_t i = 0;
    for (; i + LANES <= count; i += LANES)
        for (size_t l = 0; l < LANES; ++l) lane[l] += double(a[i + l]) * double(b[i + l]);
    for (; i < count; ++i) lane[0] += double(a[i]) * double(b[i]);
    double sum = 0.0;
    for (size_t l = 0; l < LANES; ++l) sum += lane[l];
    return sum;
}

// φ += α·s, r −= α·t; returns max |r|.
OB_VECTOR_KERNEL float updateKernel(float* __restrict phi, float* __restrict r, const float* __restrict s,
                                    const float* __restrict t, float alpha, size_t count) {
    float worst = 0.0f;
    for (size_t c = 0; c < count; ++c) {
        phi[c] += alpha * s[c];
        r[c] -= alpha * t[c];
        worst = std::max(worst, std::abs(r[c]));
    }
    return worst;
}

// The open edge's divergence of row j (the west edge face is the ghost u(−1, j); vs: the v row
// below, the ghost row for j = 0), times the checkerboard sign s·(−1)^i, reordered for the real
// FFT (Makhoul): cell 2m to m, cell 2m + 1 to n − 1 − m.
OB_VECTOR_KERNEL void openDivergenceRow(float* __restrict out, const float* __restrict ur, const float* __restrict vr,
                                        const float* __restrict vs, float s, int n) {
    const int h = n / 2;
    for (int m = 0; m < h; ++m) out[m] = s * ((ur[2 * m] - ur[2 * m - 1]) + (vr[2 * m] - vs[2 * m]));
    for (int m = 0; m < h; ++m) out[n - 1 - m] = -s * ((ur[2 * m + 1] - ur[2 * m]) + (vr[2 * m + 1] - vs[2 * m + 1]));
}

// The inverse of openDivergenceRow's reordering and sign, for φ.
OB_VECTOR_KERNEL void openPhiRow(float* __restrict phi, const float* __restrict in, float s, int n) {
    const int h = n / 2;
    for (int m = 0; m < h; ++m) {
        phi[2 * m] = s * in[m];
        phi[2 * m + 1] = -s * in[n - 1 - m];
    }
}

// Spectrum row k1 of the reordered field's r2c (a; b: row n − k1) into the DCT-II's values Y of
// row k1 at columns k2 and n − k2, k2 = 0..n/2 (Makhoul: Y = 2·Re(ω1·ω2·V(k1, k2) + ω1·ω̄2·V(k1, −k2)),
// ω = e^(−iπk/(2n)), V(k1, −k2) = conj(V(−k1, k2))), times the solve's coefficients: zf[k2] =
// cf[k2]·Y(k1, k2), zb[k2] = cb[k2]·Y(k1, n − k2) (zb[0] = 0: column n is no mode). With
// P = ω1·ω2·V(k1, k2) and Q = ω1·ω̄2·V(k1, −k2): Y(k1, k2) = 2·Re(P + Q), Y(k1, n − k2) = −2·Im(P − Q).
// (c1, s1), (cr, ci): cos, sin of πk/(2n) for k1 and per column.
OB_VECTOR_KERNEL void openModesRow(float* __restrict zf, float* __restrict zb, const float* __restrict cf,
                                   const float* __restrict cb, const float* __restrict a, const float* __restrict b, float c1,
                                   float s1, const float* __restrict cr, const float* __restrict ci, int n) {
    const int h = n / 2;
    // Columns 0 and n/2 are their own mirrors: V(k1, −k2) = conj(V(−k1, k2)) is b as stored (a at 0).
    for (int k : {0, h}) {
        const float ar = a[2 * k], ai = a[2 * k + 1];
        const float br = k == 0 ? ar : b[2 * k], bi = k == 0 ? -ai : b[2 * k + 1];
        const float pr = c1 * cr[k] - s1 * ci[k], pi = -(s1 * cr[k] + c1 * ci[k]);
        const float qr = c1 * cr[k] + s1 * ci[k], qi = c1 * ci[k] - s1 * cr[k];
        zf[k] = cf[k] * (2.0f * ((pr * ar - pi * ai) + (qr * br + qi * bi)));
    }
    zb[0] = 0.0f;
    zb[h] = zf[h];
    for (int k = 1; k < h; ++k) {
        const float ar = a[2 * k], ai = a[2 * k + 1], br = b[2 * k], bi = b[2 * k + 1];  // V(k1, −k2) = (br, −bi)
        // ω1·ω2 = e^(−i(θ1 + θ2)), ω1·ω̄2 = e^(−i(θ1 − θ2))
        const float pr = c1 * cr[k] - s1 * ci[k], pi = -(s1 * cr[k] + c1 * ci[k]);
        const float qr = c1 * cr[k] + s1 * ci[k], qi = c1 * ci[k] - s1 * cr[k];
        const float Pr = pr * ar - pi * ai, Pi = pr * ai + pi * ar;
        const float Qr = qr * br + qi * bi, Qi = qi * br - qr * bi;
        zf[k] = cf[k] * (2.0f * (Pr + Qr));
        zb[k] = cb[k] * (-2.0f * (Pi - Qi));
    }
}

// The DCT-III's spectrum (Makhoul, in reverse) of spectrum row k1, columns k2 = 0..n/2, from
// openModesRow's values of rows k1 (zf, zb) and n − k1 (zmf, zmb; 0 for k1 = 0: row n is no mode):
// H = e^(i(θ1 + θ2))·((Z(k1, k2) − Z(−k1, −k2)) − i·(Z(k1, −k2) + Z(−k1, k2))).
OB_VECTOR_KERNEL void openSpectrumRow(float* __restrict out, const float* __restrict zf, const float* __restrict zb,
                                      const float* __restrict zmf, const float* __restrict zmb, float c1, float s1,
                                      const float* __restrict cr, const float* __restrict ci, int n) {
    for (int k = 0; k <= n / 2; ++k) {
        const float re = zf[k] - zmb[k], im = -(zb[k] + zmf[k]);
        const float er = c1 * cr[k] - s1 * ci[k], ei = s1 * cr[k] + c1 * ci[k];
        out[2 * k] = er * re - ei * im;
        out[2 * k + 1] = er * im + ei * re;
    }
}

} // namespace

CurrentProjection::CurrentProjection(int n, bool open) : m_n(n), m_open(open) {
    const size_t cells = size_t(n) * size_t(n), modes = size_t(n) * size_t(n / 2 + 1);
    m_div = allocFloat(cells);
    m_spec = allocFloat(2 * modes);
    m_phiFft = allocFloat(cells);
    // The open edge's sine pair runs through the same real transforms (prepareOpen).
    m_forward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_r2c_2d(n, n, m_div, reinterpret_cast<fftwf_complex*>(m_spec), flags);
    });
    m_backward = ocean::planWithWisdom([&](unsigned flags) {
        return fftwf_plan_dft_c2r_2d(n, n, reinterpret_cast<fftwf_complex*>(m_spec), m_phiFft, flags);
    });
    if (!m_forward || !m_backward)
        throw RuntimeError("FFTW could not plan a " + std::to_string(n) + "×" + std::to_string(n) + " transform");
    if (open) {
        prepareOpen();
    } else {  // φ̂ = −D̂/λ, and FFTW's unnormalised pair multiplies by n²: both folded into one factor
        const double pi = std::numbers::pi, cells2 = double(cells);
        m_coef.resize(modes);
        for (int kz = 0; kz < n; ++kz)
            for (int kx = 0; kx <= n / 2; ++kx) {
                const double sx = std::sin(pi * kx / n), sz = std::sin(pi * kz / n);
                const double lambda = 4.0 * (sx * sx + sz * sz);
                m_coef[size_t(kz) * size_t(n / 2 + 1) + size_t(kx)] = lambda > 0.0 ? float(-1.0 / (lambda * cells2)) : 0.0f;
            }
    }
    for (auto* v : {&m_phi, &m_r, &m_z, &m_s, &m_t, &m_precon, &m_pw, &m_q}) v->assign(cells, 0.0f);
    m_row.assign(size_t(n), 0.0f);
}

// The sine pair's solve, −1/(λ·(2n)²) per mode (FFTW's RODFT10, RODFT01 pair multiplies by 2n per
// axis), λ(k) = 4·sin²(πk_x/(2n)) + 4·sin²(πk_z/(2n)), k = 1..n, stored for the DCT mode
// (n − 1 − k_z, n − 1 − k_x) the checkerboard sign turns it into: per row k1 of those, the
// coefficients of columns k2 and of n − k2, k2 = 0..n/2 (openModesRow's cf, cb; cb[0] = 0, column n
// is no mode); and the twiddles cos, sin(πk/(2n)).
void CurrentProjection::prepareOpen() {
    const int n = m_n, h = n / 2;
    const size_t row = 2 * size_t(h + 1);
    const double half = 0.5 * std::numbers::pi / double(n), norm = 4.0 * double(n) * double(n);
    auto coef = [&](int k1, int k2) {  // the DCT mode (k1, k2)'s
        const double sx = std::sin(half * (n - k2)), sz = std::sin(half * (n - k1));
        return float(-1.0 / (4.0 * (sx * sx + sz * sz) * norm));
    };
    m_coef.assign(size_t(n) * row, 0.0f);
    for (int k1 = 0; k1 < n; ++k1)
        for (int k2 = 0; k2 <= h; ++k2) {
            m_coef[size_t(k1) * row + size_t(k2)] = coef(k1, k2);
            if (k2 > 0) m_coef[size_t(k1) * row + size_t(h + 1 + k2)] = coef(k1, n - k2);
        }
    m_cos.resize(size_t(n));
    m_sin.resize(size_t(n));
    for (int k = 0; k < n; ++k) {
        m_cos[size_t(k)] = float(std::cos(half * k));
        m_sin[size_t(k)] = float(std::sin(half * k));
    }
}

long CurrentProjection::neighbour(int i, int j) const {
    const int n = m_n;
    if (m_open && (i < 0 || i >= n || j < 0 || j >= n)) return -1;
    return long(wrap(j, n)) * long(n) + long(wrap(i, n));
}

CurrentProjection::~CurrentProjection() {
    {
        std::lock_guard<std::mutex> lock(ocean::fftwPlannerMutex());
        if (m_forward) fftwf_destroy_plan(m_forward);
        if (m_backward) fftwf_destroy_plan(m_backward);
    }
    fftwf_free(m_div);
    fftwf_free(m_spec);
    fftwf_free(m_phiFft);
}

void CurrentProjection::divergence(const float* u, const float* v, float* out) const {
    const int n = m_n;
    parallelFor(0, n, rowChunk(), [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j) {
            const float* ur = u + face(0, j);
            const float* vr = v + face(0, j);
            // open: the west and south edge faces are the ghosts u(−1, j), v(i, −1)
            const float* vs = v + (m_open ? face(0, j - 1) : face(0, wrap(j - 1, n)));
            float* o = out + size_t(j) * size_t(n);
            o[0] = (ur[0] - (m_open ? ur[-1] : ur[n - 1])) + (vr[0] - vs[0]);
            for (int i = 1; i < n; ++i) o[i] = (ur[i] - ur[i - 1]) + (vr[i] - vs[i]);
        }
    });
}

// u(i, j) −= φ(i + 1, j) − φ(i, j), v(i, j) −= φ(i, j + 1) − φ(i, j), periodic; with `solid`, only
// faces between two open cells (the rest stay 0).
void CurrentProjection::applyGradient(float* u, float* v, const float* phi, const uint8_t* solid, glm::vec2 add) const {
    if (m_open) return applyGradientOpen(u, v, phi, solid);
    const int n = m_n;
    parallelFor(0, n, rowChunk(), [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j) {
            const int jn = wrap(j + 1, n);
            const float* p = phi + size_t(j) * size_t(n);
            const float* pn = phi + size_t(jn) * size_t(n);
            float* ur = u + face(0, j);
            float* vr = v + face(0, j);
            if (!solid) {
                for (int i = 0; i < n - 1; ++i) ur[i] = (ur[i] - (p[i + 1] - p[i])) + add.x;
                ur[n - 1] = (ur[n - 1] - (p[0] - p[n - 1])) + add.x;
                for (int i = 0; i < n; ++i) vr[i] = (vr[i] - (pn[i] - p[i])) + add.y;
                continue;
            }
            const uint8_t* s = solid + size_t(j) * size_t(n);
            const uint8_t* sn = solid + size_t(jn) * size_t(n);
            for (int i = 0; i < n; ++i) {
                const int ie = wrap(i + 1, n);
                if (!s[i] && !s[ie]) ur[i] -= p[ie] - p[i];
                if (!s[i] && !sn[i]) vr[i] -= pn[i] - p[i];
            }
        }
    });
}

// The open edge's gradient: φ = 0 on the edge, the ring outside holding −φ_inside (the sine
// basis' mirror), so the edge faces (the west and south ghosts, the east and north last faces)
// take 2·φ_inside; with `solid`, faces touching a wall stay 0.
void CurrentProjection::applyGradientOpen(float* u, float* v, const float* phi, const uint8_t* solid) const {
    const int n = m_n;
    if (!solid) {  // rows as vector loops, the edge faces apart
        parallelFor(0, n, rowChunk(), [&](int lo, int hi) {
            for (int j = lo; j < hi; ++j) {
                const float* p = phi + size_t(j) * size_t(n);
                float* ur = u + face(0, j);
                float* vr = v + face(0, j);
                ur[-1] -= 2.0f * p[0];  // the west edge face, the ghost u(−1, j)
                for (int i = 0; i < n - 1; ++i) ur[i] -= p[i + 1] - p[i];
                ur[n - 1] += 2.0f * p[n - 1];  // the east edge face
                if (j < n - 1) {
                    const float* pn = p + n;
                    for (int i = 0; i < n; ++i) vr[i] -= pn[i] - p[i];
                } else {
                    for (int i = 0; i < n; ++i) vr[i] += 2.0f * p[i];  // the north edge faces
                }
                if (j == 0) {  // the south edge faces, the ghost row v(i, −1)
                    float* vs = v + face(0, -1);
                    for (int i = 0; i < n; ++i) vs[i] -= 2.0f * p[i];
                }
            }
        });
        return;
    }
    auto at = [&](const float* f, int i, int j) {  // beyond the edge: minus the cell inside it
        return f[size_t(std::clamp(j, 0, n - 1)) * size_t(n) + size_t(std::clamp(i, 0, n - 1))] *
               (i < 0 || i >= n || j < 0 || j >= n ? -1.0f : 1.0f);
    };
    auto wall = [&](int i, int j) { return solid && i >= 0 && i < n && j >= 0 && j < n && solid[size_t(j) * size_t(n) + size_t(i)]; };
    parallelFor(-1, n, rowChunk(), [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j)
            for (int i = -1; i < n; ++i) {
                // u(i, j) between cells (i, j) and (i + 1, j): rows 0..n − 1; v(i, j) between (i, j) and (i, j + 1): columns 0..n − 1
                if (j >= 0 && !wall(i, j) && !wall(i + 1, j)) u[face(i, j)] -= at(phi, i + 1, j) - at(phi, i, j);
                if (i >= 0 && !wall(i, j) && !wall(i, j + 1)) v[face(i, j)] -= at(phi, i, j + 1) - at(phi, i, j);
            }
    });
}

// No flow through any face of a wall cell (open edge: the edge faces beside a wall cell too).
void CurrentProjection::closeWallFaces(float* u, float* v, const uint8_t* solid) const {
    const int n = m_n;
    auto wall = [&](long c) { return c >= 0 && solid[size_t(c)]; };
    for (int j = m_open ? -1 : 0; j < n; ++j)
        for (int i = m_open ? -1 : 0; i < n; ++i) {
            const bool here = wall(neighbour(i, j));
            if (j >= 0 && (here || wall(neighbour(i + 1, j)))) u[face(i, j)] = 0.0f;
            if (i >= 0 && (here || wall(neighbour(i, j + 1)))) v[face(i, j)] = 0.0f;
        }
}

void CurrentProjection::projectPeriodic(float* u, float* v, glm::vec2 add) {
    if (m_open) return projectOpen(u, v);  // no uniform part to add (it would flow out)
    const size_t modes = size_t(m_n) * size_t(m_n / 2 + 1);
    divergence(u, v, m_div);
    fftwf_execute_dft_r2c(m_forward, m_div, reinterpret_cast<fftwf_complex*>(m_spec));
    for (size_t m = 0; m < modes; ++m) {
        m_spec[2 * m] *= m_coef[m];
        m_spec[2 * m + 1] *= m_coef[m];
    }
    fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_spec), m_phiFft);
    applyGradient(u, v, m_phiFft, nullptr, add);
}

// The open edge (file comment): D signed and reordered, its r2c, per mode the DCT-II's values times
// the solve's coefficient and the DCT-III's spectrum of them, the c2r, φ back in order, its gradient.
void CurrentProjection::projectOpen(float* u, float* v) {
    const int n = m_n, h = n / 2;
    const size_t sc = size_t(h + 1);
    auto reordered = [n](int j) { return j % 2 == 0 ? j / 2 : n - 1 - j / 2; };
    parallelFor(0, n, rowChunk(), [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j)
            openDivergenceRow(m_div + size_t(reordered(j)) * size_t(n), u + face(0, j), v + face(0, j), v + face(0, j - 1),
                              j % 2 == 0 ? 1.0f : -1.0f, n);
    });
    fftwf_execute_dft_r2c(m_forward, m_div, reinterpret_cast<fftwf_complex*>(m_spec));
    // Rows k1 and n − k1 read and write only each other: a pair at a time, in place.
    parallelFor(0, h + 1, m_threads > 1 ? (h + 2) / 2 : h + 1, [&](int lo, int hi) {
        std::vector<float> z(4 * sc, 0.0f);  // zf, zb of row k1, then of row n − k1
        float* const zm = z.data() + 2 * sc;
        for (int k1 = lo; k1 < hi; ++k1) {
            const int mirror = n - k1;  // the mirror row (row n, no mode, for k1 = 0; k1 itself at n/2)
            auto modes = [&](int r, float* out) {
                openModesRow(out, out + sc, m_coef.data() + 2 * sc * size_t(r), m_coef.data() + 2 * sc * size_t(r) + sc,
                             m_spec + 2 * sc * size_t(r), m_spec + 2 * sc * size_t((n - r) % n), m_cos[size_t(r)], m_sin[size_t(r)],
                             m_cos.data(), m_sin.data(), n);
            };
            auto spectrum = [&](int r, const float* own, const float* mirror) {
                openSpectrumRow(m_spec + 2 * sc * size_t(r), own, own + sc, mirror, mirror + sc, m_cos[size_t(r)], m_sin[size_t(r)],
                                m_cos.data(), m_sin.data(), n);
            };
            modes(k1, z.data());
            if (k1 == 0) {  // its mirror, row n, is no mode
                std::fill(zm, zm + 2 * sc, 0.0f);
                spectrum(0, z.data(), zm);
            } else if (k1 == h) {
                spectrum(h, z.data(), z.data());
            } else {
                modes(mirror, zm);
                spectrum(k1, z.data(), zm);
                spectrum(mirror, zm, z.data());
            }
        }
    });
    fftwf_execute_dft_c2r(m_backward, reinterpret_cast<fftwf_complex*>(m_spec), m_phiFft);
    parallelFor(0, n, rowChunk(), [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j) openPhiRow(m_div + size_t(j) * size_t(n), m_phiFft + size_t(reordered(j)) * size_t(n), j % 2 == 0 ? 1.0f : -1.0f, n);
    });
    applyGradientOpen(u, v, m_div, nullptr);
}

// (A·x)_c = Σ_n (x_c − x_n) over c's open neighbours; 0 on walls. A wall's x is 0 and its
// open-neighbour weight `o` 0, so a row is a vector loop over its interior.
void CurrentProjection::applyA(const float* x, float* out, const uint8_t* solid) const {
    const int n = m_n;
    if (m_open) {  // beyond the edge −x_c (φ = 0 on the edge): a cell's term with it is 2·x_c
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const size_t c = size_t(j) * size_t(n) + size_t(i);
                float sum = 0.0f;
                if (!solid[c])
                    for (long k : {neighbour(i - 1, j), neighbour(i + 1, j), neighbour(i, j - 1), neighbour(i, j + 1)})
                        if (k < 0 || !solid[size_t(k)]) sum += k < 0 ? 2.0f * x[c] : x[c] - x[size_t(k)];
                out[c] = sum;
            }
        return;
    }
    for (int j = 0; j < n; ++j) {
        const size_t r = size_t(j) * size_t(n), rs = size_t(wrap(j - 1, n)) * size_t(n), rn = size_t(wrap(j + 1, n)) * size_t(n);
        auto cell = [&](int i, int iw, int ie) {
            const size_t c = r + size_t(i);
            if (solid[c]) return 0.0f;
            float sum = 0.0f;
            for (size_t k : {r + size_t(iw), r + size_t(ie), rs + size_t(i), rn + size_t(i)})
                if (!solid[k]) sum += x[c] - x[k];
            return sum;
        };
        out[r] = cell(0, n - 1, 1);
        for (int i = 1; i < n - 1; ++i) {
            const size_t c = r + size_t(i);
            const float o = solid[c] ? 0.0f : 1.0f;
            const float ow = solid[c - 1] ? 0.0f : 1.0f, oe = solid[c + 1] ? 0.0f : 1.0f;
            const float os = solid[rs + size_t(i)] ? 0.0f : 1.0f, on = solid[rn + size_t(i)] ? 0.0f : 1.0f;
            out[c] = o * (ow * (x[c] - x[c - 1]) + oe * (x[c] - x[c + 1]) + os * (x[c] - x[rs + size_t(i)]) + on * (x[c] - x[rn + size_t(i)]));
        }
        out[r + size_t(n - 1)] = cell(n - 1, n - 2, 0);
    }
}

// MIC(0) of A in index order (Bridson, "Fluid Simulation for Computer Graphics", §5.2, written
// for any neighbour order so the periodic edges are held): with p_k = 1/√e_k,
//   e_c = A_cc − Σ_{k<c} p_k²·(1 + τ·m_k),
// k over c's open neighbours before it in index order, m_k the count of k's open neighbours
// after k other than c (the fill-in IC(0) drops, given back to the diagonal).
void CurrentProjection::factor(const uint8_t* solid) {
    const int n = m_n;
    const size_t cells = size_t(n) * size_t(n);
    // The open edge's outside (−1) counts twice on the diagonal (it holds −φ_c), never as a neighbour.
    auto neighbours = [this, n](size_t c, long out[4]) {
        const int i = int(c % size_t(n)), j = int(c / size_t(n));
        out[0] = neighbour(i - 1, j);
        out[1] = neighbour(i + 1, j);
        out[2] = neighbour(i, j - 1);
        out[3] = neighbour(i, j + 1);
    };
    auto openCell = [solid](long k) { return k >= 0 && !solid[size_t(k)]; };
    for (size_t c = 0; c < cells; ++c) {
        m_precon[c] = 0.0f;
        if (solid[c]) continue;
        long nb[4];
        neighbours(c, nb);
        double diag = 0.0, e = 0.0;
        for (long k : nb) diag += k < 0 ? 2.0 : openCell(k) ? 1.0 : 0.0;
        if (diag == 0.0) continue;  // a lone open cell: nothing flows
        e = diag;
        for (long k : nb) {
            if (!openCell(k) || size_t(k) >= c) continue;
            long kb[4];
            neighbours(size_t(k), kb);
            int later = 0;
            for (long m : kb) later += (openCell(m) && m > k && size_t(m) != c) ? 1 : 0;
            const double pk = m_precon[size_t(k)];
            e -= pk * pk * (1.0 + MIC_TAU * later);
        }
        if (e < MIC_SAFETY * diag) e = diag;
        m_precon[c] = float(1.0 / std::sqrt(e));
    }
    for (size_t c = 0; c < cells; ++c) m_pw[c] = c % size_t(n) == 0 ? 0.0f : m_precon[c] * m_precon[c - 1];
    m_factored.assign(solid, solid + cells);
}

// z = (L·Lᵀ)⁻¹·r with L's off-diagonals A_ck·p_k = −p_k: forward then backward substitution.
// Walls and lone cells have p = 0, so they pass 0 on. In index order a cell's earlier neighbours
// are W and S, and, across the periodic edges, E of the last column and N of the last row. Each
// sweep takes a row in two passes: what the neighbouring row gives (a vector loop), then the
// recurrence along the row, one multiply-add per cell: forward q_c = t_c + (p_c·p_{c−1})·q_{c−1}
// (m_pw holds p_c·p_{c−1}; 0 in the first column, whose W is a later cell), backward
// z_c = p_c·t_c + p_c²·z_{c+1}.
void CurrentProjection::precondition(const float* r, float* z) {
    const int n = m_n;
    int j = 0;
    while (j < n) j += forwardRows(r, j);
    j = n - 1;
    while (j >= 0) j -= backwardRows(z, j);
}

// The forward sweep from row j, up to SWEEP_ROWS rows at once: the first row's terms from the row
// below as a vector pass (t), then the recurrences of the rows side by side, cell i of each row in
// turn (row k + 1's cell i takes row k's q_i, final once computed: only a row's last cell changes
// after it, by the E term across the edge, which it gets before the next row reads it). Each
// cell's arithmetic is the single row's, in the same order: the same bits, with SWEEP_ROWS
// independent chains in flight where one row's is latency-bound. A row after the first must be
// plain: not row 0 (no row below) nor, periodic, row n − 1 (N across the edge). Returns the rows done.
int CurrentProjection::forwardRows(const float* r, int j) {
    const int n = m_n;
    const float* p = m_precon.data();
    const float* pw = m_pw.data();
    float* q = m_q.data();
    float* t = m_row.data();
    const size_t row = size_t(j) * size_t(n), south = size_t(wrap(j - 1, n)) * size_t(n);
    if (j > 0)
        for (int i = 0; i < n; ++i) t[i] = p[row + size_t(i)] * (r[row + size_t(i)] + p[south + size_t(i)] * q[south + size_t(i)]);
    else
        for (int i = 0; i < n; ++i) t[i] = p[size_t(i)] * r[size_t(i)];
    if (j == n - 1 && !m_open)  // N across the edge: row 0, done
        for (int i = 0; i < n; ++i) t[i] += p[row + size_t(i)] * (p[size_t(i)] * q[size_t(i)]);
    const int last = m_open ? n - 1 : n - 2;  // the last row that may follow in a block
    const int rows = j == n - 1 ? 1 : std::min(SWEEP_ROWS, last - j + 1);
    // E across the edge of the last column: cell (0, k), done.
    auto east = [&](size_t k) {
        if (!m_open) q[k + size_t(n - 1)] += p[k + size_t(n - 1)] * (p[k] * q[k]);
    };
    q[row] = t[0];
    for (int k = 1; k < rows; ++k) {
        const size_t c = row + size_t(k) * size_t(n);
        q[c] = p[c] * (r[c] + p[c - size_t(n)] * q[c - size_t(n)]);
    }
    for (int i = 1; i < n; ++i) {
        q[row + size_t(i)] = t[i] + pw[row + size_t(i)] * q[row + size_t(i - 1)];
        if (i == n - 1) east(row);
        for (int k = 1; k < rows; ++k) {
            const size_t c = row + size_t(k) * size_t(n) + size_t(i);
            q[c] = p[c] * (r[c] + p[c - size_t(n)] * q[c - size_t(n)]) + pw[c] * q[c - 1];
            if (i == n - 1) east(row + size_t(k) * size_t(n));
        }
    }
    return rows;
}

// The backward sweep from row j down, up to SWEEP_ROWS rows at once, as forwardRows: z_c =
// p_c·(t_c + p_c·z_{c+1}) along each row from its last cell, t the row's q plus its terms from the
// row above; the first column's W across the edge (cell n − 1) is done before the row's recurrence
// reaches it, so it joins its t first, and the row's cell 0 gets it after. A row after the first
// must be plain: not row n − 1 (no row above) nor, periodic, row 0 (S across the edge).
int CurrentProjection::backwardRows(float* z, int j) {
    const int n = m_n;
    const float* p = m_precon.data();
    const float* q = m_q.data();
    float* t = m_row.data();
    const size_t row = size_t(j) * size_t(n), north = size_t(wrap(j + 1, n)) * size_t(n);
    if (j < n - 1)
        for (int i = 0; i < n; ++i) t[i] = q[row + size_t(i)] + p[row + size_t(i)] * z[north + size_t(i)];
    else
        for (int i = 0; i < n; ++i) t[i] = q[row + size_t(i)];
    if (j == 0 && !m_open)  // S across the edge: row n − 1, done
        for (int i = 0; i < n; ++i) t[i] += p[size_t(i)] * z[size_t(n - 1) * size_t(n) + size_t(i)];
    const int first = m_open ? 0 : 1;  // the last row (going down) that may follow in a block
    const int rows = j == 0 ? 1 : std::min(SWEEP_ROWS, j - first + 1);
    // W across the edge of the first column: cell (n − 1, k), done.
    auto west = [&](size_t k) {
        if (!m_open) z[k] += p[k] * (p[k] * z[k + size_t(n - 1)]);
    };
    z[row + size_t(n - 1)] = p[row + size_t(n - 1)] * t[n - 1];
    for (int k = 1; k < rows; ++k) {
        const size_t c = row - size_t(k) * size_t(n) + size_t(n - 1);
        z[c] = p[c] * (q[c] + p[c] * z[c + size_t(n)]);
    }
    for (int i = n - 2; i >= 0; --i) {
        const float pc = p[row + size_t(i)];
        z[row + size_t(i)] = pc * t[i] + (pc * pc) * z[row + size_t(i + 1)];
        if (i == 0) west(row);
        for (int k = 1; k < rows; ++k) {
            const size_t c = row - size_t(k) * size_t(n) + size_t(i);
            const float pk = p[c];
            z[c] = pk * (q[c] + pk * z[c + size_t(n)]) + (pk * pk) * z[c + 1];
            if (i == 0) west(row - size_t(k) * size_t(n));
        }
    }
    return rows;
}

WallSolve CurrentProjection::projectWithWalls(float* u, float* v, const uint8_t* solid, float tolerance, int maxIterations) {
    const int n = m_n;
    const size_t cells = size_t(n) * size_t(n);
    // --- the bulk: the periodic projection, then no flow through any face of a wall cell
    projectPeriodic(u, v);
    closeWallFaces(u, v, solid);
    if (m_factored.size() != cells || !std::equal(m_factored.begin(), m_factored.end(), solid)) factor(solid);

    // --- the rest: A·φ = −D on the open cells, from last step's φ
    divergence(u, v, m_div);
    float* phi = m_phi.data();
    float* r = m_r.data();
    float* z = m_z.data();
    float* s = m_s.data();
    float* t = m_t.data();
    for (size_t c = 0; c < cells; ++c)
        if (solid[c]) phi[c] = 0.0f;
    applyA(phi, t, solid);
    float worst = 0.0f;
    for (size_t c = 0; c < cells; ++c) {
        r[c] = solid[c] ? 0.0f : -m_div[c] - t[c];
        worst = std::max(worst, std::abs(r[c]));
    }
    WallSolve out;
    if (worst > tolerance) {
        precondition(r, z);
        std::copy(z, z + cells, s);
        double sigma = dot(r, z, cells);
        while (out.iterations < maxIterations && sigma != 0.0) {
            ++out.iterations;
            applyA(s, t, solid);
            const double st = dot(s, t, cells);
            if (st <= 0.0) break;
            const float alpha = float(sigma / st);
            worst = updateKernel(phi, r, s, t, alpha, cells);
            if (worst <= tolerance) break;
            precondition(r, z);
            const double sigmaNew = dot(r, z, cells);
            const float beta = float(sigmaNew / sigma);
            sigma = sigmaNew;
            for (size_t c = 0; c < cells; ++c) s[c] = z[c] + beta * s[c];
        }
    }
    applyGradient(u, v, phi, solid);
    // The residual as the faces now hold it (the recurrence's r drifts from it in float).
    divergence(u, v, m_div);
    out.residual = 0.0f;
    for (size_t c = 0; c < cells; ++c)
        if (!solid[c]) out.residual = std::max(out.residual, std::abs(m_div[c]));
    return out;
}

void CurrentProjection::scroll(glm::ivec2 shift) { scrollCells(m_phi.data(), m_n, m_n, shift, 0.0f); }

void CurrentProjection::clearWarmStart() {
    std::fill(m_phi.begin(), m_phi.end(), 0.0f);
    m_factored.clear();
}

} // namespace ob::currents
