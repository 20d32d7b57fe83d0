#version 450 core
// Sky bake: one cube face of the analytic sky with its clouds (linear radiance), drawn when the
// sun moves or, under clouds, when they drift.
#include "common_frame.glsl"
#include "common_sky.glsl"

in vec2 v_ndc;
layout(location = SKY_FACE_LOCATION) uniform mat3 u_face;  // columns: world axes of face s, face t, face normal
out vec4 o_color;

void main() {
    vec3 dir = normalize(u_face * vec3(v_ndc, 1.0));
    o_color = vec4(skyWithClouds(dir, frame.sunDirectionFresnel.xyz), 1.0);
}
