#version 450 core
// Opaque objects: a built-in mesh scaled, rotated and placed by its model matrix.
#include "common_frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 0) uniform mat4 u_model;
out vec3 v_world;
out vec3 v_normal;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = normalize(mat3(transpose(inverse(u_model))) * a_normal);
    gl_Position = u_viewProjection * world;
}
