// Foam on the water (docs/splash_foam.md §6): a density from the sea (whitecaps where the FFT
// Jacobian folds, steep ripples) and the persistent foam map's coverage; drawn as three scales of
// structure (streaks along the wind, lace, bubbles) whose opacity ramps softly with the density
// (no hard threshold), averaged toward its exact mean where the pixel covers the pattern (no
// shimmer at a distance), lit as a rough white surface by the sun (N·L) and the sky, and thinner,
// greyer and more transparent as its coverage decays (coverage stands for age: the map's foam
// falls as e^(−t/τ)). Needs common_sky.glsl, common_water.glsl and common_detail.glsl.
layout(binding = FOAM_PATTERN_UNIT) uniform sampler2D u_foamPattern;  // foamPattern() baked over its repeat, RGBA8 (du, dv as 0.5 + 0.5·x)

const float FOAM_TILE = 5.0;            // m per repeat of the lace (foamPattern's first octave; its others 1.9 m, 0.68 m)
const float FOAM_STREAK_STRETCH = 3.0;  // the lace is this many times longer along the wind than across it
// From a gale up the wind tears the foam into spume blown in streaks along it (Beaufort force 8,
// 17.2 m/s: "foam blown in well-marked streaks along the direction of the wind"; force 10,
// 24.5 m/s: "dense white streaks"): the lace is drawn out from FOAM_STREAK_STRETCH to this.
const float FOAM_SPUME_STRETCH = 10.0;
const vec2 FOAM_SPUME_WIND = vec2(17.2, 24.5);  // U10 (m/s) where the spume streaks begin and where they are whole
const float FOAM_DENSE = 0.9;           // the share of the pattern dense foam (coverage 1) covers
const float FOAM_SOFT = 0.45;           // width of the lace's opacity ramp, in pattern units: soft edges everywhere
const float FOAM_WARP = 1.0;            // foam map cells the lookup is pushed by the DU/DV field, at most
const vec3 FOAM_ALBEDO_FRESH = vec3(0.82, 0.85, 0.86);  // fresh whitecap foam (Koepke 1984: ~0.55 effective over a patch of which it is a part)
const vec3 FOAM_ALBEDO_OLD = vec3(0.55, 0.60, 0.62);    // old foam: a thin film of bubbles over the water, greyer
// Fresh foam (docs/look.md#fresh-foam): bubbles at a second, finer scale (this many times the
// first, 0.4 m to 6 cm) open holes through it, where either octave is low, as wide as this
// share of the pattern's range; its opacity grows with its coverage as a layer's of that
// thickness, 1 − e^(−k·c) (normalised to 1 at c = 1), so thin foam shows the water through.
const float FOAM_FRESH_SCALE = 2.3;
const float FOAM_FRESH_OFFSET = 0.17;
const float FOAM_HOLE_BELOW = 0.24;  // pattern values below this are open water
const float FOAM_HOLE_WIDTH = 0.2;
const float FOAM_THICKNESS = 2.5;
// One octave's open share averaged over the pattern (its values uniform on [0, 1], as foamPattern is made).
const float FOAM_HOLES_MEAN = 1.0 - FOAM_HOLE_BELOW - 0.5 * FOAM_HOLE_WIDTH;
const vec3 FOAM_SKY = vec3(0.30, 0.38, 0.48);           // skylight on an upward rough surface by day: about the day dome's mean radiance (common_sky.glsl)
const vec3 FOAM_SKY_OVERCAST = vec3(0.21, 0.22, 0.24);  // ...under an overcast: its grey dome's mean (cloudRadiance)

// ∫ clamp(u, 0, 1) du from −∞ to x.
float foamRampIntegral(float x) { return x <= 0.0 ? 0.0 : (x < 1.0 ? 0.5 * x * x : x - 0.5); }

// The lace's opacity ramp at pattern value p, threshold t: clamp((p − t)/FOAM_SOFT + ½, 0, 1).
float foamRamp(float p, float t) { return clamp((p - t) / FOAM_SOFT + 0.5, 0.0, 1.0); }

// Its mean over the pattern (p uniform on [0, 1], as foamPattern() is made): what a pixel that
// covers many cells of the pattern sees, exactly, not the ramp of the averaged pattern.
float foamRampMean(float t) {
    return FOAM_SOFT * (foamRampIntegral((1.0 - t) / FOAM_SOFT + 0.5) - foamRampIntegral(-t / FOAM_SOFT + 0.5));
}

// How far a pixel averages a pattern of which it spans `repeats` repeats: 0 it resolves it, 1 it
// covers several of its finer cells (~a sixth of a repeat) and should see its mean.
float foamBlur(float repeats) { return smoothstep(0.04, 0.25, repeats); }

// The whitecaps' density at the per-pixel Jacobian J (J − 1 summed over the cascades): ½ at the
// threshold that leaves the wind's whitecap share of the sea below it (water.farFade.y,
// foam_whitecaps.h), ramping over one σ of J (farFade.z) either side; without a wind-derived
// threshold (σ = 0), from J = 0.6 to 0.1.
float foamWhitecaps(float jacobian) {
    float sigma = water.farFade.z;
    if (sigma <= 0.0) return smoothstep(0.6, 0.1, jacobian);
    return clamp(0.5 + (water.farFade.y - jacobian) / (2.0 * sigma), 0.0, 1.0);
}

