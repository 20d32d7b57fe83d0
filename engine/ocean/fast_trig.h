// sin and cos of an angle already reduced to [−π, π], as half angle u = r/2 ∈ [−π/2, π/2]:
// Taylor polynomials (first omitted terms: u^13/13! < 6e-8, u^14/14! < 7e-9), then the
// double-angle formulas. Plain float arithmetic in a fixed order, so the AVX2 and baseline
// clones of the kernels that inline it give the same bits (shaders/ocean_spectrum.comp
// repeats it for the GPU).
#pragma once

namespace ob::ocean {

[[gnu::always_inline]] inline void halfAngleSinCos(float u, float& s, float& c) {
    const float u2 = u * u;
    const float su = u * (1.0f + u2 * (-1.0f / 6.0f + u2 * (1.0f / 120.0f + u2 * (-1.0f / 5040.0f
                   + u2 * (1.0f / 362880.0f + u2 * (-1.0f / 39916800.0f))))));
    const float cu = 1.0f + u2 * (-0.5f + u2 * (1.0f / 24.0f + u2 * (-1.0f / 720.0f
                   + u2 * (1.0f / 40320.0f + u2 * (-1.0f / 3628800.0f + u2 * (1.0f / 479001600.0f))))));
    s = 2.0f * su * cu;
    c = 1.0f - 2.0f * su * su;
}

} // namespace ob::ocean
