#version 450 core
#include "common_bindings.glsl"
// The finished frame drawn smaller (render.resolution_scale < 1) scaled up to the output:
// one bilinear lookup at each output pixel's centre, as a linear blit samples.
in vec2 v_ndc;
layout(binding = POST_SOURCE_UNIT) uniform sampler2D u_source;  // the internal frame, linear filtered
out vec4 o_color;

void main() { o_color = textureLod(u_source, v_ndc * 0.5 + 0.5, 0.0); }
