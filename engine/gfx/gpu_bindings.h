// The GL binding points, uniform locations and std140 uniform blocks that the shaders share
// with C++: shaders/common_bindings.glsl, read here as C++ (each number is written there once).
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace ob::gfx {

// The GLSL types the shared blocks use, as the C++ types std140 lays out alike.
namespace glsl {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
#include "common_bindings.glsl"
} // namespace glsl

using glsl::FrameUniforms;
using glsl::WaterUniforms;
using glsl::MAX_GERSTNER_WAVES;
using glsl::MAX_HULL_CLIPS;
using glsl::MAX_RIPPLE_LEVELS;

// std140 puts every vec4 and mat4 member at a multiple of 16 bytes, arrays at a 16-byte stride:
// the C++ structs' sizes must be the members' sizes summed, with no padding.
static_assert(sizeof(FrameUniforms) == 2 * 64 + 12 * 16, "FrameUniforms must match its std140 layout");
static_assert(sizeof(WaterUniforms) == 16 * (4 + 11 + MAX_RIPPLE_LEVELS + 1 + MAX_GERSTNER_WAVES + 1)
                                        + (64 + 16) * MAX_HULL_CLIPS,
              "WaterUniforms must match its std140 layout");

} // namespace ob::gfx
