// Scripted input (`run --input EVENTS.toml`, `play --input`): key presses and mouse actions
// at times of the run's clock, fed through the same queue as a window's events, so the
// input path is tested headless and deterministically.
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "platform/input.h"
#include "platform/window_def.h"
#include "world/script.h"

#include <string>
#include <vector>

namespace ob::game {

/// One [[press]]: `key` goes down at `at` and up `hold` seconds later.
struct PressDef {
    float at = 0.0f;           ///< clock time of the press (s): simulated in `run`, wall in `play`, [0, 1e6]
    platform::Key key = platform::Key::Space;  ///< the key
    float hold = 0.05f;        ///< seconds held, [0, 1e6] (0: down and up at once, a tap)
};

template <class V> void describe(V& v, PressDef& d) {
    v.field("at", d.at, range(0, 1e6), "clock time of the press (s)");
    v.field("key", d.key, "the key pressed");
    v.field("hold", d.hold, range(0, 1e6), "seconds held (0: a tap)");
}

/// The button a [[mouse]] entry holds.
enum class ScriptButton : uint8_t { Left, Right, None };
constexpr std::array<const char*, 3> names(ScriptButton) { return {"left", "right", "none"}; }

/// One [[mouse]]: the cursor put at `pos` (when given), a button held for `hold` seconds
/// (optional), the cursor dragged by `drag` pixels halfway through and kept there to the
/// release, the wheel turned by `scroll` steps at `at`.
struct MouseDef {
    float at = 0.0f;              ///< clock time (s), [0, 1e6]
    ScriptButton button = ScriptButton::Left;  ///< "left", "right" or "none"
    float hold = 0.05f;           ///< seconds the button is held, [0, 1e6]
    glm::vec2 pos{-1.0f};         ///< where the press happens (framebuffer px, origin top left); [-1, -1]: where the cursor is
    glm::vec2 drag{0.0f};         ///< cursor motion (px, +x right, +y down), at at + hold/2
    float scroll = 0.0f;          ///< wheel steps (+: away from the user), at `at`
};

template <class V> void describe(V& v, MouseDef& d) {
    v.field("at", d.at, range(0, 1e6), "clock time (s)");
    v.field("button", d.button, "button held");
    v.field("hold", d.hold, range(0, 1e6), "seconds the button is held");
    v.field("pos", d.pos, range(-1, 1e5), "where the press happens, framebuffer px from the top left ([-1, -1]: where the cursor is)");
    v.field("drag", d.drag, range(-1e5, 1e5), "cursor motion (px), halfway through the hold");
    v.field("scroll", d.scroll, range(-1000, 1000), "wheel steps");
}

/// One [[move]]: the cursor moves by `drag` pixels to `pos` at `at` (what a recording writes
/// of every motion; a script may give either).
struct MoveDef {
    float at = 0.0f;       ///< clock time (s), [0, 1e6]
    glm::vec2 pos{-1.0f};  ///< where the cursor arrives (framebuffer px); [-1, -1]: unknown (pos + drag)
    glm::vec2 drag{0.0f};  ///< the motion (px; what right drag steers the camera by)
};

template <class V> void describe(V& v, MoveDef& d) {
    v.field("at", d.at, range(0, 1e6), "clock time (s)");
    v.field("pos", d.pos, range(-1, 1e5), "where the cursor arrives, framebuffer px ([-1, -1]: unknown)");
    v.field("drag", d.drag, range(-1e5, 1e5), "the cursor's motion, px");
}

/// One [[set]]: a live scene key changed at `at` (what the overlay's sea panel does, recorded;
/// the same keys and checks as a `set` event of the scene's timeline).
struct SetDef {
    float at = 0.0f;      ///< simulated time, s, [0, 1e6]: the step that starts nearest it
    std::string key;      ///< a live scene key, e.g. ocean.wind_speed
    float value = 0.0f;   ///< its new value
};

template <class V> void describe(V& v, SetDef& d) {
    v.field("at", d.at, range(0, 1e6), "simulated time of the change (s)");
    v.field("key", d.key, "a live scene key (as a set event's)");
    v.field("value", d.value, any(), "its new value");
}

/// The most steps a recording may say it ran: a day of play at the fastest step rate
/// (86,400 s × sim.step_hz's maximum, 1000 Hz: 86.4 million). More is no session anyone
/// recorded, and `run` of it would not end within a day (an int64's maximum: never).
constexpr uint64_t MAX_RECORDED_STEPS = uint64_t(86400.0 * ecs::MAX_STEP_HZ);

/// An input script file; a recording (`play --record`) also says how long the session ran
/// and in what framebuffer.
struct InputScriptDef {
    uint64_t steps = 0;          ///< simulation steps the recorded session ran (0: not a recording), at most MAX_RECORDED_STEPS; `run` runs as many
    glm::vec2 size{0.0f};        ///< the recorded framebuffer (px; 0: none, else --size's range [16, 8192]): `run` renders at it, so the cursor's rays are the same
    bool goal_clock_waits = false;  ///< the goal clock waited for the first input acting in the world (a recording of play)
    std::vector<PressDef> press;
    std::vector<MouseDef> mouse;
    std::vector<MoveDef> move;
    std::vector<SetDef> set;
};

template <class V> void describe(V& v, InputScriptDef& d) {
    v.field("steps", d.steps, "simulation steps the recorded session ran (run runs as many)");
    v.field("size", d.size, autoOrRange(platform::MIN_FRAMEBUFFER_PX, platform::MAX_FRAMEBUFFER_PX),
            "the recorded framebuffer, px (run renders at it)");
    v.field("goal_clock_waits", d.goal_clock_waits, "the goal clock waited for the first input (a recording of play)");
    v.list("press", d.press, "key presses");
    v.list("mouse", d.mouse, "mouse actions");
    v.list("move", d.move, "cursor motions");
    v.list("set", d.set, "live scene changes (the overlay's)");
}

/// Reads an input script; every problem (file:line:column: key: message) in one
/// ob::InputError.
InputScriptDef loadInputScript(const std::string& path);
/// The script's events, in time order (a key's up after its down when both fall together).
std::vector<platform::InputEvent> scriptEvents(const InputScriptDef& script);
/// A recording as a script: each key's down and up become a [[press]], each button's a
/// [[mouse]] at the cursor's position, each wheel turn a [[mouse]] with button "none", each
/// motion a [[move]]; scriptEvents() of it gives the events back in an order the steps
/// consume alike. `events` in time order; a key or button still down at the end is released
/// at the end of the last step.
/// The overlay's live changes (`changes`, at their steps' start times) become [[set]] entries.
InputScriptDef recordedScript(const std::vector<platform::InputEvent>& events, const std::vector<LiveChange>& changes,
                              uint64_t steps, double stepSeconds, glm::ivec2 size);

} // namespace ob::game
