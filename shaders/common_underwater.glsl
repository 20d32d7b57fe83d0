// The view from under water (docs/frame.md, "Under water"): per-channel extinction by
// Jerlov's oceanic water type I ([Jerlov1976] Kd at 650/550/450 nm), the water's own in-scattered
// light and the per-pixel waterline test at the near plane; the surface seen from below is in
// common_underwater_surface.glsl. Also the exposure under water, the light shafts and the
// caustics on bodies (docs/frame.md, "Under water"). Needs common_frame.glsl.
#ifndef COMMON_UNDERWATER_GLSL
#define COMMON_UNDERWATER_GLSL

#include "common_sky.glsl"
#include "common_fresnel.glsl"

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

// Exposure under water: radiance entering the water through the surface grows by n² (the same
// flux in a solid angle narrowed by n²), so Snell's window is n² brighter than the sky it shows;
// the eye (or a camera's metering) adapts to that brightest thing in view. The frame under water
// is exposed 1/n² of the frame above: the window's sky comes out near where the sky itself does
// above water, on the filmic curve's slope instead of its shoulder, and keeps its gradient.
const float UNDERWATER_EXPOSURE = 1.0 / (WATER_IOR * WATER_IOR);
const float UNDERWATER_HUE_KEPT_FROM = 0.25;

// finalColor (common_frame.glsl) for a pixel under the water: the under-water exposure, and the
// filmic curve applied to the colour's largest channel with the others scaled alike (the hue
// kept), so a bright window rolls off toward its own colour instead of each channel clipping
// on its own into a flat cyan. Dim colours (the deep, bodies) keep the per-channel curve as above
// water; the hue-kept one takes over from this exposed peak up to 1.
vec4 finalColorUnderwater(vec3 radiance, vec2 pixel) {
    if (linearTarget()) return vec4(radiance, 1.0);
    vec3 x = radiance * frame.waterColorExposure.w * UNDERWATER_EXPOSURE;
    float peak = max(max(x.r, x.g), max(x.b, 1e-6));
    vec3 kept = x * (toneCurve(vec3(peak)).r / peak);
    return encodeDisplay(mix(toneCurve(x), kept, smoothstep(UNDERWATER_HUE_KEPT_FROM, 1.0, peak)), pixel);
}

// Light shafts and caustics: sunlight focused by the waves into bright sheets that run down
// along the refracted sun's direction. The focusing pattern is an analytic stand-in (five
// drifting plane waves), not the sea's own waves; a point's light is the pattern where the sun's
// ray to it crossed the mean level, its contrast blurred away with depth (the sun's 0.5° disk and
// the forward scattering widen each sheet). Along a view ray the shafts are the single scattering
// of that light (Henyey–Greenstein phase). Every factor along the ray is exp(linear in t) or a
// sine of a phase linear in t, so the integral is closed-form: no samples, no noise.
// frame.shading.w is render.light_shafts (0 switches both off).
const float SHAFT_SCATTER = 0.03;       // b, 1/m: scattering coefficient of clear ocean water (Jerlov I: 0.02–0.04)
const float SHAFT_PHASE_G = 0.75;       // Henyey–Greenstein asymmetry (sea water scatters forward)
const float SHAFT_RANGE_M = 40.0;       // the view ray's length that is summed (blue fades to 47 % over it)
const float SHAFT_BLUR_DEPTH_M = 12.0;  // depth over which the pattern's contrast falls to 1/e
const float SHAFT_WAVE_AMPLITUDE = 0.3;  // each wave's share of the sheets' light at the surface (1 ± 0.3 per wave)
const float SHAFT_SUN = 1.4;            // the sunlight's strength, as the objects' (object_mesh.frag)
// The pattern's plane waves: wave vector (rad/m) and drift (rad/s); 2.4–3.3 m apart, their
// directions spread round the circle (each wave's sheets, seen edge-on, make the rays that
// leave the refracted sun along one great circle).
const int SHAFT_WAVE_COUNT = 5;
const vec3 SHAFT_WAVES[SHAFT_WAVE_COUNT] = vec3[SHAFT_WAVE_COUNT](vec3(1.9, 0.6, 0.9), vec3(-0.7, 1.6, -1.1), vec3(-1.7, -1.8, 0.7),
                                                                  vec3(0.4, -2.5, -0.8), vec3(2.2, -1.1, 1.2));

// Direction toward the sun seen from under a flat surface (Snell: sin θw = sin θair / n); the
// sun at or below the horizon refracts at the critical angle.
vec3 refractedSunUp(vec3 sun) {
    vec3 s = normalize(vec3(sun.x, max(sun.y, 1e-3), sun.z));
    return -refract(-s, vec3(0.0, 1.0, 0.0), 1.0 / WATER_IOR);
}

