// Hull clip volumes: the water surface is not drawn inside a floating hull, so no sea shows in a
// hull where the waves rise above its deck or in an open boat (as Crest's clip surface and the
// boat "water-tight" masks of other engines do). Each hull is its box's unit cube (x across, y
// up from the keel at −1 to the deck at +1, z to the bow), with an outline on the deck plane
// that narrows with depth as the hull's section does; everything above the keel inside that
// outline is the hull's, up to any height (a wave's crest over the deck). docs/frame.md#hulls.
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

// Whether world point p lies inside a hull (over its keel, within its outline).
bool insideHull(vec3 p) {
    int count = int(water.hullCount.x);
    for (int i = 0; i < MAX_HULL_CLIPS; ++i) {
        if (i >= count) break;
        vec3 q = (water.hullFromWorld[i] * vec4(p, 1.0)).xyz;
        if (q.y <= -1.0 || abs(q.z) >= 1.0 || abs(q.x) >= 1.0) continue;
        if (water.hullPlan[i].x < 0.5) return true;  // the box
        if (abs(q.x) < (1.0 - HULL_CLIP_MARGIN) * shipHalfBeam(q.z, min(q.y, 1.0))) return true;
    }
    return false;
}

#endif
