#version 450 core
#include "common_bindings.glsl"
// Ocean inverse FFT (docs/references.md#spectral-ocean eq. 1; [Lee2007] §3.3: radix-2 decimation in time on bit-reversed
// input; [CodingTower]: compute shaders). One workgroup transforms one line of N complex values in
// place, X[j] = Σ_k x[k]·exp(+2πi·jk/N) (unnormalised, FFTW_BACKWARD): a bit-reversed load
// into shared memory, the log2 N butterfly stages paired into radix-4 steps with a barrier
// after each, a natural-order store. Pass 0 transforms rows, pass 1 columns (rows then columns
// is the 2-D transform). gl_WorkGroupID = (line, packed transform, cascade).
layout(local_size_x = 64) in;

// Per cascade four N² complex arrays [transform][row][col]; read and written in place.
layout(std430, binding = OCEAN_SPECTRA_BUFFER) buffer Spectra { vec2 b_spectra[]; };
// exp(+2πi·k/N), k ∈ [0, N/2), computed in double on the CPU.
layout(std430, binding = OCEAN_TWIDDLES_BUFFER) readonly buffer Twiddles { vec2 b_twiddles[]; };

layout(location = OCEAN_N_LOCATION) uniform int u_n;       // N, power of two in [4, 2048]
layout(location = OCEAN_LOG2N_LOCATION) uniform int u_log2n;   // log2 N
layout(location = OCEAN_COLUMNS_LOCATION) uniform int u_columns; // 0: transform rows, 1: columns

// One line of complex floats: 16 KiB at N = 2048, half of llvmpipe's 32 KiB limit (and the
// GL minimum), so any conforming GPU runs every N.
const uint MAX_N = 2048u;
shared vec2 s_line[MAX_N];

vec2 complexMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }

void main() {
    uint n = uint(u_n);
    uint threads = gl_WorkGroupSize.x;
    uint lid = gl_LocalInvocationID.x;
    uint line = gl_WorkGroupID.x;
    uint plane = (gl_WorkGroupID.z * 4u + gl_WorkGroupID.y) * n * n;
    uint first = u_columns != 0 ? plane + line : plane + line * n;
    uint stride = u_columns != 0 ? n : 1u;

    // --- load, bit-reversed: the DIT stages then leave the output in natural order
    uint shift = 32u - uint(u_log2n);
    for (uint k = lid; k < n; k += threads) s_line[bitfieldReverse(k) >> shift] = b_spectra[first + k * stride];
    memoryBarrierShared();
    barrier();

    // --- butterflies, two radix-2 stages at a time (half the barriers and shared-memory
    // round trips): stages h and 2h join four h-point transforms at i0 + {0, h, 2h, 3h},
    // i0 = 4h·(b / h) + b % h, into one 4h-point transform. W(p, m) = exp(+2πi·p/m) is
    // b_twiddles[p·N/m]; stage h uses W(pos, 2h), stage 2h W(pos, 4h) and W(pos + h, 4h) = i·W(pos, 4h).
    uint h = 1u;
    for (; 4u * h <= n; h <<= 2) {
        uint step = n / (4u * h);
        for (uint b = lid; b < (n >> 2); b += threads) {
            uint pos = b & (h - 1u);
            uint i0 = ((b - pos) << 2) + pos;
            vec2 w1 = b_twiddles[2u * pos * step];
            vec2 w2 = b_twiddles[pos * step];
            vec2 x1 = complexMul(w1, s_line[i0 + h]);
            vec2 x3 = complexMul(w1, s_line[i0 + 3u * h]);
            vec2 a0 = s_line[i0] + x1, a1 = s_line[i0] - x1;
            vec2 a2 = complexMul(w2, s_line[i0 + 2u * h] + x3);
            vec2 a3 = complexMul(w2, s_line[i0 + 2u * h] - x3);
            a3 = vec2(-a3.y, a3.x);  // · i
            s_line[i0] = a0 + a2;
            s_line[i0 + 2u * h] = a0 - a2;
            s_line[i0 + h] = a1 + a3;
            s_line[i0 + 3u * h] = a1 - a3;
        }
        memoryBarrierShared();
        barrier();
    }
    // Odd log2 N: one radix-2 stage (h = N/2) is left, twiddle W(pos, N).
    if (h < n) {
        for (uint b = lid; b < (n >> 1); b += threads) {
            vec2 a = s_line[b];
            vec2 c = complexMul(b_twiddles[b], s_line[b + h]);
            s_line[b] = a + c;
            s_line[b + h] = a - c;
        }
        memoryBarrierShared();
        barrier();
    }

    // --- store in natural order
    for (uint k = lid; k < n; k += threads) b_spectra[first + k * stride] = s_line[k];
}
