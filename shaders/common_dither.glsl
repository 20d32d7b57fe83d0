// Dither of a colour about to be stored in 8 bits: triangular-PDF noise of ±1 LSB (the sum of
// two uniform noises, range (−1, 1) LSB) added before the rounding, so the rounding error is
// independent of the signal in its mean and variance (Lipshitz, Wannamaker & Vanderkooy 1992):
// a gradient of less than a level per pixel turns into fine noise instead of visible steps.
// The noise is a hash of the pixel (no time): a frame is the same in every run.
#ifndef COMMON_DITHER_GLSL
#define COMMON_DITHER_GLSL

// Three well mixed 32-bit words from three (Jarzynski & Olano 2020, "Hash functions for GPU
// rendering", pcg3d): a few integer operations, no visible structure at any scale.
uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// `display` (encoded colour, 0..1) plus TPDF noise of `lsb` levels of 1/255 per channel, each
// channel its own noise: the two uniform noises are the low and high 16 bits of its hash word
// (one hash a pixel; 16 bits resolve the noise far below a level). `pixel` is gl_FragCoord.xy;
// lsb 0 returns the colour unchanged.
vec3 dither8(vec3 display, vec2 pixel, float lsb) {
    uvec3 h = pcg3d(uvec3(uvec2(pixel), 0u));
    const float UNIT = 1.0 / 65536.0;  // a 16-bit word to [0, 1)
    vec3 a = vec3(h & 0xffffu) * UNIT;
    vec3 b = vec3(h >> 16u) * UNIT;
    return display + (a + b - 1.0) * (lsb / 255.0);
}

#endif
