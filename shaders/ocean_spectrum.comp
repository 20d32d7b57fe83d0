#version 450 core
#include "common_bindings.glsl"
// Ocean synthesis (docs/references.md#spectral-ocean eq. 2, 6, 7, 9): h̃(K,t) per mode and the four packed spectra the
// inverse FFT turns into (h, ∂Dx/∂z), (Dx, Dz), (∂h/∂x, ∂h/∂z), (∂Dx/∂x, ∂Dz/∂z). GPU twin
// of CascadeSpectrum::synthesize (engine/ocean/spectrum.cpp): same coefficients, same phase.
// One invocation per mode: x the column, y the row (FFT order), gl_WorkGroupID.z the cascade.
layout(local_size_x = 8, local_size_y = 8) in;

// Re h̃ = cosRe·cos ωt + sinRe·sin ωt, Im h̃ = cosIm·cos ωt + sinIm·sin ωt; FFT order [row][col].
layout(std430, binding = OCEAN_MODES_BUFFER) readonly buffer Modes { vec4 b_modes[]; };
// ω (rad/s, double) and 1/k (m) on the quarter grid [|m|][|n|], (N/2+1)² per cascade.
struct QuarterMode {
    double omega;
    float invK;
    float pad;
};
layout(std430, binding = OCEAN_QUARTER_BUFFER) readonly buffer Quarter { QuarterMode b_quarter[]; };
// 2π·s/L for FFT-order position s: kx of column s, kz of row s; N per cascade.
layout(std430, binding = OCEAN_WAVE_NUMBERS_BUFFER) readonly buffer WaveNumbers { float b_k[]; };
// Output: per cascade four N² complex arrays [transform][row][col].
layout(std430, binding = OCEAN_SPECTRA_BUFFER) writeonly buffer Spectra { vec2 b_spectra[]; };

layout(location = OCEAN_N_LOCATION) uniform int u_n;        // N
layout(location = OCEAN_TIME_LOCATION) uniform double u_time;  // t, seconds

const double TWO_PI = 6.283185307179586476925286766559lf;
const double INV_TWO_PI = 0.15915494309189533576888376337251lf;

// sin and cos of ω·t as the CPU's phaseSinCos: ω·t reduced in double to r ∈ [−π, π] (float
// cannot hold ω·t for long runs: at t = 1000 s its ulp is already ~1e-3 rad), then Taylor
// polynomials of the half angle u = r/2 and the double-angle formulas (|error| < 1e-6).
vec2 phaseSinCos(double omega, double t) {
    precise double x = omega * t;
    precise double turns = roundEven(x * INV_TWO_PI);
    precise double reduced = x - turns * TWO_PI;
    float u = 0.5 * float(reduced);
    float u2 = u * u;
    float su = u * (1.0 + u2 * (-1.0 / 6.0 + u2 * (1.0 / 120.0 + u2 * (-1.0 / 5040.0
             + u2 * (1.0 / 362880.0 + u2 * (-1.0 / 39916800.0))))));
    float cu = 1.0 + u2 * (-0.5 + u2 * (1.0 / 24.0 + u2 * (-1.0 / 720.0
             + u2 * (1.0 / 40320.0 + u2 * (-1.0 / 3628800.0 + u2 * (1.0 / 479001600.0))))));
    return vec2(2.0 * su * cu, 1.0 - 2.0 * su * su);
}

void main() {
    int n = u_n;
    int col = int(gl_GlobalInvocationID.x);
    int row = int(gl_GlobalInvocationID.y);
    if (col >= n || row >= n) return;
    int cascade = int(gl_WorkGroupID.z);
    int mode = row * n + col;
    // ω and 1/k depend on |K| only: the quarter grid holds |n|, |m| ∈ [0, N/2].
    int quarter = n / 2 + 1;
    int an = min(col, n - col);
    int am = min(row, n - row);
    QuarterMode q = b_quarter[cascade * quarter * quarter + am * quarter + an];
    vec2 sc = phaseSinCos(q.omega, u_time);
    vec4 coef = b_modes[cascade * n * n + mode];
    float hr = coef.x * sc.y + coef.y * sc.x;
    float hi = coef.z * sc.y + coef.w * sc.x;

    float kx = b_k[cascade * n + col];
    float kz = b_k[cascade * n + row];
    float ux = kx * q.invK;  // kx/k
    float uz = kz * q.invK;  // kz/k
    float dxz = kx * uz;     // kx·kz/k
    float dxx = kx * ux;     // kx²/k
    float dzz = kz * uz;     // kz²/k

    int base = cascade * 4 * n * n + mode;
    int plane = n * n;
    b_spectra[base] = vec2(hr - hi * dxz, hi + hr * dxz);                 // h̃·(1 + i·kx·kz/k)
    b_spectra[base + plane] = vec2(hr * uz + hi * ux, hi * uz - hr * ux); // h̃·(kz − i·kx)/k
    b_spectra[base + 2 * plane] = vec2(-hr * kz - hi * kx, hr * kx - hi * kz);  // h̃·(−kz + i·kx)
    b_spectra[base + 3 * plane] = vec2(hr * dxx - hi * dzz, hi * dxx + hr * dzz); // h̃·(kx² + i·kz²)/k
}
