// Render targets.
#include "gfx/render_target.h"

#include "core/error.h"

#include <cassert>
#include <string>

namespace ob::gfx {

Texture createTexture2D(const char* label, GLenum format, glm::ivec2 size, int levels) {
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, label);
    glTextureStorage2D(id, levels, format, size.x, size.y);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return Texture(id);
}

// A multisampled texture has no sampler state: it is only drawn into and resolved.
static Texture createMultisampleTexture(const char* label, GLenum format, glm::ivec2 size, int samples) {
    GLuint id;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
    glObjectLabel(GL_TEXTURE, id, -1, label);
    glTextureStorage2DMultisample(id, samples, format, size.x, size.y, GL_TRUE);
    return Texture(id);
}

RenderTarget createRenderTarget(const char* label, glm::ivec2 size, int samples, GLenum colorFormat) {
    RenderTarget t;
    t.size = size;
    t.samples = samples;
    const std::string colorLabel = std::string(label) + " colour", depthLabel = std::string(label) + " depth";
    if (samples > 1) {
        t.color = createMultisampleTexture(colorLabel.c_str(), colorFormat, size, samples);
        t.depth = createMultisampleTexture(depthLabel.c_str(), GL_DEPTH_COMPONENT32F, size, samples);
    } else {
        t.color = createTexture2D(colorLabel.c_str(), colorFormat, size);
        t.depth = createTexture2D(depthLabel.c_str(), GL_DEPTH_COMPONENT32F, size);
    }
    GLuint fbo;
    glCreateFramebuffers(1, &fbo);
    glObjectLabel(GL_FRAMEBUFFER, fbo, -1, label);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, t.color.id(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, t.depth.id(), 0);
    t.framebuffer = Framebuffer(fbo);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError(std::string("render target '") + label + "' is incomplete on this GL driver");
    return t;
}

void resolveTarget(const RenderTarget& from, const RenderTarget& to, bool depth) {
    assert(from.size == to.size);
    // Depth cannot be averaged: a blit of it is NEAREST, one sample per pixel.
    glBlitNamedFramebuffer(from.framebuffer.id(), to.framebuffer.id(), 0, 0, from.size.x, from.size.y, 0, 0, to.size.x,
                           to.size.y, GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0), GL_NEAREST);
}

} // namespace ob::gfx
