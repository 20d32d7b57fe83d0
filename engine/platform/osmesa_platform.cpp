// Headless platform: an OSMesa GL 4.5 core context (llvmpipe) rendering into memory.
#include "gfx/gl.h"  // glad before osmesa.h, which includes GL/gl.h
#include "platform/platform.h"

#include "core/error.h"

#include <GL/osmesa.h>
#include <vector>

namespace ob::platform {

namespace {

class OsmesaPlatform final : public Platform {
public:
    explicit OsmesaPlatform(glm::ivec2 size) : m_size(size) {
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                               OSMESA_DEPTH_BITS, 24,
                               OSMESA_STENCIL_BITS, 8,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        m_context = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!m_context)
            throw RuntimeError("could not create an OSMesa OpenGL 4.5 core context (install libosmesa6 from Mesa 22 or newer)");
        m_pixels.resize(size_t(size.x) * size_t(size.y));
        if (!OSMesaMakeCurrent(m_context, m_pixels.data(), GL_UNSIGNED_BYTE, size.x, size.y)) {
            OSMesaDestroyContext(m_context);
            throw RuntimeError("could not make the OSMesa context current");
        }
        gfx::initGl(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress));
    }
    ~OsmesaPlatform() override { OSMesaDestroyContext(m_context); }

    const char* name() const override { return "osmesa"; }
    bool headless() const override { return true; }
    glm::ivec2 framebufferSize() const override { return m_size; }
    void pollInput(InputState& in) override { in.pressed.fill(false); in.mouseDelta = {}; in.mouseLeftPressed = false; in.scroll = 0; }
    // Finish, so frame times include the rasteriser's work.
    void present() override { glFinish(); }

private:
    glm::ivec2 m_size;
    OSMesaContext m_context = nullptr;
    std::vector<uint32_t> m_pixels;  // RGBA8, bottom row first
};

} // namespace

std::unique_ptr<Platform> createHeadlessPlatform(glm::ivec2 size) { return std::make_unique<OsmesaPlatform>(size); }

} // namespace ob::platform
