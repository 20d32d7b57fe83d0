#version 450 core
// Bakes the persistent foam's bubble pattern (common_detail.glsl, foamPattern) over its repeat
// of FOAM_PATTERN_REPEAT foam tiles into an RGBA8 map, once: (du, dv) as 0.5 + 0.5·x, the
// pattern, and the bubbles (the pattern FOAM_BUBBLE_SCALE times finer). The water shader then
// reads one lookup instead of six and two pows.
#define FOAM_PATTERN_BAKE
#include "common_detail.glsl"

in vec2 v_ndc;
out vec4 o_color;

void main() {
    vec2 fuv = (v_ndc * 0.5 + 0.5) * FOAM_PATTERN_REPEAT;
    vec3 p = foamPattern(fuv);
    o_color = vec4(p.xy * 0.5 + 0.5, p.z, foamPattern(fuv * FOAM_BUBBLE_SCALE + FOAM_BUBBLE_OFFSET).z);
}
