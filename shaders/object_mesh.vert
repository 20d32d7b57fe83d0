#version 450 core
// Objects: a mesh scaled, rotated and placed by its model matrix; the clip plane keeps the
// side of the water the pass draws (reflection: above, refraction: below).
#include "common_frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 0) uniform mat4 u_model;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = normalize(mat3(transpose(inverse(u_model))) * a_normal);
    v_color = a_color;
    gl_ClipDistance[0] = dot(u_clipPlane, vec4(world.xyz, 1.0));
    gl_Position = u_viewProjection * world;
}
