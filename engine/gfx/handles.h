// Typed, owning GL object handles: raw GL ids never leave engine/gfx.
#pragma once
#include "gfx/gl.h"

#include <utility>

namespace ob::gfx {

enum class GlKind { Buffer, Texture, Sampler, Framebuffer, VertexArray, Program, Query, Shader };

/// Move-only owner of one GL object of kind K; deletes it on destruction.
template <GlKind K>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : m_id(id) {}
    Handle(Handle&& o) noexcept : m_id(std::exchange(o.m_id, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            m_id = std::exchange(o.m_id, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset() {
        if (!m_id) return;
        if constexpr (K == GlKind::Buffer) glDeleteBuffers(1, &m_id);
        else if constexpr (K == GlKind::Texture) glDeleteTextures(1, &m_id);
        else if constexpr (K == GlKind::Sampler) glDeleteSamplers(1, &m_id);
        else if constexpr (K == GlKind::Framebuffer) glDeleteFramebuffers(1, &m_id);
        else if constexpr (K == GlKind::VertexArray) glDeleteVertexArrays(1, &m_id);
        else if constexpr (K == GlKind::Program) glDeleteProgram(m_id);
        else if constexpr (K == GlKind::Query) glDeleteQueries(1, &m_id);
        else if constexpr (K == GlKind::Shader) glDeleteShader(m_id);
        m_id = 0;
    }

private:
    GLuint m_id = 0;
};

using Buffer = Handle<GlKind::Buffer>;
using Texture = Handle<GlKind::Texture>;
using Sampler = Handle<GlKind::Sampler>;
using Framebuffer = Handle<GlKind::Framebuffer>;
using VertexArray = Handle<GlKind::VertexArray>;
using Program = Handle<GlKind::Program>;
using Query = Handle<GlKind::Query>;

/// Creates a labelled buffer of `size` bytes (GL_DYNAMIC_STORAGE_BIT).
Buffer createBuffer(const char* label, GLsizeiptr size, const void* data = nullptr);
/// Creates a labelled empty vertex array.
VertexArray createVertexArray(const char* label);

} // namespace ob::gfx
