#version 450 core
// Ripple field step, [Kang2008] eq. 1–2, fixed ring or absorbing sponge (docs/references.md#ripple-layer): the GPU twin
// of RippleField::step. Every float operation of the CPU loop in the same order, `precise` so
// that none is fused into a multiply-add: the result is the CPU's to the bit. One invocation
// per cell; mode 1 instead shifts a level by whole cells (RippleField::scroll) into another.
#include "kang2008_bindings.glsl"
layout(local_size_x = KANG2008_STEP_TILE, local_size_y = KANG2008_STEP_TILE) in;

// Row-major N×M floats, index z·M + x.
layout(std430, binding = KANG2008_CURRENT_BUFFER) readonly buffer Current { float b_current[]; };  // Vh(t); mode 1: source
layout(std430, binding = KANG2008_PREVIOUS_BUFFER) buffer Previous { float b_previous[]; };         // Vh(t−1) in, Vh(t+1) out; mode 1: destination
layout(std430, binding = KANG2008_SPONGE_BUFFER) readonly buffer Sponge { float b_sponge[]; };    // s(d): N row factors, then M column factors

layout(location = KANG2008_SIZE_LOCATION) uniform ivec2 u_size;     // (M columns along x, N rows along z)
layout(location = KANG2008_DAMPING_LOCATION) uniform float u_damping;  // DF of eq. 2, [0, 1]
layout(location = KANG2008_SPONGE_LOCATION) uniform int u_sponge;     // 1: absorbing band present (width > 0)
layout(location = KANG2008_MODE_LOCATION) uniform int u_mode;
layout(location = KANG2008_SHIFT_LOCATION) uniform ivec2 u_shift;    // mode 1: (dx, dz), cell (x, z) takes (x + dx, z + dz)

// RippleField's friction at the outer ring (stable below 1/2).
const float SPONGE_MAX_FRICTION = 0.4;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    int cols = u_size.x, rows = u_size.y;
    if (p.x >= cols || p.y >= rows) return;
    int i = p.y * cols + p.x;
    bool ring = p.x == 0 || p.y == 0 || p.x == cols - 1 || p.y == rows - 1;

    if (u_mode == KANG2008_MODE_SHIFT) {
        ivec2 s = p + u_shift;
        bool inside = s.x >= 0 && s.y >= 0 && s.x < cols && s.y < rows;
        b_previous[i] = (!ring && inside) ? b_current[s.y * cols + s.x] : 0.0;
        return;
    }
    // The outer ring is held at 0 (both modes of the boundary).
    if (ring) {
        b_previous[i] = 0.0;
        return;
    }
    int up = i - cols, down = i + cols;
    // Eq. 1: C(i,j) = 1/4 for the 8 neighbours, C(0,0) = 0; summed row by row as on the CPU.
    precise float sum = (b_current[up - 1] + b_current[up] + b_current[up + 1]) + (b_current[i - 1] + b_current[i + 1]) +
                        (b_current[down - 1] + b_current[down] + b_current[down + 1]);
    precise float buff = 0.25 * sum;
    float old = b_previous[i];  // Vh(t−1), read before this invocation overwrites it
    precise float next;
    if (u_sponge != 0) {
        // Friction on the vertical velocity, γ·(Vh(t) − Vh(t−1)), γ = 0.4·(1 − s_row·s_col):
        // ±0 away from the band, so those cells get eq. 2's bits.
        precise float gamma = SPONGE_MAX_FRICTION * (1.0 - b_sponge[p.y] * b_sponge[rows + p.x]);
        next = ((buff - old) - gamma * (b_current[i] - old)) * u_damping;
    } else {
        next = (buff - old) * u_damping;  // eq. 2
    }
    b_previous[i] = next;
}
