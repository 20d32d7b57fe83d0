#version 450 core
// Dispersive ripple step, the per-mode and real-space passes (docs/references.md#dispersive-ripples; Tessendorf, eWave 2014):
// the GPU twin of EWaveField::step around ocean_fft.comp's transforms. One invocation per cell
// or mode of the N×N grid. The state is kept conjugated, w = h − i·v, so that ocean_fft.comp's
// e^{+} transform is the forward one: S = FFT⁺(w) = conj(Z), Z = FFT⁻(h + i·v) (see EWaveGpu).
#include "ewave_bindings.glsl"
layout(local_size_x = EWAVE_TILE, local_size_y = EWAVE_TILE) in;

// Row-major N×N complex floats, index row·N + column.
layout(std430, binding = EWAVE_SPECTRUM_BUFFER) readonly buffer Spectrum { vec2 b_spectrum[]; };  // mode 0: S
layout(std430, binding = EWAVE_FIELD_BUFFER) buffer Field { vec2 b_field[]; };                 // mode 0: Y out; else w in place
// Per |row index|, |column index| in [0, N/2]: (a, b, c, 0) = d·(cos ωΔt, sin(ωΔt)/ω, −ω·sin ωΔt)/N².
layout(std430, binding = EWAVE_ROTATION_BUFFER) readonly buffer Rotation { vec4 b_rotation[]; };
layout(std430, binding = EWAVE_SPONGE_BUFFER) readonly buffer Sponge { float b_sponge[]; };     // mode 2: exp(−γΔt) per cell
// Σh per work group of the sponge pass (row-major over the groups), then their total at index groups².
layout(std430, binding = EWAVE_SUM_BUFFER) buffer Sum { float b_sum[]; };

layout(location = EWAVE_N_LOCATION) uniform int u_n;
layout(location = EWAVE_MODE_LOCATION) uniform int u_mode;
layout(location = EWAVE_LEVEL_LOCATION) uniform float u_level;

shared float s_sum[EWAVE_TILE * EWAVE_TILE];

vec2 timesI(vec2 a) { return vec2(-a.y, a.x); }

// The work group's values added in shared memory (a fixed tree: the same order every run);
// every invocation of the group must call it. The total is in s_sum[0].
void groupSum(float value) {
    uint l = gl_LocalInvocationIndex;
    s_sum[l] = value;
    for (uint stride = EWAVE_TILE * EWAVE_TILE / 2; stride > 0; stride >>= 1) {
        memoryBarrierShared();
        barrier();
        if (l < stride) s_sum[l] += s_sum[l + stride];
    }
    memoryBarrierShared();
    barrier();
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);  // (column, row)
    int n = u_n;
    bool inside = p.x < n && p.y < n;
    int i = p.y * n + p.x;
    int groups = (n + EWAVE_TILE - 1) / EWAVE_TILE;
    // The absorbing border keeps the volume as EWaveField does: the sponge relaxes h towards the
    // mean level (v towards 0), and the water it still moved is put back as a uniform shift of
    // h (modes total, restore), which every invocation of a group must reach (barriers).
    if (u_mode == EWAVE_MODE_SPONGE) {
        float h = 0.0;
        if (inside) {
            float s = b_sponge[i];
            b_field[i] = s * b_field[i] + (1.0 - s) * vec2(u_level, 0.0);
            h = b_field[i].x;
        }
        groupSum(h);
        if (gl_LocalInvocationIndex == 0) b_sum[gl_WorkGroupID.y * groups + gl_WorkGroupID.x] = s_sum[0];
        return;
    }
    if (u_mode == EWAVE_MODE_TOTAL) {  // one work group
        int count = groups * groups;
        float sum = 0.0;
        for (int g = int(gl_LocalInvocationIndex); g < count; g += EWAVE_TILE * EWAVE_TILE) sum += b_sum[g];
        groupSum(sum);
        if (gl_LocalInvocationIndex == 0) b_sum[count] = s_sum[0];
        return;
    }
    if (!inside) return;
    if (u_mode == EWAVE_MODE_RESTORE) {
        b_field[i].x += u_level - b_sum[groups * groups] / float(n * n);
        return;
    }
    if (u_mode == EWAVE_MODE_RING) {
        if (p.x == 0 || p.y == 0 || p.x == n - 1 || p.y == n - 1) b_field[i] = vec2(0.0);
        return;
    }
    // Mode K = (p.x, p.y) and its mirror −K. With P = S(−K) = conj Z(−K) and Q = conj S(K) = Z(K):
    // conj H(−K) = (P + Q)/2, conj V(−K) = i·(P − Q)/2, and the output Y(K) = conj Z'(−K) with
    // Z' = a·Z + b·V + i·c·H (H' = a·H + b·V, V' = c·H + a·V) is
    //   Y = a·P + i·(b·(P − Q) − c·(P + Q))/2,
    // so the inverse e^{+} transform of Y is conj(h' + i·v') = w' (a, b, c hold 1/N²). K = 0, the
    // volume: H' = a·H, V' = 0 (EWaveField::modeStep), so Y = a·(P + Q)/2.
    int mask = n - 1;
    ivec2 m = (ivec2(n) - p) & ivec2(mask);
    vec2 P = b_spectrum[m.y * n + m.x];
    vec2 s = b_spectrum[i];
    vec2 Q = vec2(s.x, -s.y);
    ivec2 q = min(p, ivec2(n) - p);  // |signed index|, [0, N/2]
    vec4 r = b_rotation[q.y * (n / 2 + 1) + q.x];
    if (i == 0) b_field[i] = 0.5 * r.x * (P + Q);
    else b_field[i] = r.x * P + timesI(0.5 * (r.y * (P - Q) - r.z * (P + Q)));
}
