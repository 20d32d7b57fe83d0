// The composite water surface (docs/references.md#composite-ocean): Gerstner waves (analytic) + FFT cascades
// (textures) + ripples, with normals added in slope form. The parameters: WaterUniforms
// (common_bindings.glsl).
#include "common_bindings.glsl"

// The water program is compiled per configuration (gfx::WaterVariant defines WATER_VARIANT and
// these as constants); other programs read them from the uniforms.
#ifndef WATER_VARIANT
#define WATER_CASCADES int(water.gridParams.z)
#define WATER_RIPPLES (water.rippleParams.w > 0.0)
#define WATER_FOAM_MAP (water.foamParams.w > 0.0)
#define WATER_CLOUDS (frame.sky.x > 0.0)
#endif

layout(binding = DISPLACEMENT_UNIT) uniform sampler2DArray u_displacement;  // layer c: (Dx, h, Dz, J)
layout(binding = SLOPES_UNIT) uniform sampler2DArray u_slopes;        // layer c: (dh/dx, dh/dz, J, |∇h|²)
layout(binding = RIPPLES_UNIT) uniform sampler2D u_ripples;            // ripple heights Vh(t) (m), 0 outside
layout(binding = FOAM_UNIT) uniform sampler2D u_foamMap;            // persistent foam coverage [0, 1], 0 outside
layout(binding = RIPPLE_SLOPES_UNIT) uniform sampler2D u_rippleSlopes;       // ripple (dh/dx, dh/dz) per cell, one cell of margin round the patch

layout(binding = RIPPLE_LEVELS_UNIT) uniform sampler2DArray u_rippleLevels;  // coarse levels' heights (m), layer L − 1, 0 outside
layout(binding = RIPPLE_LEVEL_SLOPES_UNIT) uniform sampler2DArray u_rippleLevelSlopes;  // their (dh/dx, dh/dz), one cell of margin

// The composite's weight of a level at grid position `cell` (centres at integers; the levels
// share N): 0 within the fade band of its border, 1 from twice it inwards, a smoothstep per
// axis between (RippleLevels' levelWeight, docs/ewave.md#levels).
float rippleLevelWeight(vec2 cell) {
    vec2 d = min(cell, water.rippleParams.w - 1.0 - cell);
    vec2 s = smoothstep(vec2(water.rippleFade.y), vec2(2.0 * water.rippleFade.y), d);
    return s.x * s.y;
}

// The coarse levels' share of the composite after level 0 took `weight` of value0; `slope`:
// the slope layer instead of the height (the weights' own gradient left out, see docs/ewave.md).
vec2 rippleLevels(vec2 world, vec2 value0, float weight, bool slope) {
    vec2 sum = weight * value0;
    float rest = 1.0 - weight;
    int count = int(water.rippleFade.x);
    for (int L = 0; L < count && rest > 0.0; ++L) {
        vec2 c = (world - water.rippleLevels[L].xy) / water.rippleLevels[L].z;
        float w = L == count - 1 ? 1.0 : rippleLevelWeight(c);
        vec2 v = slope ? textureLod(u_rippleLevelSlopes, vec3((c + 1.5) / (water.rippleParams.w + 2.0), float(L)), 0.0).xy
                       : vec2(textureLod(u_rippleLevels, vec3((c + 0.5) / water.rippleParams.w, float(L)), 0.0).r, 0.0);
        sum += rest * w * v;
        rest *= 1.0 - w;
    }
    return sum;
}

// Ripple height at world (x, z) (bilinear between cell centres; 0 outside the patch); with
// coarse levels the composite, cross-faded as the CPU's RipplePatch::heightAt.
float rippleHeight(vec2 world) {
    if (!WATER_RIPPLES) return 0.0;
    vec2 cell = (world - water.rippleParams.xy) / water.rippleParams.z;
    float h = textureLod(u_ripples, (cell + 0.5) / water.rippleParams.w, 0.0).r;
    if (water.rippleFade.x == 0.0) return h;
    return rippleLevels(world, vec2(h, 0.0), rippleLevelWeight(cell), false).x;
}

// Persistent foam coverage at world (x, z) (bilinear between cell centres; 0 outside the map),
// faded out over the outer tenth of the map so that a map following a ship leaves no straight edge.
float foamCoverage(vec2 world) {
    if (!WATER_FOAM_MAP) return 0.0;
    vec2 cell = (world - water.foamParams.xy) / water.foamParams.z;
    vec2 fromEdge = min(cell + 0.5, water.foamParams.w - 0.5 - cell);
    float fade = smoothstep(0.0, 0.1 * water.foamParams.w, min(fromEdge.x, fromEdge.y));
    return fade * textureLod(u_foamMap, (cell + 0.5) / water.foamParams.w, 0.0).r;
}

