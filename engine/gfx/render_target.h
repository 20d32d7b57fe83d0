// Off-screen render targets: a framebuffer with a colour and a depth texture, both sampled
// later (reflection, refraction), and the labelled 2D textures they are made of.
#pragma once
#include "gfx/handles.h"

#include <glm/vec2.hpp>

namespace ob::gfx {

/// Creates a labelled, immutable 2D texture (one level unless `levels` > 1), linear filtered
/// and clamped to the edge.
Texture createTexture2D(const char* label, GLenum format, glm::ivec2 size, int levels = 1);

/// A framebuffer object with a colour texture (linear radiance in rgb, coverage in alpha, or
/// the display-encoded frame) and a depth texture (DEPTH_COMPONENT32F), both `size`; with
/// `samples` > 1 both are multisampled (drawn into, then resolved by a blit, never sampled).
struct RenderTarget {
    Framebuffer framebuffer;
    Texture color, depth;
    glm::ivec2 size{0};
    int samples = 1;
};

/// Creates a complete render target named `label` ("<label> colour", "<label> depth") with
/// `samples` samples per pixel (1: plain textures) and a colour of `colorFormat`.
RenderTarget createRenderTarget(const char* label, glm::ivec2 size, int samples = 1, GLenum colorFormat = GL_RGBA16F);

/// Copies `from`'s colour (and depth, with `depth`) into `to`, same size: resolves the
/// samples of a multisampled target (colour averaged; depth one sample's).
void resolveTarget(const RenderTarget& from, const RenderTarget& to, bool depth);

} // namespace ob::gfx
