#version 450 core
// Splash drops mirrored in the water surface, for the reflection target (splash_drops_common.glsl).
#define MIRROR
#include "splash_drops_common.glsl"
