#version 450 core
#include "common_bindings.glsl"
// Fast approximate anti-aliasing of the finished (tone-mapped) frame, after Lottes' FXAA 3.11
// "quality" scheme: find the pixels on a luma edge, the edge's direction and its two ends
// along it, and blend each pixel toward its neighbour across the edge by how far it sits
// from the nearer end; a sub-pixel term softens single-pixel features. Drawn at the source's
// size. A frame drawn smaller (render.resolution_scale < 1) is scaled up after this pass by a
// bilinear draw, so here its pixels off the edges are sharpened first (after AMD's
// contrast-adaptive sharpening, on luma) so the scaled-up frame does not look blurred.
// Drawn twice (a software rasteriser runs every branch for every pixel, but skips blocks that
// fail the depth test): FXAA_OFF_EDGES writes the pixels off the edges (about 8% of a sea's
// pixels are on one) and marks them at depth 0, discarding the others; compiled without it,
// drawn at depth 1 with the test LEQUAL, it walks the edges for the pixels left.
in vec2 v_ndc;
layout(binding = POST_SOURCE_UNIT) uniform sampler2D u_source;  // rgb display-encoded colour, a its luma; linear filtered
layout(location = FXAA_TEXEL_LOCATION) uniform vec2 u_texel;       // 1 / source size (uv per source pixel)
layout(location = FXAA_SHARPNESS_LOCATION) uniform float u_sharpness;  // [0, 1]: 0 none (drawn at the output size), 1 the most
out vec4 o_color;

// Contrast below max(EDGE_MIN, EDGE_RELATIVE · brightest) is not an edge: most pixels stop there.
const float EDGE_MIN = 0.0833;
const float EDGE_RELATIVE = 0.166;
// How much of the sub-pixel term applies (0 = none, 1 = soft).
const float SUBPIXEL = 0.75;
// Steps (in source pixels) of the walk along the edge; an end further away is taken as the last.
const int WALK_STEPS = 5;
const float WALK[WALK_STEPS] = float[](1.0, 1.5, 2.0, 4.0, 12.0);

float lumaAt(vec2 uv) { return textureLod(u_source, uv, 0.0).a; }

// The colour c of a pixel whose luma is m and its cross n, s, e, w: its luma pushed away from
// the cross's mean by a negative-lobe filter, (L + k·Σcross) / (1 + 4k), k = −sharpness·amp/5,
// where amp shrinks as the cross nears black or white (no clipped halos); the luma's change is
// added to every channel, so the hue stays.
vec3 sharpen(vec3 c, float m, float n, float s, float e, float w) {
    float lo = min(min(min(n, s), min(e, w)), m), hi = max(max(max(n, s), max(e, w)), m);
    float amp = sqrt(clamp(min(lo, 1.0 - hi) / max(hi, 1e-4), 0.0, 1.0));
    float k = -0.2 * u_sharpness * amp;
    float luma = dot(c, vec3(0.299, 0.587, 0.114));
    float sharpened = (luma + k * (n + s + e + w)) / (1.0 + 4.0 * k);
    return clamp(c + (sharpened - luma), 0.0, 1.0);
}

void main() {
    vec2 uv = v_ndc * 0.5 + 0.5;
    // The 3×3 lumas around the source pixel: two gathers of four (each a 2×2 block, in the
    // order (−x +y), (+x +y), (+x −y), (−x −y) around the block's shared corner).
    vec2 centre = (floor(uv / u_texel) + 0.5) * u_texel;
    vec4 lower = textureGather(u_source, centre - 0.5 * u_texel, 3);  // w, m, s, sw
    vec4 upper = textureGather(u_source, centre + 0.5 * u_texel, 3);  // n, ne, e, m
    float m = lower.y, w = lower.x, s = lower.z, sw = lower.w, n = upper.x, ne = upper.y, e = upper.z;
    float brightest = max(max(max(n, s), max(e, w)), m);
    float range = brightest - min(min(min(n, s), min(e, w)), m);
#ifdef FXAA_OFF_EDGES
    if (range >= max(EDGE_MIN, EDGE_RELATIVE * brightest)) discard;
    // Off the edges: as drawn, sharpened when it is to be scaled up.
    o_color = vec4(sharpen(textureLod(u_source, uv, 0.0).rgb, m, n, s, e, w), 1.0);
    gl_FragDepth = 0.0;
    return;
#endif
    float nw = textureLodOffset(u_source, centre, 0.0, ivec2(-1, 1)).a;
    float se = textureLodOffset(u_source, centre, 0.0, ivec2(1, -1)).a;

    // --- direction: the luma's second difference across rows (a horizontal edge) against
    // across columns (a vertical edge), the centre row/column weighted twice.
    float acrossRows = 2.0 * abs(n - 2.0 * m + s) + abs(ne - 2.0 * e + se) + abs(nw - 2.0 * w + sw);
    float acrossColumns = 2.0 * abs(e - 2.0 * m + w) + abs(ne - 2.0 * n + nw) + abs(se - 2.0 * s + sw);
    bool horizontal = acrossRows >= acrossColumns;
    // `across` steps to the neighbour on the edge's other side, `along` walks the edge.
    vec2 across = horizontal ? vec2(0.0, u_texel.y) : vec2(u_texel.x, 0.0);
    vec2 along = horizontal ? vec2(u_texel.x, 0.0) : vec2(0.0, u_texel.y);
    float positive = horizontal ? n : e, negative = horizontal ? s : w;
    float gradientPositive = abs(positive - m), gradientNegative = abs(negative - m);
    float other = positive;
    if (gradientNegative > gradientPositive) {
        across = -across;
        other = negative;
    }
    float gradient = max(gradientPositive, gradientNegative);

    // --- walk both ways along the line between the two pixels (a bilinear lookup there reads
    // their mean) until the mean departs from the edge's by a quarter of the gradient.
    float edgeLuma = 0.5 * (m + other);
    float threshold = 0.25 * gradient;
    vec2 start = centre + 0.5 * across;
    vec2 toA = start, toB = start;
    float deltaA = 0.0, deltaB = 0.0;
    bool endA = false, endB = false;
    for (int i = 0; i < WALK_STEPS && !(endA && endB); ++i) {
        if (!endA) {
            toA -= WALK[i] * along;
            deltaA = lumaAt(toA) - edgeLuma;
            endA = abs(deltaA) >= threshold;
        }
        if (!endB) {
            toB += WALK[i] * along;
            deltaB = lumaAt(toB) - edgeLuma;
            endB = abs(deltaB) >= threshold;
        }
    }
    float distanceA = dot(centre - toA, along) / dot(along, along);
    float distanceB = dot(toB - centre, along) / dot(along, along);
    bool nearerA = distanceA < distanceB;
    float nearest = min(distanceA, distanceB);
    // The edge ends on the centre's side of the step only when the luma there moves the
    // other way from the centre's: then the pixel lies under the slanted part and blends.
    float endDelta = nearerA ? deltaA : deltaB;
    bool blends = (endDelta < 0.0) != (m - edgeLuma < 0.0);
    float edgeBlend = blends ? 0.5 - nearest / (distanceA + distanceB) : 0.0;

    // --- sub-pixel: a pixel unlike the weighted mean of its 3×3 block is softened toward it.
    float mean = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
    float subpixel = smoothstep(0.0, 1.0, clamp(abs(mean - m) / range, 0.0, 1.0));
    float blend = max(edgeBlend, subpixel * subpixel * SUBPIXEL);
    o_color = vec4(textureLod(u_source, uv + blend * across, 0.0).rgb, 1.0);
}