// The sunlight's caustic factor at the world point `p` under water: the pattern's first three waves,
// CAUSTIC_SCALE times finer than the shafts' sheets (those are the caustics blurred by the sun's
// disk and the scattering over tens of metres), at the point where the sun's ray to `p`
// crossed the mean level, their sum sharpened (7.7·u⁴, u = ½ + sum / 6: mean 1 for three
// independent phases, 0 to 7.7) and toward 1 with depth; 1 with the switch off.
const float CAUSTIC_SCALE = 2.5;
float underwaterCaustics(vec3 p) {
    vec3 up = refractedSunUp(frame.sunDirectionFresnel.xyz);
    float depth = max(-p.y, 0.0), time = frame.cameraPositionTime.w;
    vec2 q = (p.xz + up.xz / up.y * depth) * CAUSTIC_SCALE;
    float g = 0.0;
    for (int i = 0; i < 3; ++i) g += sin(dot(q, SHAFT_WAVES[i].xy) + SHAFT_WAVES[i].z * time);
    float u = 0.5 + g / 6.0, u2 = u * u;
    float focus = 1.0 + exp(-depth / SHAFT_BLUR_DEPTH_M) * (7.7 * u2 * u2 - 1.0);  // E[u⁴] = 0.13
    return mix(1.0, focus, min(frame.shading.w, 1.0));
}

// ∫0^L exp(−s·t) dt per channel, safe where s is near 0 (s may be negative: a ray up the shaft).
vec3 shaftExpIntegral(vec3 s, float len) {
    vec3 x = s * len;
    return mix((1.0 - exp(-x)) / (s + 1e-8), len * (1.0 - 0.5 * x), lessThan(abs(x), vec3(1e-3)));
}

// The shafts' radiance added along `dist` metres of a ray in `dir` from `origin` (linear):
// ∫ b·p(θ)·E(x)·T(t) dt, E the sunlight at x (dimmed per channel over its slanted path down,
// times 1 + 0.3·exp(−depth/blur)·sum of the five sines; its integral is kept ≥ 0), T the ray's
// transmittance, θ between the ray and the refracted sun. Along x = origin + dir·t the depth, the
// light's path and each sine's phase are linear in t: ∫ exp(−s t) sin(α + β t) dt = Im[e^{iα}(1 − e^{(−s+iβ)L})/(s − iβ)].
// `sheets` false keeps the mean light only (the waves' terms compile out): for the rays the
// surface mirrors, cheaper, and blurred there anyway by the surface's slopes.
vec3 underwaterShafts(vec3 origin, vec3 dir, float dist, const bool sheets) {
    if (frame.shading.w <= 0.0) return vec3(0.0);
    vec3 sun = frame.sunDirectionFresnel.xyz;
    vec3 up = refractedSunUp(sun);
    float g = SHAFT_PHASE_G, cosT = dot(dir, up);
    float phase = (1.0 - g * g) / (4.0 * 3.14159265 * pow(1.0 + g * g - 2.0 * g * cosT, 1.5));
    float len = min(dist, SHAFT_RANGE_M);
    // depth(t) = d0 + d1·t; the sun's crossing point q(t) = q0 + q1·t.
    float d0 = -origin.y, d1 = -dir.y;
    vec2 slant = up.xz / up.y;
    vec2 q0 = origin.xz + slant * d0, q1 = dir.xz + slant * d1;
    vec3 s = UNDERWATER_KD * (1.0 + d1 / up.y);  // the light's path down and the view path
    vec3 mean = exp(-UNDERWATER_KD * (d0 / up.y)) * shaftExpIntegral(s, len);
    vec3 sb = s + d1 / SHAFT_BLUR_DEPTH_M, fade = exp(-sb * len), waves = vec3(0.0);
    for (int i = 0; i < (sheets ? SHAFT_WAVE_COUNT : 0); ++i) {
        float a = dot(q0, SHAFT_WAVES[i].xy) + SHAFT_WAVES[i].z * frame.cameraPositionTime.w;
        float b = dot(q1, SHAFT_WAVES[i].xy);
        vec3 re = cos(a) - fade * cos(a + b * len), im = sin(a) - fade * sin(a + b * len);
        waves += (re * b + im * sb) / (sb * sb + b * b + 1e-8);
    }
    waves *= exp(-UNDERWATER_KD * (d0 / up.y) - d0 / SHAFT_BLUR_DEPTH_M) * SHAFT_WAVE_AMPLITUDE;
    vec3 light = frame.sunLight.rgb * sunTint(sun) * SHAFT_SUN;
    return light * (frame.shading.w * SHAFT_SCATTER * phase) * max(mean + waves, 0.0);
}

#endif
