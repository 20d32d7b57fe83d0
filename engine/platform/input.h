// Input as games do it: the platform's events are queued in order with the clock time they
// arrived at; each consumer (the frame, the fixed simulation step) drains the events due by
// its time into its own InputState, so an edge (a press, a click) is seen exactly once by
// each consumer, held keys are integrated per step, and a press shorter than a frame counts.
#pragma once
#include <array>
#include <cstdint>
#include <deque>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace ob::platform {

/// Keys the game reads.
enum class Key : uint8_t {
    W, A, S, D, Q, E, Space, Shift, Escape, Up, Down, Left, Right, F1, P, N, F, F12, H, C, R,
    Num1, Num2, Num3, Num4, Num5, Num6, Num7, Num8, Num9, T, Count
};
constexpr size_t KEY_COUNT = size_t(Key::Count);
/// Lower-case key names as scripts write them (enumName(Key::Space) is "space").
constexpr std::array<const char*, KEY_COUNT> names(Key) {
    return {"w", "a", "s", "d", "q", "e", "space", "shift", "escape", "up", "down", "left", "right", "f1", "p",
            "n", "f", "f12", "h", "c", "r", "1", "2", "3", "4", "5", "6", "7", "8", "9", "t"};
}

enum class MouseButton : uint8_t { Left, Right, Count };
constexpr size_t BUTTON_COUNT = size_t(MouseButton::Count);

/// One platform event, stamped with the time of the run's clock it belongs to (s).
struct InputEvent {
    enum class Type : uint8_t { KeyDown, KeyUp, ButtonDown, ButtonUp, Move, Scroll, Close };
    Type type = Type::KeyDown;
    double time = 0.0;
    Key key = Key::W;                      ///< KeyDown, KeyUp
    MouseButton button = MouseButton::Left;  ///< ButtonDown, ButtonUp
    glm::vec2 value{0.0f};                 ///< Move: cursor motion (px); Scroll: (0, wheel steps)
    bool hasPos = false;                   ///< `pos` is known (a window's mouse events, scripts with `pos`)
    glm::vec2 pos{0.0f};                   ///< Move, ButtonDown, ButtonUp: the cursor after the event (framebuffer px, origin top left)
};

/// What one consumer has seen of the input: held keys and buttons, and the edges, motion
/// and wheel since its last `beginConsume()`.
struct InputState {
    std::array<bool, KEY_COUNT> down{};             ///< keys held now
    std::array<uint8_t, KEY_COUNT> presses{};       ///< key presses since the last beginConsume
    std::array<bool, BUTTON_COUNT> buttonDown{};    ///< mouse buttons held now
    std::array<uint8_t, BUTTON_COUNT> clicks{};     ///< button presses since the last beginConsume
    glm::vec2 mouseDelta{0.0f};  ///< cursor motion (px)
    glm::vec2 cursor{0.0f};      ///< where the cursor is (framebuffer px, origin top left) once cursorKnown
    bool cursorKnown = false;    ///< an event has told where the cursor is
    float scroll = 0.0f;         ///< wheel steps
    bool quit = false;           ///< the window was closed or Escape pressed
    bool uiCapturesMouse = false, uiCapturesKeyboard = false;  ///< the UI owns these (frame only)

    bool isDown(Key k) const { return down[size_t(k)]; }
    bool wasPressed(Key k) const { return presses[size_t(k)] > 0; }
    int pressCount(Key k) const { return presses[size_t(k)]; }
    bool isDown(MouseButton b) const { return buttonDown[size_t(b)]; }
    bool wasClicked(MouseButton b) const { return clicks[size_t(b)] > 0; }
    /// Forgets the edges, motion and wheel (held keys stay held).
    void beginConsume();
    /// Applies one event.
    void apply(const InputEvent& e);
};

/// The events in arrival order, drained by two consumers: the frame and the fixed step.
class InputQueue {
public:
    /// Appends an event; events must come in time order (a stamp earlier than the last
    /// one is raised to it, so the order holds).
    void push(InputEvent e);
    /// Applies to `state` every event not yet given to the frame whose time is <= `until`.
    void drainFrame(double until, InputState& state) { drain(m_frame, until, state); }
    /// Applies to `state` every event not yet given to the steps whose time is < `until`
    /// (an event exactly at a step's end belongs to the next step).
    void drainStep(double until, InputState& state, std::vector<InputEvent>* consumed = nullptr) {
        drain(m_step, until - 1e-6, state, consumed);
    }
    bool empty() const { return m_frame.empty() && m_step.empty(); }

private:
    static void drain(std::deque<InputEvent>& q, double until, InputState& state, std::vector<InputEvent>* consumed = nullptr);
    std::deque<InputEvent> m_frame, m_step;
    double m_last = -1e300;
};

} // namespace ob::platform