// True inside the ripple patch (plus one cell); with coarse levels, inside the coarsest.
bool inRipplePatch(vec2 world) {
    if (!WATER_RIPPLES) return false;
    int last = int(water.rippleFade.x) - 1;
    vec4 grid = last < 0 ? water.rippleParams : vec4(water.rippleLevels[last].xyz, water.rippleParams.w);
    vec2 cell = (world - grid.xy) / grid.z;
    return all(greaterThan(cell, vec2(-1.0))) && all(lessThan(cell, vec2(grid.w)));
}

// Ripple slope (dh/dx, dh/dz) at world (x, z): central differences over one cell of the
// bilinear heights. Interpolating is linear, so that equals the bilinear interpolation of each
// cell's central difference, which the renderer stores beside the heights (one lookup, not four;
// texel (i + 1, j + 1) is cell (i, j), so the margin holds the differences against the zero outside).
// With coarse levels: each level's slope, cross-faded with the heights' weights.
vec2 rippleSlope(vec2 world) {
    if (!inRipplePatch(world)) return vec2(0.0);
#ifdef WATER_FULL_QUALITY
    float h = water.rippleParams.z;
    return vec2(rippleHeight(world + vec2(h, 0.0)) - rippleHeight(world - vec2(h, 0.0)),
                rippleHeight(world + vec2(0.0, h)) - rippleHeight(world - vec2(0.0, h))) / (2.0 * h);
#else
    vec2 cell = (world - water.rippleParams.xy) / water.rippleParams.z;
    vec2 s = textureLod(u_rippleSlopes, (cell + 1.5) / (water.rippleParams.w + 2.0), 0.0).xy;
    if (water.rippleFade.x == 0.0) return s;
    return rippleLevels(world, s, rippleLevelWeight(cell), true);
#endif
}

// The projected grid point (u, v): homogeneous bilinear interpolation, w clamped ([Lee2007]).
vec2 gridPoint(vec2 uv) {
    vec4 p = mix(mix(water.corner[0], water.corner[1], uv.x), mix(water.corner[2], water.corner[3], uv.x), uv.y);
    return p.xz / max(p.w, water.waterParams.w);
}

// Gerstner waves at rest point (α, β), time t (docs/references.md#gerstner-waves), in one pass over the waves:
// the displacement (x − α, y, z − β), and the slope (∂y/∂x, ∂y/∂z) of the displaced surface
// from the analytic normal n = ∂r/∂β × ∂r/∂α, as −n.xz / n.y. `spacing` (m): the distance
// between the grid's vertices there (0: exact). A wave shorter than three spacings fades out
// (gone at three, whole at six): sampled by vertices further apart than half its length it
// would alias into a regular pattern of false, longer waves (seen at the horizon).
void gerstner(vec2 rest, float t, float spacing, out vec3 offset, out vec2 slope) {
    offset = vec3(0.0);
    float axx = 0.0, axz = 0.0, azz = 0.0, sx = 0.0, sz = 0.0;
    int count = int(water.waterParams.z);
    for (int m = 0; m < count; ++m) {
        vec4 w = water.gerstner[m];
        float k = length(w.xy);
        float theta = dot(w.xy, rest) - sqrt(water.waterParams.y * k) * t - w.w;
        float c = cos(theta), s = sin(theta);
        float wavelength = 6.2831853 / k;
        float a = w.z * (1.0 - smoothstep(wavelength / 6.0, wavelength / 3.0, spacing));
        offset.xz -= (w.xy / k) * a * s;
        offset.y += a * c;
        float ac = a * c / k, as = a * s;
        axx += w.x * w.x * ac;
        axz += w.x * w.y * ac;
        azz += w.y * w.y * ac;
        sx += w.x * as;
        sz += w.y * as;
    }
    vec3 ta = vec3(1.0 - axx, -sx, -axz);   // ∂r/∂α in (x, y, z)
    vec3 tb = vec3(-axz, -sz, 1.0 - azz);   // ∂r/∂β
    vec3 n = cross(tb, ta);
    slope = -n.xz / max(n.y, 1e-4);
}

// Texture coordinate of world rest point p in cascade c (texel i sits at X = i·L/N).
vec3 cascadeCoord(vec2 p, int c) {
    return vec3(p / water.cascadeSize[c] + 0.5 / water.gridParams.w, float(c));
}

// Weight of cascade c at rest point p: 1 near the eye, fading to 0 between the cascade's two
// fade distances, so far away no tile repeats in a regular pattern (the Gerstner waves, which
// never repeat, carry the far field). Needs common_frame.glsl for the eye.
float cascadeWeight(vec2 p, int c) {
    if (water.cascadeFadeEnd[c] <= 0.0) return 1.0;
    return 1.0 - smoothstep(water.cascadeFade[c], water.cascadeFadeEnd[c], length(p - frame.cameraPositionTime.xz));
}
