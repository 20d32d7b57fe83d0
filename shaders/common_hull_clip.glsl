// Hull clip volumes: the water surface is not drawn inside a floating hull, so no sea shows in a
// hull where the waves rise above its deck or in an open boat (as Crest's clip surface and the
// boat "water-tight" masks of other engines do). Each hull is its box's unit cube (x across, y
// up from the keel at −1 to the deck at +1, z to the bow), with an outline on the deck plane
// that narrows with depth as the hull's section does; everything above the keel inside that
// outline is the hull's, up to any height (a wave's crest over the deck). A water fragment there
// is dropped only where the opaque scene behind it is that hull's, so a dropped fragment never
// opens onto the sky. docs/frame.md#hulls.
#ifndef COMMON_HULL_CLIP_GLSL
#define COMMON_HULL_CLIP_GLSL
#include "common_bindings.glsl"

// Kept inside the model's hull by this share of its beam, so no clip reaches past the hull's
// skin between the outline's samples.
const float HULL_CLIP_MARGIN = 0.005;

// The hulls' outlines (assets::HullOutline, hull_outline.h): a layer each, STATIONS rows of ROW
// texels: the station's keel height, then its half-beams from the keel up, all in the unit cube.
layout(binding = HULL_OUTLINE_UNIT) uniform sampler2DArray u_hullOutlines;

// The half-beam of station k of outline `layer` at the share t (in height steps) of its depth.
float outlineAt(int layer, int k, int j, float u) {
    float a = texelFetch(u_hullOutlines, ivec3(1 + j, k, layer), 0).r, b = texelFetch(u_hullOutlines, ivec3(2 + j, k, layer), 0).r;
    return mix(a, b, u);
}

// The model's half-beam over its box's at length w and height y (unit cube; assets::halfBeam):
// between the two stations around w (at w = −cos(π·i/(STATIONS − 1))), the keel linear; over
// it, both at the same share of their depth, y = keel + (1 − keel)·t⁴ (t in HEIGHTS − 1 steps).
float hullHalfBeam(int layer, float w, float y) {
    float s = acos(clamp(-w, -1.0, 1.0)) / 3.14159265 * float(HULL_OUTLINE_STATIONS - 1);
    int i = clamp(int(s), 0, HULL_OUTLINE_STATIONS - 2);
    float f = clamp(s - float(i), 0.0, 1.0);
    float keel = mix(texelFetch(u_hullOutlines, ivec3(0, i, layer), 0).r, texelFetch(u_hullOutlines, ivec3(0, i + 1, layer), 0).r, f);
    if (y <= keel || keel >= 1.0) return 0.0;
    float t = sqrt(sqrt(clamp((y - keel) / max(1.0 - keel, 1e-6), 0.0, 1.0))) * float(HULL_OUTLINE_HEIGHTS - 1);
    int j = min(int(t), HULL_OUTLINE_HEIGHTS - 2);
    return mix(outlineAt(layer, i, j, t - float(j)), outlineAt(layer, i + 1, j, t - float(j)), f);
}

// Whether world point p lies inside hull i (over its keel, within its outline).
bool insideHull(int i, vec3 p) {
    vec3 q = (water.hullFromWorld[i] * vec4(p, 1.0)).xyz;
    if (q.y <= -1.0 || abs(q.z) >= 1.0 || abs(q.x) >= 1.0) return false;
    if (water.hullPlan[i].x < 0.5) return true;  // the box
    return abs(q.x) < (1.0 - HULL_CLIP_MARGIN) * hullHalfBeam(int(water.hullPlan[i].x) - 1, q.z, min(q.y, 1.0));
}

// The opaque scene's window depth before the water pass (WaterPass::copySceneDepth), with the
// frame's samples: a discarded water fragment shows what that depth holds.
#if WATER_HULL_DEPTH_SAMPLES > 1
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2DMS u_sceneDepth;
#else
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D u_sceneDepth;
#endif

// How far past its box (a share of each half-extent) an opaque point still counts as the hull's:
// the depth's rounding and the deck's edge pixels.
const float HULL_SCENE_MARGIN = 0.05;

// Whether opaque world point s belongs to hull i: within its box's footprint, over its keel, at
// any height (its deck, cabin, mast).
bool hullOwns(int i, vec3 s) {
    vec3 q = (water.hullFromWorld[i] * vec4(s, 1.0)).xyz;
    return q.y > -1.0 - HULL_SCENE_MARGIN && max(abs(q.x), abs(q.z)) < 1.0 + HULL_SCENE_MARGIN;
}

// Whether the water fragment at world point p is clipped: it lies inside a hull and, behind it
// at every sample of the pixel, the depth buffer holds that hull (its deck, the inside of an
// open boat). Where the view ray leaves the hull under the sea (the eye over a deck, looking
// out under the far side) nothing lies behind the surface but the sky: the water stays.
// Overlapping hulls (a boat on a deck): any that holds both. One pass over the hulls: a software
// rasteriser runs every branch of this for every water pixel, so it is written to be short.
bool hullClipped(vec3 p) {
    // The opaque points behind the pixel, a world point a sample; nothing behind one: keep.
    vec3 behind[WATER_HULL_DEPTH_SAMPLES];
    vec2 ndc = gl_FragCoord.xy / frame.viewport.xy * 2.0 - 1.0;
    bool open = false;
    for (int s = 0; s < WATER_HULL_DEPTH_SAMPLES; ++s) {
        float z = texelFetch(u_sceneDepth, ivec2(gl_FragCoord.xy), s).r;  // single-sampled: s is the level, 0
        open = open || z >= 1.0;
        vec4 world = frame.inverseViewProjection * vec4(ndc, 2.0 * z - 1.0, 1.0);
        behind[s] = world.xyz / world.w;
    }
    if (open) return false;
    int count = min(int(water.hullCount.x), MAX_HULL_CLIPS);
    for (int i = 0; i < count; ++i) {
        bool owned = insideHull(i, p);
        for (int s = 0; s < WATER_HULL_DEPTH_SAMPLES; ++s) owned = owned && hullOwns(i, behind[s]);
        if (owned) return true;
    }
    return false;
}

#endif
