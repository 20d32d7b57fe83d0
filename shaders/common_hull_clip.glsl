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

// Kept inside the ship model's hull by this share of its beam, so no clip reaches past the
// hull's skin (its facets lie inside the curves below by less than 0.1 %).
const float HULL_CLIP_MARGIN = 0.02;

// The ship model's half-beam over its box's (game/tools/model_shapes.cpp, hullStations and
// hullPoint, in the unit cube) at length w and height y: the deck outline (round stern over
// w < −0.6, straight waist, parabolic bow from w = 0.2) times the section's width at y (the
// bilge s(2 − s) from the deck edge to the keel, whose height rises at both ends).
float shipHalfBeam(float w, float y) {
    float stern = (w + 0.6) / 0.4, bow = (w - 0.2) / 0.8;
    float deck = w < -0.6 ? sqrt(max(1.0 - stern * stern, 0.0)) : (w > 0.2 ? 1.0 - bow * bow : 1.0);
    float keel = -1.0 + (w < -0.6 ? stern * stern / 3.0 : (w > 0.2 ? 2.0 / 3.0 * bow * bow * bow : 0.0));
    float g = clamp((1.0 - y) / (1.0 - keel), 0.0, 1.0);  // depth below the deck edge over the section's
    float s = 1.0 - sqrt(1.0 - g);                        // sin φ of hullPoint's angle there
    return y <= keel ? 0.0 : deck * sqrt(max(1.0 - s * s, 0.0));
}

// Whether world point p lies inside hull i (over its keel, within its outline).
bool insideHull(int i, vec3 p) {
    vec3 q = (water.hullFromWorld[i] * vec4(p, 1.0)).xyz;
    if (q.y <= -1.0 || abs(q.z) >= 1.0 || abs(q.x) >= 1.0) return false;
    if (water.hullPlan[i].x < 0.5) return true;  // the box
    return abs(q.x) < (1.0 - HULL_CLIP_MARGIN) * shipHalfBeam(q.z, min(q.y, 1.0));
}

// The first hull (nearest the eye first) that holds world point p, −1 none.
int hullHolding(vec3 p) {
    int count = int(water.hullCount.x);
    for (int i = 0; i < MAX_HULL_CLIPS; ++i) {
        if (i >= count) break;
        if (insideHull(i, p)) return i;
    }
    return -1;
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
bool hullClipped(vec3 p) {
    int first = hullHolding(p);
    if (first < 0) return false;
    // The opaque points behind the pixel, a world point a sample; nothing behind one: keep.
    vec3 behind[WATER_HULL_DEPTH_SAMPLES];
    vec2 ndc = gl_FragCoord.xy / frame.viewport.xy * 2.0 - 1.0;
    for (int s = 0; s < WATER_HULL_DEPTH_SAMPLES; ++s) {
        float z = texelFetch(u_sceneDepth, ivec2(gl_FragCoord.xy), s).r;  // single-sampled: s is the level, 0
        if (z >= 1.0) return false;
        vec4 world = frame.inverseViewProjection * vec4(ndc, 2.0 * z - 1.0, 1.0);
        behind[s] = world.xyz / world.w;
    }
    int count = int(water.hullCount.x);
    for (int i = first; i < MAX_HULL_CLIPS; ++i) {  // overlapping hulls (a boat on a deck): any that holds both
        if (i >= count) break;
        if (i > first && !insideHull(i, p)) continue;
        bool owned = true;
        for (int s = 0; s < WATER_HULL_DEPTH_SAMPLES; ++s) owned = owned && hullOwns(i, behind[s]);
        if (owned) return true;
    }
    return false;
}

#endif
