#version 450 core
// Bounding-sphere stamps, [Kang2008] eq. 5 then eq. 7 (docs/references.md#ripple-layer): the GPU twin of stampFootprint
// for a list of stamps. Overlaps: the last stamp in list order wins every cell, as when the
// CPU stamps the list in order. Pass 0 claims cells (atomicMax of stamp index + 1); pass 1
// lets the owner write both levels and release its claim (back to 0 for the next call).
// gl_WorkGroupID.z = stamp (from u_firstStamp); x, y cover the stamp's footprint box.
#include "kang2008_bindings.glsl"
layout(local_size_x = KANG2008_STAMP_TILE, local_size_y = KANG2008_STAMP_TILE) in;

// One stamp (std430, 32 bytes; RippleFieldGpu's GpuStamp).
struct Stamp {
    int cx, cz;         // centre cell
    int phOffset;       // first PH of its box in b_ph
    int reach;          // box half-width: the box is (2·reach + 1)² cells, row-major by dz
    float base;         // eq. 5 base height, m
    float heightScale;  // SD·SHR·cell size, m per cell of PH
    float af;           // AF of eq. 7
    uint pad;
};

// Row-major N×M floats, index z·M + x.
layout(std430, binding = KANG2008_CURRENT_BUFFER) buffer Current { float b_current[]; };     // Vh(t)
layout(std430, binding = KANG2008_PREVIOUS_BUFFER) buffer Previous { float b_previous[]; };   // Vh(t−1)
layout(std430, binding = KANG2008_STAMPS_BUFFER) readonly buffer Stamps { Stamp b_stamps[]; };
layout(std430, binding = KANG2008_PH_BUFFER) readonly buffer Ph { float b_ph[]; };      // eq. 4 PH per box cell (CPU makeFootprint), −1 outside the disc
layout(std430, binding = KANG2008_OWNER_BUFFER) buffer Owner { uint b_owner[]; };          // per cell: 0, or the claiming stamp index + 1

layout(location = KANG2008_SIZE_LOCATION) uniform ivec2 u_size;      // (M, N)
layout(location = KANG2008_PASS_LOCATION) uniform int u_pass;        // 0: claim, 1: write
layout(location = KANG2008_FIRST_STAMP_LOCATION) uniform int u_firstStamp;  // stamp of gl_WorkGroupID.z = 0
layout(location = KANG2008_STAMP_COUNT_LOCATION) uniform int u_stampCount;  // stamps in the list

void main() {
    int s = u_firstStamp + int(gl_WorkGroupID.z);
    if (s >= u_stampCount) return;
    Stamp st = b_stamps[s];
    int box = 2 * st.reach + 1;
    ivec2 b = ivec2(gl_GlobalInvocationID.xy);
    if (b.x >= box || b.y >= box) return;
    ivec2 cell = ivec2(st.cx, st.cz) + b - ivec2(st.reach);
    // Off the field or on the ring held at 0: skipped, as on the CPU.
    if (cell.x < 1 || cell.y < 1 || cell.x > u_size.x - 2 || cell.y > u_size.y - 2) return;
    float ph = b_ph[st.phOffset + b.y * box + b.x];
    if (ph < 0.0) return;  // PR >= SR: not in the footprint
    int i = cell.y * u_size.x + cell.x;
    uint tag = uint(s) + 1u;
    if (u_pass == 0) {
        atomicMax(b_owner[i], tag);
        return;
    }
    // Only the owner passes, and it resets the claim in the same atomic.
    if (atomicCompSwap(b_owner[i], tag, 0u) != tag) return;
    precise float v = st.base + ph * st.heightScale;  // eq. 5: base + PH·SD·SHR, metres
    precise float p = v - v * st.af;                   // eq. 7
    b_current[i] = v;
    b_previous[i] = p;
}
