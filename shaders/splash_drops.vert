#version 450 core
// Splash drops seen by the camera (splash_drops_common.glsl).
#include "splash_drops_common.glsl"
