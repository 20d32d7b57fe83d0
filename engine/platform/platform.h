// Platform: a GL 4.5 core context and its events, behind one interface with three
// implementations: a GLFW window, and headless an OSMesa (llvmpipe) or EGL (GPU) context.
#pragma once
#include "platform/window_def.h"
#include "platform/input.h"

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

namespace ob::platform {

/// A GL 4.5 core context with a default framebuffer of framebufferSize().
class Platform {
public:
    virtual ~Platform() = default;
    /// "glfw", "osmesa" or "egl".
    virtual const char* name() const = 0;
    virtual bool headless() const = 0;
    virtual glm::ivec2 framebufferSize() const = 0;
    /// Appends the events that arrived since the last call, in order (headless: none).
    virtual void pollEvents(std::vector<InputEvent>& out) = 0;
    /// Shows the finished frame (window) or completes it (headless).
    virtual void present() = 0;
    /// The GLFWwindow* for the UI backend (null when headless).
    virtual void* nativeWindow() { return nullptr; }
    /// The display's content scale (DPI / 96; 1 headless).
    virtual float contentScale() const { return 1.0f; }
    /// Names the window (headless: nothing).
    virtual void setTitle(const std::string& /*title*/) {}
};

/// True when a window can be opened (an X11 or Wayland display is named).
bool displayAvailable();

/// Opens a window with a GL 4.5 core context. Throws ob::RuntimeError when it cannot.
std::unique_ptr<Platform> createWindowPlatform(const WindowDef& def, const std::string& title);

/// Creates a headless GL 4.5 core context of `size`: OSMesa (llvmpipe, the default, what CI
/// runs) or, with OCEANBOX_HEADLESS_GL=egl, EGL on the GPU (a GPU server has no display).
/// Throws ob::RuntimeError when the context cannot be made, ob::InputError for another value.
std::unique_ptr<Platform> createHeadlessPlatform(glm::ivec2 size);
/// The two headless implementations.
std::unique_ptr<Platform> createOsmesaPlatform(glm::ivec2 size);
std::unique_ptr<Platform> createEglPlatform(glm::ivec2 size);

} // namespace ob::platform
