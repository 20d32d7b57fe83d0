#version 450 core
// The overlay's colour times its font atlas (straight alpha, blended over the frame).
layout(binding = 0) uniform sampler2D u_atlas;
in vec2 v_uv;
in vec4 v_color;
out vec4 o_color;

void main() {
    o_color = v_color * texture(u_atlas, v_uv);
}
