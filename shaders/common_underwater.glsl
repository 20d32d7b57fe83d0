// The view from under water (docs/frame.md, "Under water"): per-channel extinction by
// Jerlov's oceanic water type I ([Jerlov1976] Kd at 650/550/450 nm), the water's own in-scattered
// light and the per-pixel waterline test at the near plane; the surface seen from below is in
// common_underwater_surface.glsl. Needs common_frame.glsl.
#ifndef COMMON_UNDERWATER_GLSL
#define COMMON_UNDERWATER_GLSL

// Diffuse attenuation coefficient Kd (1/m) of Jerlov's oceanic type I water for the red, green
// and blue channels, read at 650, 550 and 450 nm ([Jerlov1976] Table XXVI). Used as the view
// path's extinction: forward-scattered light stays near its beam, so an image fades at about
// Kd rather than at the beam attenuation c = a + b ([Jerlov1976] in docs/references.md).
const vec3 UNDERWATER_KD = vec3(0.36, 0.063, 0.019);
// The surface's colour seen glancing from below, by the sun's height above the horizon, is the
// in-scattered light's: brightest looking up, a tenth of it looking straight down.
const float INSCATTER_UP = 0.6, INSCATTER_SLOPE = 0.5;

// Fraction of light per channel left after `d` metres of water.
vec3 underwaterTransmittance(float d) { return exp(-UNDERWATER_KD * max(d, 0.0)); }

// The water's own radiance along a ray in `dir` that meets nothing (linear): the body colour lit
// by the daylight that reaches the eye's depth (dimmed per channel by Kd over it), brighter
// toward the surface. Every extinction fades toward it, so far things meet the background.
vec3 underwaterInscatter(vec3 dir) {
    vec3 lit = waterBodyColor() * underwaterTransmittance(frame.waterline.w);
    return lit * max(INSCATTER_UP + INSCATTER_SLOPE * dir.y, 0.1);
}

// What `color` becomes over `dist` metres of water seen along `dir` (from the eye): Beer–Lambert
// per channel, plus the in-scattered light of the same path.
vec3 underwaterExtinction(vec3 color, float dist, vec3 dir) {
    vec3 t = underwaterTransmittance(dist);
    return color * t + underwaterInscatter(dir) * (1.0 - t);
}

// True where the pixel's point on the near plane lies under the water: the affine function of
// the pixel that frame.waterline holds (its height above the water's tangent plane at the eye).
bool pixelUnderwater(vec2 fragCoord) {
    vec2 ndc = 2.0 * fragCoord / frame.viewport.xy - 1.0;
    return dot(frame.waterline.xyz, vec3(ndc, 1.0)) < 0.0;
}

#endif
