// Render targets.
#include "gfx/render_target.h"

#include "core/error.h"

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

RenderTarget createRenderTarget(const char* label, glm::ivec2 size) {
    RenderTarget t;
    t.size = size;
    t.color = createTexture2D((std::string(label) + " colour").c_str(), GL_RGBA16F, size);
    t.depth = createTexture2D((std::string(label) + " depth").c_str(), GL_DEPTH_COMPONENT32F, size);
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

} // namespace ob::gfx
