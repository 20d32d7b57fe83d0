// GL loading, version check and KHR_debug output.
#include "gfx/gl.h"

#include "core/error.h"
#include "core/log.h"

#include <cstdlib>
#include <cstring>
#include <string>

namespace ob::gfx {

namespace {
int s_forceDebug = -1;  // -1: decide from build type and environment
int s_errorCount = 0;

void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message, const void*) {
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++s_errorCount;
        logWarn("GL error: %s", message);
    } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
        logWarn("GL: %s", message);
    }
}
} // namespace

bool debugOutputRequested() {
    if (s_forceDebug >= 0) return s_forceDebug == 1;
    const char* env = std::getenv("OCEANBOX_GL_DEBUG");
    if (env && *env) return std::strcmp(env, "0") != 0;
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

void requestDebugOutput(bool on) { s_forceDebug = on ? 1 : 0; }
int glErrorCount() { return s_errorCount; }

const char* glRendererName() {
    const GLubyte* r = glGetString(GL_RENDERER);
    return r ? reinterpret_cast<const char*>(r) : "unknown";
}

bool isSoftwareRenderer() {
    std::string r = glRendererName();
    return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
}

void initGl(GLADloadfunc getProc) {
    int version = gladLoadGL(getProc);
    if (!version) throw RuntimeError("could not load OpenGL entry points (is a GL driver installed?)");
    int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major * 10 + minor < 43)
        throw RuntimeError("OpenGL 4.3 or newer is needed (compute shaders); this context is " +
                           std::to_string(major) + "." + std::to_string(minor) + " on " + glRendererName() +
                           ". Update the GPU driver, or run with --headless (Mesa llvmpipe)");
    if (debugOutputRequested() && GLAD_GL_KHR_debug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onDebugMessage, nullptr);
    }
}

} // namespace ob::gfx
