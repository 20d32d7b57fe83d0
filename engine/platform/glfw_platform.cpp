// Window platform: GLFW with a GL 4.5 core context.
#include "gfx/gl.h"
#include "platform/platform.h"

#include "core/error.h"

#include <GLFW/glfw3.h>
#include <cstdlib>

namespace ob::platform {

bool displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

namespace {

constexpr int KEY_CODES[size_t(Key::Count)] = {
    GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E, GLFW_KEY_SPACE,
    GLFW_KEY_LEFT_SHIFT, GLFW_KEY_ESCAPE, GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_LEFT, GLFW_KEY_RIGHT, GLFW_KEY_F1,
    GLFW_KEY_P, GLFW_KEY_N, GLFW_KEY_F, GLFW_KEY_F12};

class GlfwPlatform final : public Platform {
public:
    GlfwPlatform(const WindowDef& def, const std::string& title) {
        if (!glfwInit()) throw RuntimeError("could not initialise GLFW (no usable display?); run with --headless");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, gfx::debugOutputRequested() ? GLFW_TRUE : GLFW_FALSE);
        m_window = glfwCreateWindow(def.width, def.height, title.c_str(), nullptr, nullptr);
        if (!m_window) {
            glfwTerminate();
            throw RuntimeError("could not open a window with an OpenGL 4.5 core context; run with --headless");
        }
        glfwMakeContextCurrent(m_window);
        glfwSwapInterval(def.vsync ? 1 : 0);
        gfx::initGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress));
        glfwSetWindowUserPointer(m_window, this);
        glfwSetScrollCallback(m_window, [](GLFWwindow* w, double, double dy) {
            static_cast<GlfwPlatform*>(glfwGetWindowUserPointer(w))->m_scroll += float(dy);
        });
    }
    ~GlfwPlatform() override {
        glfwDestroyWindow(m_window);
        glfwTerminate();
    }

    const char* name() const override { return "glfw"; }
    bool headless() const override { return false; }
    void* nativeWindow() override { return m_window; }

    glm::ivec2 framebufferSize() const override {
        int w, h;
        glfwGetFramebufferSize(m_window, &w, &h);
        return {w, h};
    }

    void pollInput(InputState& in) override {
        glfwPollEvents();
        for (size_t k = 0; k < size_t(Key::Count); ++k) {
            bool now = glfwGetKey(m_window, KEY_CODES[k]) == GLFW_PRESS;
            in.pressed[k] = now && !in.down[k];
            in.down[k] = now;
        }
        double x, y;
        glfwGetCursorPos(m_window, &x, &y);
        glm::vec2 mouse{float(x), float(y)};
        in.mouseDelta = m_firstPoll ? glm::vec2(0.0f) : mouse - in.mouse;
        in.mouse = mouse;
        m_firstPoll = false;
        bool left = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        in.mouseLeftPressed = left && !in.mouseLeft;
        in.mouseLeft = left;
        in.mouseRight = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        in.scroll = m_scroll;
        m_scroll = 0.0f;
        in.quit = glfwWindowShouldClose(m_window) || in.wasPressed(Key::Escape);
    }

    void present() override { glfwSwapBuffers(m_window); }

private:
    GLFWwindow* m_window = nullptr;
    float m_scroll = 0.0f;
    bool m_firstPoll = true;
};

} // namespace

std::unique_ptr<Platform> createWindowPlatform(const WindowDef& def, const std::string& title) {
    return std::make_unique<GlfwPlatform>(def, title);
}

} // namespace ob::platform
