// Off-screen render targets: a framebuffer with a colour and a depth texture, both sampled
// later (reflection, refraction), and the labelled 2D textures they are made of.
#pragma once
#include "gfx/handles.h"

#include <glm/vec2.hpp>

namespace ob::gfx {

/// Creates a labelled, immutable 2D texture (one level unless `levels` > 1), linear filtered
/// and clamped to the edge.
Texture createTexture2D(const char* label, GLenum format, glm::ivec2 size, int levels = 1);

/// A framebuffer object with a colour texture (RGBA16F: linear radiance in rgb, coverage in
/// alpha) and a depth texture (DEPTH_COMPONENT32F), both `size`.
struct RenderTarget {
    Framebuffer framebuffer;
    Texture color, depth;
    glm::ivec2 size{0};
};

/// Creates a complete render target named `label` ("<label> colour", "<label> depth").
RenderTarget createRenderTarget(const char* label, glm::ivec2 size);

} // namespace ob::gfx
