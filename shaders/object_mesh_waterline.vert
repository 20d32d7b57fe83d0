#version 450 core
// Objects cut at the surface evaluated at every vertex (object_mesh_common.glsl).
#define SURFACE_PER_VERTEX
#include "object_mesh_common.glsl"
