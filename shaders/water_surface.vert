#version 450 core
// Water surface vertices: projected grid point → Gerstner displacement + every FFT cascade's
// choppy displacement ([Lee2007] vertex shader) + the ripple height at the displaced point;
// past the grid's reach, a wall to the horizon. Each cascade fades out with distance.
#include "common_frame.glsl"
#include "common_water.glsl"

layout(location = GRID_UV_ATTRIB) in vec2 a_uv;
out vec3 v_world;   // displaced surface point (m)
out vec2 v_rest;    // rest point on the mean plane (m)
out vec2 v_gerstnerSlope;  // Gerstner slope per vertex: long waves are smooth across a cell
out vec3 v_haze;           // the sky at the horizon behind the point (linear radiance): it changes only with the azimuth
out vec4 v_cascadeWeight;  // each cascade's weight (cascadeWeight): it changes only with the distance
layout(binding = SKY_UNIT) uniform samplerCube u_sky;

void main() {
    vec2 rest = gridPoint(a_uv);
    vec2 eye = frame.cameraPositionTime.xz;
    vec2 rel = rest - eye;
    float dist = length(rel);
    // Past the grid's reach (a fraction of the far clip distance) the grid is a wall up to the
    // eye's level: a point level with the eye projects onto the horizon line, so the water
    // always reaches the horizon, whatever lies between the reach and it.
    bool horizonWall = dist > water.gridParams.y;
    if (horizonWall) rest = eye + rel * (water.gridParams.y / dist);
    // Mip level: the spacing of neighbouring grid vertices against the FFT texel size.
    vec2 next = gridPoint(a_uv + vec2(0.0, 1.0) / water.gridParams.x);
    float spacing = length(next - rest);

    float t = frame.cameraPositionTime.w;
    vec3 offset;
    gerstner(rest, t, water.farFade.x > 0.5 ? spacing : 0.0, offset, v_gerstnerSlope);
    vec3 pos = vec3(rest.x, 0.0, rest.y) + offset;
    v_cascadeWeight = vec4(0.0);
    for (int c = 0; c < WATER_CASCADES; ++c) {
        float lod = log2(max(spacing * water.gridParams.w / water.cascadeSize[c], 1.0));
        v_cascadeWeight[c] = cascadeWeight(rest, c);
        vec4 d = v_cascadeWeight[c] * textureLod(u_displacement, cascadeCoord(rest, c), lod);
        pos += vec3(water.waterParams.x * d.x, d.y, water.waterParams.x * d.z);
    }
    pos.y += rippleHeight(pos.xz);
    if (horizonWall) pos = vec3(rest.x, frame.cameraPositionTime.y, rest.y);
    vec2 away = pos.xz - eye;
    v_haze = textureLod(u_sky, dot(away, away) > 1e-8 ? vec3(away.x, 0.0, away.y) : vec3(1.0, 0.0, 0.0), 0.0).rgb;
    v_world = pos;
    v_rest = rest;
    gl_Position = frame.viewProjection * vec4(pos, 1.0);
}
