// The composite water surface (SPEC §2.3): Gerstner waves (analytic) + FFT cascades
// (textures) + ripples, with normals added in slope form. Mirror: gfx::WaterUniforms.
layout(std140, binding = 1) uniform WaterUniforms {
    vec4 u_corner[4];          // projected grid corners, homogeneous (x, 0, z, w)
    vec4 u_cascadeSize;        // tile side of each cascade (m); unused cascades 0
    vec4 u_waterParams;        // x λ (choppiness sign included), y gravity, z Gerstner wave count, w minimum |w|
    vec4 u_gridParams;         // x grid resolution, y max distance (m), z cascade count, w FFT resolution N
    vec4 u_rippleParams;       // xy world origin of cell (0, 0) (m), z cell size (m), w cells per side (0: none)
    vec4 u_gerstner[32];       // (kx, kz, amplitude, phase) per wave
};

layout(binding = 0) uniform sampler2DArray u_displacement;  // layer c: (Dx, h, Dz, J)
layout(binding = 1) uniform sampler2DArray u_slopes;        // layer c: (dh/dx, dh/dz, 0, 0)
layout(binding = 2) uniform sampler2D u_ripples;            // ripple heights Vh(t) (m), 0 outside

// Ripple height at world (x, z) (bilinear between cell centres; 0 outside the patch).
float rippleHeight(vec2 world) {
    if (u_rippleParams.w <= 0.0) return 0.0;
    vec2 uv = ((world - u_rippleParams.xy) / u_rippleParams.z + 0.5) / u_rippleParams.w;
    return textureLod(u_ripples, uv, 0.0).r;
}

// Ripple slope (dh/dx, dh/dz) at world (x, z), central differences over one cell.
vec2 rippleSlope(vec2 world) {
    if (u_rippleParams.w <= 0.0) return vec2(0.0);
    float h = u_rippleParams.z;
    return vec2(rippleHeight(world + vec2(h, 0.0)) - rippleHeight(world - vec2(h, 0.0)),
                rippleHeight(world + vec2(0.0, h)) - rippleHeight(world - vec2(0.0, h))) / (2.0 * h);
}

// The projected grid point (u, v): homogeneous bilinear interpolation, |w| clamped (seed 000).
vec2 gridPoint(vec2 uv) {
    vec4 p = mix(mix(u_corner[0], u_corner[1], uv.x), mix(u_corner[2], u_corner[3], uv.x), uv.y);
    return p.xz / max(p.w, u_waterParams.w);
}

// Gerstner displacement of rest point (α, β) at time t (SPEC §2.2): (x − α, y, z − β).
vec3 gerstnerOffset(vec2 rest, float t) {
    vec3 d = vec3(0.0);
    int count = int(u_waterParams.z);
    for (int m = 0; m < count; ++m) {
        vec4 w = u_gerstner[m];
        float k = length(w.xy);
        float theta = dot(w.xy, rest) - sqrt(u_waterParams.y * k) * t - w.w;
        d.xz -= (w.xy / k) * w.z * sin(theta);
        d.y += w.z * cos(theta);
    }
    return d;
}

// Gerstner slope (∂y/∂x, ∂y/∂z) of the displaced surface, from the analytic normal
// n = ∂r/∂β × ∂r/∂α (SPEC §2.2), as −n.xz / n.y.
vec2 gerstnerSlope(vec2 rest, float t) {
    float axx = 0.0, axz = 0.0, azz = 0.0, sx = 0.0, sz = 0.0;
    int count = int(u_waterParams.z);
    for (int m = 0; m < count; ++m) {
        vec4 w = u_gerstner[m];
        float k = length(w.xy);
        float theta = dot(w.xy, rest) - sqrt(u_waterParams.y * k) * t - w.w;
        float ac = w.z * cos(theta) / k, as = w.z * sin(theta);
        axx += w.x * w.x * ac;
        axz += w.x * w.y * ac;
        azz += w.y * w.y * ac;
        sx += w.x * as;
        sz += w.y * as;
    }
    vec3 ta = vec3(1.0 - axx, -sx, -axz);   // ∂r/∂α in (x, y, z)
    vec3 tb = vec3(-axz, -sz, 1.0 - azz);   // ∂r/∂β
    vec3 n = cross(tb, ta);
    return -n.xz / max(n.y, 1e-4);
}

// Texture coordinate of world rest point p in cascade c (texel i sits at X = i·L/N).
vec3 cascadeCoord(vec2 p, int c) {
    return vec3(p / u_cascadeSize[c] + 0.5 / u_gridParams.w, float(c));
}
