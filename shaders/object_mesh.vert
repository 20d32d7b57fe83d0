#version 450 core
// Objects cut at the surface's tangent plane under them (object_mesh_common.glsl).
#include "object_mesh_common.glsl"
