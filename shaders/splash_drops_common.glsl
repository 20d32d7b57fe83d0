// Splash drops as point sprites, one vertex a drop (a_drop: world centre, radius): one vertex
// shader run a drop (a software rasteriser runs vertex shaders on one thread). A point is
// clipped by its centre, and the driver caps its size (GL_POINT_SIZE_RANGE, 255 px on llvmpipe).
// Each simulated drop stands for a cluster of spray: its sprite radius is the drop's times
// u_sprite.x. A sprite smaller than u_sprite.z px in radius is drawn at that radius with its
// opacity cut by the area ratio, so far drops fade instead of flickering between pixels.
// The including stage defines MIRROR for the reflection view: a drop above the composite
// surface is mirrored about the surface under it, one below it is dropped.
#include "common_frame.glsl"
#ifdef MIRROR
#include "common_water.glsl"
#include "common_surface_height.glsl"
#endif

layout(location = SPLASH_DROP_ATTRIB) in vec4 a_drop;
layout(location = SPLASH_SPRITE_LOCATION) uniform vec3 u_sprite;  // x sprite radius / drop radius, y projection[1][1], z smallest sprite radius (px)
out vec3 v_centre;    // the (mirrored) drop centre, world m
out float v_opacity;  // the area ratio of a sprite enlarged to the smallest size, else 1

void main() {
    vec3 c = a_drop.xyz;
    float r = a_drop.w * u_sprite.x;
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    gl_PointSize = 1.0;
    v_centre = c;
    v_opacity = 0.0;
#ifdef MIRROR
    float h = surfaceHeight(c.xz, frame.cameraPositionTime.w);
    if (c.y < h) return;
    c.y = 2.0 * h - c.y;
#endif
    vec4 clip = frame.viewProjection * vec4(c, 1.0);
    if (clip.w <= frame.depthParams.x) return;  // at or behind the eye
    float radiusPx = r * u_sprite.y * 0.5 * frame.viewport.y / clip.w;
    float grow = max(u_sprite.z / max(radiusPx, 1e-6), 1.0);
    v_opacity = 1.0 / (grow * grow);
    v_centre = c;
    gl_PointSize = 2.0 * radiusPx * grow;
    gl_Position = clip;
}
