// The cloud layer's pattern (docs/look.md#weather): fractal value noise on a layer at the
// cloud height, drifting with the wind aloft, thresholded so that about the cover's share of it
// is cloud. Written once for both languages: the sky's programs draw it (common_sky.glsl), and
// engine/gfx/clouds.cpp includes this file as C++ (glm's vec2/vec3/mat2 and functions) to find,
// once a frame, how much of the sun's direct light the cloud on the sun's own ray holds back.
// Only what GLSL 4.50 and glm share: float literals with an f, no swizzles, explicit arguments.
#ifndef COMMON_CLOUDS_GLSL
#define COMMON_CLOUDS_GLSL

#ifdef __cplusplus
#define CLOUD_CONST constexpr
#else
#define CLOUD_CONST const
#endif

CLOUD_CONST float CLOUD_SCALE_M = 3000.0f;  // the clouds' largest features (m on the layer)
CLOUD_CONST int CLOUD_OCTAVES = 5;
CLOUD_CONST float CLOUD_HIDES = 0.97f;      // how much of what lies behind a cloud's core it hides (the rest: a thin veil over the whole cover)

// Value noise in [0, 1] (a hash per lattice point, smooth between).
float cloudHash(vec2 p) {
    vec3 q = fract(vec3(p.x, p.y, p.x) * 0.1031f);
    q += dot(q, vec3(q.y, q.z, q.x) + 33.33f);
    return fract((q.x + q.y) * q.z);
}

float cloudNoise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    f = f * f * (3.0f - 2.0f * f);
    return mix(mix(cloudHash(i), cloudHash(i + vec2(1.0f, 0.0f)), f.x), mix(cloudHash(i + vec2(0.0f, 1.0f)), cloudHash(i + vec2(1.0f, 1.0f)), f.x), f.y);
}

// The clouds' density along dir, [0, 1], for a layer `height` m up covering `cover` of the sky,
// drifted by `drift` (m): toward the horizon the pattern shrinks below what the sky cube
// resolves, so it fades to its mean, the cover.
float cloudLayerDensity(vec3 dir, float cover, vec2 drift, float height) {
    if (cover <= 0.0f) return 0.0f;
    float up = max(dir.y, 0.0f);
    vec2 p = (vec2(dir.x, dir.z) / max(up, 0.02f) * height + drift) / CLOUD_SCALE_M;
    float n = 0.0f, a = 0.5f, total = 0.0f;
    for (int o = 0; o < CLOUD_OCTAVES; ++o) {
        n += a * cloudNoise(p);
        total += a;
        p = mat2(1.6f, 1.2f, -1.2f, 1.6f) * p + 7.1f;
        a *= 0.5f;
    }
    n /= total;
    float threshold = mix(0.72f, 0.28f, cover);
    float d = smoothstep(threshold - 0.06f, threshold + 0.10f, n);
    d = max(d, smoothstep(0.85f, 1.0f, cover));
    return mix(cover, d, smoothstep(0.03f, 0.25f, up));
}

// The share of the clear sky behind the clouds that they hide along dir (what the sky draws).
float cloudLayerOpacity(vec3 dir, float cover, vec2 drift, float height) {
    return CLOUD_HIDES * cloudLayerDensity(dir, cover, drift, height) + (1.0f - CLOUD_HIDES) * cover;
}

// The share of the sun's direct beam they hold back along dir: all of it behind a cloud's core
// (its optical depth is tens), at its edge as much as the density, in a gap the thin veil's.
float cloudLayerBeamLoss(vec3 dir, float cover, vec2 drift, float height) {
    return 1.0f - (1.0f - cloudLayerDensity(dir, cover, drift, height)) * (1.0f - (1.0f - CLOUD_HIDES) * cover);
}

#undef CLOUD_CONST
#endif
