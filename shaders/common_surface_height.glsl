// Height of the composite surface (Gerstner + FFT cascades + ripples) above a world point,
// as the water vertex shader displaces it; needs common_water.glsl. Used where objects meet
// the water: the reflection and refraction passes clip them at the surface, not the mean level.

// Displacement (x, y, z) of rest point `rest` at time t: Gerstner and every FFT cascade (finest
// level), each faded with distance as the water pass draws it.
vec3 surfaceDisplacement(vec2 rest, float t) {
    vec3 offset;
    vec2 slope;
    gerstner(rest, t, 0.0, offset, slope);
    int cascades = int(water.gridParams.z);
    for (int c = 0; c < cascades; ++c) {
        vec4 d = cascadeWeight(rest, c) * textureLod(u_displacement, cascadeCoord(rest, c), 0.0);
        offset += vec3(water.waterParams.x * d.x, d.y, water.waterParams.x * d.z);
    }
    return offset;
}

// Surface height (m) above world (x, z) at time t: the height at the rest point that the
// horizontal displacement carries to (x, z), found by one fixed-point step (rest = world −
// D(world); the residual is D's change over |D|, a few cm for waves that do not fold: it
// is per vertex, on a software rasteriser's one vertex thread), and the ripples at (x, z).
float surfaceHeight(vec2 world, float t) {
    vec2 rest = world - surfaceDisplacement(world, t).xz;
    return surfaceDisplacement(rest, t).y + rippleHeight(world);
}
