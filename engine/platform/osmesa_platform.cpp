// Headless platform: an OSMesa GL 4.5 core context (llvmpipe) rendering into memory.
// libOSMesa is opened at run time, so the program also starts where only a GPU's EGL is
// installed (OSMesa pulls in LLVM, a large dependency a GPU server need not have).
#include "gfx/gl.h"  // glad before osmesa.h, which includes GL/gl.h
#include "platform/platform.h"

#include "core/error.h"

#include <GL/osmesa.h>
#include <cstdlib>
#include <dlfcn.h>
#include <string>
#include <vector>

namespace ob::platform {

namespace {

// The four entry points the platform uses, from libOSMesa.
struct OsmesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

const OsmesaApi& osmesa() {
    static const OsmesaApi api = [] {
        OsmesaApi a;
        void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        if (!lib) return a;
        a.createContextAttribs = reinterpret_cast<decltype(a.createContextAttribs)>(dlsym(lib, "OSMesaCreateContextAttribs"));
        a.makeCurrent = reinterpret_cast<decltype(a.makeCurrent)>(dlsym(lib, "OSMesaMakeCurrent"));
        a.destroyContext = reinterpret_cast<decltype(a.destroyContext)>(dlsym(lib, "OSMesaDestroyContext"));
        a.getProcAddress = reinterpret_cast<decltype(a.getProcAddress)>(dlsym(lib, "OSMesaGetProcAddress"));
        return a;
    }();
    return api;
}

// GLAD's loader signature over OSMesaGetProcAddress.
GLADapiproc osmesaProc(const char* name) { return reinterpret_cast<GLADapiproc>(osmesa().getProcAddress(name)); }

class OsmesaPlatform final : public Platform {
public:
    explicit OsmesaPlatform(glm::ivec2 size) : m_size(size) {
        const OsmesaApi& api = osmesa();
        if (!api.createContextAttribs || !api.makeCurrent || !api.destroyContext || !api.getProcAddress)
            throw RuntimeError("could not load libOSMesa.so.8 for headless rendering (install the libosmesa6 package)");
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                               OSMESA_DEPTH_BITS, 24,
                               OSMESA_STENCIL_BITS, 8,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 5,
                               0};
        m_context = api.createContextAttribs(attribs, nullptr);
        if (!m_context) {
            // Mesa caps its versions at MESA_GL_VERSION_OVERRIDE: name it when it is the cause.
            const char* cap = std::getenv("MESA_GL_VERSION_OVERRIDE");
            if (cap && *cap)
                throw RuntimeError(std::string("could not create an OSMesa OpenGL 4.5 core context: MESA_GL_VERSION_OVERRIDE=") +
                                   cap + " caps Mesa below it (unset it; oceanbox needs OpenGL 4.5)");
            throw RuntimeError("could not create an OSMesa OpenGL 4.5 core context (install libosmesa6 from Mesa 22 or newer)");
        }
        m_pixels.resize(size_t(size.x) * size_t(size.y));
        if (!api.makeCurrent(m_context, m_pixels.data(), GL_UNSIGNED_BYTE, size.x, size.y)) {
            api.destroyContext(m_context);
            throw RuntimeError("could not make the OSMesa context current");
        }
        gfx::initGl(osmesaProc);
    }
    ~OsmesaPlatform() override { osmesa().destroyContext(m_context); }

    const char* name() const override { return "osmesa"; }
    bool headless() const override { return true; }
    glm::ivec2 framebufferSize() const override { return m_size; }
    void pollEvents(std::vector<InputEvent>&) override {}
    // Finish, so frame times include the rasteriser's work.
    void present() override { glFinish(); }

private:
    glm::ivec2 m_size;
    OSMesaContext m_context = nullptr;
    std::vector<uint32_t> m_pixels;  // RGBA8, bottom row first
};

} // namespace

std::unique_ptr<Platform> createOsmesaPlatform(glm::ivec2 size) { return std::make_unique<OsmesaPlatform>(size); }

} // namespace ob::platform
