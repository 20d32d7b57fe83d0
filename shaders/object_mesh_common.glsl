// Objects: a mesh scaled, rotated and placed by its model matrix. The reflection and
// refraction passes keep the side of the water surface they draw, cut where the surface
// is (not at its mean level), and the reflection mirrors each vertex about the surface
// under it, so an object's image meets it at its waterline however the water moves.
// The including stage defines SURFACE_PER_VERTEX (large objects across the surface: the
// surface evaluated at every vertex) or not (the surface's tangent plane under the object:
// a software rasteriser runs both sides of a branch, so the two are separate programs).
#include "common_frame.glsl"
#include "common_water.glsl"
#include "common_surface_height.glsl"

layout(location = MESH_POSITION_ATTRIB) in vec3 a_position;
layout(location = MESH_NORMAL_ATTRIB) in vec3 a_normal;
layout(location = MESH_COLOR_ATTRIB) in vec3 a_color;
layout(location = OBJECT_MODEL_LOCATION) uniform mat4 u_model;
// The surface's tangent plane under the object's origin: height x (m), slope (y, z) = (dh/dx, dh/dz).
layout(location = OBJECT_SURFACE_PLANE_LOCATION) uniform vec3 u_surfacePlane;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = normalize(mat3(transpose(inverse(u_model))) * a_normal);
    v_color = a_color;
    vec3 p = world.xyz;
    gl_ClipDistance[0] = 1.0;
    if (frame.surfaceClip.x != 0.0) {
#ifdef SURFACE_PER_VERTEX
        float h = surfaceHeight(p.xz, frame.cameraPositionTime.w);
#else
        float h = u_surfacePlane.x + dot(u_surfacePlane.yz, p.xz - u_model[3].xz);
#endif
        gl_ClipDistance[0] = frame.surfaceClip.x * (p.y - h) + frame.surfaceClip.y;
        if (frame.surfaceClip.z > 0.5) p.y = 2.0 * h - p.y;
    }
    gl_Position = frame.viewProjection * vec4(p, 1.0);
}
