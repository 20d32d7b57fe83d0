// Window platform: GLFW with a GL 4.5 core context.
#include "gfx/gl.h"
#include "platform/platform.h"

#include "core/error.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <vector>

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
    GLFW_KEY_P, GLFW_KEY_N, GLFW_KEY_F, GLFW_KEY_F12, GLFW_KEY_H, GLFW_KEY_C, GLFW_KEY_R,
    GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4, GLFW_KEY_5, GLFW_KEY_6, GLFW_KEY_7, GLFW_KEY_8, GLFW_KEY_9, GLFW_KEY_T};

class GlfwPlatform final : public Platform {
public:
    GlfwPlatform(const WindowDef& def, const std::string& title) {
        if (!glfwInit()) throw RuntimeError("could not initialise GLFW (no usable display?); run with --headless");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, gfx::debugOutputRequested() ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);  // the renderer's FXAA marks finished pixels in it
        m_window = glfwCreateWindow(def.width, def.height, title.c_str(), nullptr, nullptr);
        if (!m_window) {
            glfwTerminate();
            throw RuntimeError("could not open a window with an OpenGL 4.5 core context; run with --headless");
        }
        glfwMakeContextCurrent(m_window);
        glfwSwapInterval(def.vsync ? 1 : 0);
        gfx::initGl(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress));
        // Every event is queued as it is delivered, so order and short taps survive a slow frame.
        glfwSetWindowUserPointer(m_window, this);
        glfwSetKeyCallback(m_window, [](GLFWwindow* w, int key, int, int action, int) {
            if (action == GLFW_REPEAT) return;
            const int* code = std::find(std::begin(KEY_CODES), std::end(KEY_CODES), key);
            if (key == GLFW_KEY_RIGHT_SHIFT) code = std::find(std::begin(KEY_CODES), std::end(KEY_CODES), GLFW_KEY_LEFT_SHIFT);
            if (code == std::end(KEY_CODES)) return;
            InputEvent e;
            e.type = action == GLFW_PRESS ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp;
            e.key = Key(code - std::begin(KEY_CODES));
            self(w)->m_events.push_back(e);
        });
        glfwSetMouseButtonCallback(m_window, [](GLFWwindow* w, int button, int action, int) {
            if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
            InputEvent e;
            e.type = action == GLFW_PRESS ? InputEvent::Type::ButtonDown : InputEvent::Type::ButtonUp;
            e.button = button == GLFW_MOUSE_BUTTON_LEFT ? MouseButton::Left : MouseButton::Right;
            e.hasPos = self(w)->m_cursorKnown;
            e.pos = self(w)->m_cursor;
            self(w)->m_events.push_back(e);
        });
        glfwSetCursorPosCallback(m_window, [](GLFWwindow* w, double x, double y) {
            GlfwPlatform* p = self(w);
            // Window coordinates to framebuffer pixels (they differ on a high-density display).
            int ww, wh, fw, fh;
            glfwGetWindowSize(w, &ww, &wh);
            glfwGetFramebufferSize(w, &fw, &fh);
            const glm::vec2 scale = ww > 0 && wh > 0 ? glm::vec2(float(fw) / float(ww), float(fh) / float(wh)) : glm::vec2(1.0f);
            const glm::vec2 cursor = glm::vec2(float(x), float(y)) * scale;
            const glm::vec2 motion = p->m_cursorKnown ? cursor - p->m_cursor : glm::vec2(0.0f);
            p->m_events.push_back({InputEvent::Type::Move, 0.0, Key::W, MouseButton::Left, motion, true, cursor});
            p->m_cursor = cursor;
            p->m_cursorKnown = true;
        });
        glfwSetScrollCallback(m_window, [](GLFWwindow* w, double, double dy) {
            self(w)->m_events.push_back({InputEvent::Type::Scroll, 0.0, Key::W, MouseButton::Left, glm::vec2(0.0f, float(dy))});
        });
        glfwSetWindowCloseCallback(m_window, [](GLFWwindow* w) { self(w)->m_events.push_back({InputEvent::Type::Close}); });
    }
    ~GlfwPlatform() override {
        glfwDestroyWindow(m_window);
        glfwTerminate();
    }

    const char* name() const override { return "glfw"; }
    bool headless() const override { return false; }
    void* nativeWindow() override { return m_window; }
    float contentScale() const override {
        float x = 1.0f, y = 1.0f;
        glfwGetWindowContentScale(m_window, &x, &y);
        return std::max(x, y);
    }
    void setTitle(const std::string& title) override { glfwSetWindowTitle(m_window, title.c_str()); }

    glm::ivec2 framebufferSize() const override {
        int w, h;
        glfwGetFramebufferSize(m_window, &w, &h);
        return {w, h};
    }

    void pollEvents(std::vector<InputEvent>& out) override {
        glfwPollEvents();
        out.insert(out.end(), m_events.begin(), m_events.end());
        m_events.clear();
    }

    void present() override { glfwSwapBuffers(m_window); }

private:
    static GlfwPlatform* self(GLFWwindow* w) { return static_cast<GlfwPlatform*>(glfwGetWindowUserPointer(w)); }

    GLFWwindow* m_window = nullptr;
    std::vector<InputEvent> m_events;  // delivered since the last poll, in order
    glm::vec2 m_cursor{0.0f};  // framebuffer px
    bool m_cursorKnown = false;
};

} // namespace

std::unique_ptr<Platform> createWindowPlatform(const WindowDef& def, const std::string& title) {
    return std::make_unique<GlfwPlatform>(def, title);
}

} // namespace ob::platform