// The colour with foam over it at world point `world`: `n` the water's normal, `sun` toward the
// sun, `jacobian` the sea's (1 flat, ≤ 0 folded), `rippleSlope` |∇h| of the ripples, `detail`
// the detail map's (du, dv, streaks) there.
vec3 shadeFoam(vec3 color, vec2 world, vec3 n, vec3 sun, float jacobian, float rippleSlope, vec3 detail) {
    float density = max(foamWhitecaps(jacobian), smoothstep(0.12, 0.45, rippleSlope));
    // --- the lace, laid along the wind (streaks), and the bubbles in it
    float angle = water.farFade.w;
    vec2 along = vec2(cos(angle), sin(angle));
    float stretch = mix(FOAM_STREAK_STRETCH, FOAM_SPUME_STRETCH, smoothstep(FOAM_SPUME_WIND.x, FOAM_SPUME_WIND.y, water.glitterParams.y));
    vec2 fuv = vec2(dot(world, along) / stretch, dot(world, vec2(-along.y, along.x))) / FOAM_TILE;
    // The bubbles (FOAM_BUBBLE_SCALE times finer: 1 m to 0.14 m) baked beside the lace.
#ifdef WATER_FULL_QUALITY
    vec3 lace = foamPattern(fuv);
    float bubbles = foamPattern(fuv * FOAM_BUBBLE_SCALE + FOAM_BUBBLE_OFFSET).z;
#else
    vec4 baked = texture(u_foamPattern, fuv / FOAM_PATTERN_REPEAT);
    vec3 lace = decodeDetail(baked);
    float bubbles = baked.a;
#endif
    if (WATER_FOAM_MAP) {
        // The map read at a point pushed up to FOAM_WARP cells by the pattern's DU/DV, so its
        // edges follow the lace rather than the cells.
        density = max(density, min(foamCoverage(world + lace.xy * FOAM_WARP * water.foamParams.z), 1.0));
    }
    // (the derivatives before any branch)
    vec2 span = fwidth(fuv);
    float repeats = max(span.x, span.y);
    float laceBlur = foamBlur(repeats), bubbleBlur = foamBlur(repeats * FOAM_BUBBLE_SCALE);
    float fineBlur = foamBlur(repeats * FOAM_BUBBLE_SCALE * FOAM_FRESH_SCALE);
#ifndef WATER_FULL_QUALITY
    // The fine bubbles' lookup before any branch, with the pixel's own derivatives: a software
    // rasteriser pays every branch's work anyway, and with explicit ones (textureGrad, as a
    // branch would need) paid more for it; a GPU pays one RGBA8 lookup a water pixel.
    float fineBubbles = texture(u_foamPattern, (fuv * FOAM_FRESH_SCALE + FOAM_FRESH_OFFSET) / FOAM_PATTERN_REPEAT).a;
#endif
    if (density <= 0.0) return color;
    // --- opacity: the lace's soft ramp (thinner as the density falls), the bubbles' holes,
    // both tending to their means where the pixel averages them; thin old foam lets water through
    float t = 1.0 - FOAM_DENSE * density;
    float laceAlpha = mix(foamRamp(lace.z, t), foamRampMean(t), laceBlur);
    float holes = mix(0.55 + 0.45 * bubbles, 0.775, bubbleBlur);
    float alpha = laceAlpha * holes * (0.1 + 0.9 * density * density);
    // fresh foam: holes where either bubble octave is low, soft-rimmed, each octave's toward its
    // mean where the pixel averages it; the lace's soft ramp above carries the rim along the coverage
    if (density > 0.5) {
#ifdef WATER_FULL_QUALITY
        float fineBubbles = foamPattern((fuv * FOAM_FRESH_SCALE + FOAM_FRESH_OFFSET) * FOAM_BUBBLE_SCALE + FOAM_BUBBLE_OFFSET).z;
#endif
        float open = mix(smoothstep(0.0, FOAM_HOLE_WIDTH, bubbles - FOAM_HOLE_BELOW), FOAM_HOLES_MEAN, bubbleBlur) *
                     mix(smoothstep(0.0, FOAM_HOLE_WIDTH, fineBubbles - FOAM_HOLE_BELOW), FOAM_HOLES_MEAN, fineBlur);
        float thickness = (1.0 - exp(-FOAM_THICKNESS * density)) / (1.0 - exp(-FOAM_THICKNESS));
        alpha = mix(alpha, laceAlpha * open * thickness, smoothstep(0.5, 1.0, density));
    }
    // --- light: a rough white surface lying on the water (Lambert), greyer as it ages
    vec3 albedo = mix(FOAM_ALBEDO_OLD, FOAM_ALBEDO_FRESH, smoothstep(0.1, 0.9, density));
    vec3 light = frame.sunLight.rgb * frame.sunLight.w * sunTint(sun) * max(dot(n, sun), 0.0) + mix(FOAM_SKY, FOAM_SKY_OVERCAST, cloudCover()) * daylight(sun);
    return mix(color, albedo * light, alpha);
}
