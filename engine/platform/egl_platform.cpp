// Headless platform on a GPU: an EGL OpenGL 4.5 core context with a pbuffer surface, on the
// first EGL device that gives one (EXT_platform_device: no display server needed), else on
// EGL's default display.
#include "gfx/gl.h"
#include "platform/platform.h"

#include "core/error.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <string>

namespace ob::platform {

namespace {

GLADapiproc eglProc(const char* name) { return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name)); }

// An initialised display: each EGL device in turn, then the default display.
EGLDisplay openDisplay() {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (queryDevices && platformDisplay) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
            }
    }
    EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    return EGL_NO_DISPLAY;
}

class EglPlatform final : public Platform {
public:
    explicit EglPlatform(glm::ivec2 size) : m_size(size) {
        m_display = openDisplay();
        if (m_display == EGL_NO_DISPLAY) throw RuntimeError("no EGL display could be initialised (is a GPU driver with EGL installed?)");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL has no desktop OpenGL API");
        const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                        EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
        EGLConfig config;
        EGLint configs = 0;
        if (!eglChooseConfig(m_display, configAttribs, &config, 1, &configs) || configs < 1) fail("no RGBA8 + depth pbuffer config");
        const EGLint surfaceAttribs[] = {EGL_WIDTH, size.x, EGL_HEIGHT, size.y, EGL_NONE};
        m_surface = eglCreatePbufferSurface(m_display, config, surfaceAttribs);
        if (m_surface == EGL_NO_SURFACE) fail("could not create a pbuffer surface");
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        m_context = eglCreateContext(m_display, config, EGL_NO_CONTEXT, contextAttribs);
        if (m_context == EGL_NO_CONTEXT) fail("could not create an OpenGL 4.5 core context");
        if (!eglMakeCurrent(m_display, m_surface, m_surface, m_context)) fail("could not make the context current");
        gfx::initGl(eglProc);
    }
    ~EglPlatform() override { release(); }

    const char* name() const override { return "egl"; }
    bool headless() const override { return true; }
    glm::ivec2 framebufferSize() const override { return m_size; }
    void pollEvents(std::vector<InputEvent>&) override {}
    // As a swap chain does: at most FRAMES_IN_FLIGHT frames queued on the GPU, so frame
    // times measure throughput (the CPU's next frame overlaps the GPU's last).
    void present() override {
        m_fences[m_frame % FRAMES_IN_FLIGHT] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        ++m_frame;
        GLsync& oldest = m_fences[m_frame % FRAMES_IN_FLIGHT];
        if (oldest) {
            glClientWaitSync(oldest, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000ull);
            glDeleteSync(oldest);
            oldest = nullptr;
        }
    }

private:
    [[noreturn]] void fail(const char* what) {
        std::string message = std::string("EGL: ") + what + " (EGL error 0x" + hex(eglGetError()) + ")";
        release();
        throw RuntimeError(message);
    }
    static std::string hex(EGLint v) {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%04x", unsigned(v));
        return buf;
    }
    void release() {
        if (m_display == EGL_NO_DISPLAY) return;
        for (GLsync& fence : m_fences) {
            if (fence) glDeleteSync(fence);
            fence = nullptr;
        }
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (m_context != EGL_NO_CONTEXT) eglDestroyContext(m_display, m_context);
        if (m_surface != EGL_NO_SURFACE) eglDestroySurface(m_display, m_surface);
        eglTerminate(m_display);
        m_display = EGL_NO_DISPLAY;
    }

    glm::ivec2 m_size;
    EGLDisplay m_display = EGL_NO_DISPLAY;
    EGLSurface m_surface = EGL_NO_SURFACE;
    EGLContext m_context = EGL_NO_CONTEXT;
    static constexpr int FRAMES_IN_FLIGHT = 2;
    GLsync m_fences[FRAMES_IN_FLIGHT] = {};
    unsigned m_frame = 0;
};

} // namespace

std::unique_ptr<Platform> createEglPlatform(glm::ivec2 size) { return std::make_unique<EglPlatform>(size); }

} // namespace ob::platform
