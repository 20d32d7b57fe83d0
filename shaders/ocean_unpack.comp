#version 450 core
#include "common_bindings.glsl"
// Ocean maps from the four inverse-transformed packed spectra (docs/references.md#spectral-ocean eq. 9: f = Re,
// g = Im) and the foam Jacobian ([CodingTower] "Future"), as OceanFftCpu's unpack:
//   displacement = (Dx, h, Dz, J),   slopes = (∂h/∂x, ∂h/∂z, J, |∇h|²),
//   J = (1 + λ∂Dx/∂x)(1 + λ∂Dz/∂z) − (λ∂Dx/∂z)².
// One invocation per texel: x along i, y along j, gl_WorkGroupID.z the cascade (= layer).
layout(local_size_x = 8, local_size_y = 8) in;

// Per cascade four N² complex arrays [transform][row j][col i], after the 2-D inverse FFT.
layout(std430, binding = OCEAN_SPECTRA_BUFFER) readonly buffer Spectra { vec2 b_spectra[]; };

layout(rgba32f, binding = OCEAN_DISPLACEMENT_IMAGE) writeonly uniform image2DArray u_displacement;
layout(rgba32f, binding = OCEAN_SLOPES_IMAGE) writeonly uniform image2DArray u_slopes;

layout(location = OCEAN_N_LOCATION) uniform int u_n;        // N
layout(location = OCEAN_LAMBDA_LOCATION) uniform float u_lambda; // λ = −choppiness

void main() {
    int n = u_n;
    ivec3 texel = ivec3(gl_GlobalInvocationID.xy, gl_WorkGroupID.z);
    if (texel.x >= n || texel.y >= n) return;
    int plane = n * n;
    int base = texel.z * 4 * plane + texel.y * n + texel.x;
    vec2 heightDxz = b_spectra[base];
    vec2 dispXZ = b_spectra[base + plane];
    vec2 slopeXZ = b_spectra[base + 2 * plane];
    vec2 dxxDzz = b_spectra[base + 3 * plane];
    float dxz = u_lambda * heightDxz.y;
    float jacobian = (1.0 + u_lambda * dxxDzz.x) * (1.0 + u_lambda * dxxDzz.y) - dxz * dxz;
    imageStore(u_displacement, texel, vec4(dispXZ.x, heightDxz.x, dispXZ.y, jacobian));
    // |∇h|² beside the slope: its mips' mean less the mean slope's square is the slope variance a
    // filtered lookup loses (Bruneton, Neyret & Holzschuch 2010 §4; common_glitter.glsl)
    imageStore(u_slopes, texel, vec4(slopeXZ, jacobian, dot(slopeXZ, slopeXZ)));
}
