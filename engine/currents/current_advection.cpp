// Semi-Lagrangian self-advection of the current layer's faces (law in current_advection.h).
#include "currents/current_advection.h"

#include "core/parallel.h"
#include "core/simd.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace ob::currents {

namespace {

// Bilinear value of a row-major field on the departure point (x − a, z − b) in samples, from the
// sample at the centre of a 3 × 3 neighbourhood (rows rm = z − 1, r0 = z, rp = z + 1, column pi)
// for |a|, |b| ≤ 1: the stencil is the sample and its upstream neighbours along each axis. All
// nine samples are read and the upstream ones chosen by selects, so a row is one vector loop.
inline float upstreamBilinear(const float* rm, const float* r0, const float* rp, int pi, float a, float b) {
    const float mW = rm[pi - 1], mC = rm[pi], mE = rm[pi + 1];
    const float cW = r0[pi - 1], cC = r0[pi], cE = r0[pi + 1];
    const float pW = rp[pi - 1], pC = rp[pi], pE = rp[pi + 1];
    const bool east = a <= 0.0f, north = b <= 0.0f;  // the departure point lies toward +x, +z
    const float ax = std::abs(a), bz = std::abs(b);
    const float side = east ? cE : cW;
    const float up = north ? pC : mC;
    const float corner = north ? (east ? pE : pW) : (east ? mE : mW);
    return (1.0f - bz) * ((1.0f - ax) * cC + ax * side) + bz * ((1.0f - ax) * up + ax * corner);
}

// One row of u faces, columns [1, n] of the padded row (all its faces). ur*: the u rows j − 1, j,
// j + 1 (padded, row starts); vm, vc: the v rows j − 1, j. k = dt/Δ. Returns nonzero when some face
// moves more than the fast path holds (the caller redoes the row).
OB_VECTOR_KERNEL int uRowKernel(float* __restrict out, const float* __restrict um, const float* __restrict uc,
                                const float* __restrict up, const float* __restrict vm, const float* __restrict vc, int n,
                                float k) {
    int over = 0;
    for (int pi = 1; pi <= n; ++pi) {
        // The face's own velocity: u, and v the mean of the four v faces around it.
        const float vbar = 0.25f * ((vm[pi] + vm[pi + 1]) + (vc[pi] + vc[pi + 1]));
        const float a1 = 0.5f * k * uc[pi], b1 = 0.5f * k * vbar;
        // At the midpoint: u upstream, v on the fixed stencil (i..i+1, j−1..j), weights ½ − a1, ½ − b1.
        const float umid = upstreamBilinear(um, uc, up, pi, a1, b1);
        const float wx = 0.5f - a1, wz = 0.5f - b1;
        const float vmid = (1.0f - wz) * ((1.0f - wx) * vm[pi] + wx * vm[pi + 1]) + wz * ((1.0f - wx) * vc[pi] + wx * vc[pi + 1]);
        const float a2 = k * umid, b2 = k * vmid;
        over |= int(std::abs(a1) > 0.5f) | int(std::abs(b1) > 0.5f) | int(std::abs(a2) > 1.0f) | int(std::abs(b2) > 1.0f);
        out[pi] = upstreamBilinear(um, uc, up, pi, a2, b2);
    }
    return over;
}

// One row of v faces: vr*: the v rows j − 1, j, j + 1; uc, up: the u rows j, j + 1. The u at a v
// face's midpoint lies in the fixed stencil (i−1..i, j..j+1).
OB_VECTOR_KERNEL int vRowKernel(float* __restrict out, const float* __restrict vm, const float* __restrict vc,
                                const float* __restrict vp, const float* __restrict uc, const float* __restrict up, int n,
                                float k) {
    int over = 0;
    for (int pi = 1; pi <= n; ++pi) {
        const float ubar = 0.25f * ((uc[pi - 1] + uc[pi]) + (up[pi - 1] + up[pi]));
        const float a1 = 0.5f * k * ubar, b1 = 0.5f * k * vc[pi];
        const float vmid = upstreamBilinear(vm, vc, vp, pi, a1, b1);
        const float wx = 0.5f - a1, wz = 0.5f - b1;
        const float umid = (1.0f - wz) * ((1.0f - wx) * uc[pi - 1] + wx * uc[pi]) + wz * ((1.0f - wx) * up[pi - 1] + wx * up[pi]);
        const float a2 = k * umid, b2 = k * vmid;
        over |= int(std::abs(a1) > 0.5f) | int(std::abs(b1) > 0.5f) | int(std::abs(a2) > 1.0f) | int(std::abs(b2) > 1.0f);
        out[pi] = upstreamBilinear(vm, vc, vp, pi, a2, b2);
    }
    return over;
}

// The general backtrace of one face at grid point g (cell centres at integers): u padded
// coordinates are g + (½, 1), v's g + (1, ½).
inline glm::vec2 velocityPadded(const float* u0, const float* v0, int n, glm::vec2 g) {
    return {samplePadded(u0, n, g + glm::vec2(0.5f, 1.0f)), samplePadded(v0, n, g + glm::vec2(1.0f, 0.5f))};
}
inline glm::vec2 departure(const float* u0, const float* v0, int n, glm::vec2 g, float k) {
    const glm::vec2 mid = g - 0.5f * k * velocityPadded(u0, v0, n, g);
    return g - k * velocityPadded(u0, v0, n, mid);
}

} // namespace

float samplePadded(const float* f, int n, glm::vec2 p) {
    const int s = n + 2;
    const float hi = float(n + 1);
    const float x = std::clamp(p.x, 0.0f, hi), z = std::clamp(p.y, 0.0f, hi);
    const int x0 = std::min(int(x), n), z0 = std::min(int(z), n);  // x0 + 1 stays in the ring
    const float tx = x - float(x0), tz = z - float(z0);
    const float* r0 = f + size_t(z0) * size_t(s);
    const float* r1 = r0 + s;
    return (1.0f - tz) * ((1.0f - tx) * r0[x0] + tx * r0[x0 + 1]) + tz * ((1.0f - tx) * r1[x0] + tx * r1[x0 + 1]);
}

void advectFaces(const float* u0, const float* v0, float* u, float* v, int n, float cell, float dt, int threads) {
    const size_t s = size_t(n + 2);
    const float k = dt / cell;
    parallelFor(0, n, threads > 1 ? (n + threads - 1) / threads : n, [&](int lo, int hi) {
        for (int j = lo; j < hi; ++j) {
            const size_t pj = size_t(j + 1);
            const float* um = u0 + (pj - 1) * s;
            const float* uc = u0 + pj * s;
            const float* up = u0 + (pj + 1) * s;
            const float* vm = v0 + (pj - 1) * s;
            const float* vc = v0 + pj * s;
            const float* vp = v0 + (pj + 1) * s;
            if (uRowKernel(u + pj * s, um, uc, up, vm, vc, n, k))
                for (int i = 0; i < n; ++i) {
                    const glm::vec2 d = departure(u0, v0, n, glm::vec2(float(i) + 0.5f, float(j)), k);
                    u[pj * s + size_t(i + 1)] = samplePadded(u0, n, d + glm::vec2(0.5f, 1.0f));
                }
            if (vRowKernel(v + pj * s, vm, vc, vp, uc, up, n, k))
                for (int i = 0; i < n; ++i) {
                    const glm::vec2 d = departure(u0, v0, n, glm::vec2(float(i), float(j) + 0.5f), k);
                    v[pj * s + size_t(i + 1)] = samplePadded(v0, n, d + glm::vec2(1.0f, 0.5f));
                }
        }
    });
}

} // namespace ob::currents
