// Scripted input (`run --input EVENTS.toml`, `play --input`): key presses and mouse actions
// at times of the run's clock, fed through the same queue as a window's events, so the
// input path is tested headless and deterministically.
#pragma once
#include "core/schema.h"
#include "platform/input.h"

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

/// One [[mouse]]: a button held for `hold` seconds (optional), the cursor dragged by `drag`
/// pixels halfway through, the wheel turned by `scroll` steps at `at`.
struct MouseDef {
    float at = 0.0f;              ///< clock time (s), [0, 1e6]
    ScriptButton button = ScriptButton::Left;  ///< "left", "right" or "none"
    float hold = 0.05f;           ///< seconds the button is held, [0, 1e6]
    glm::vec2 drag{0.0f};         ///< cursor motion (px, +x right, +y down), at at + hold/2
    float scroll = 0.0f;          ///< wheel steps (+: away from the user), at `at`
};

template <class V> void describe(V& v, MouseDef& d) {
    v.field("at", d.at, range(0, 1e6), "clock time (s)");
    v.field("button", d.button, "button held");
    v.field("hold", d.hold, range(0, 1e6), "seconds the button is held");
    v.field("drag", d.drag, any(), "cursor motion (px), halfway through the hold");
    v.field("scroll", d.scroll, range(-1000, 1000), "wheel steps");
}

/// An input script file.
struct InputScriptDef {
    std::vector<PressDef> press;
    std::vector<MouseDef> mouse;
};

template <class V> void describe(V& v, InputScriptDef& d) {
    v.list("press", d.press, "key presses");
    v.list("mouse", d.mouse, "mouse actions");
}

/// Reads an input script; every problem (file:line:column: key: message) in one
/// ob::InputError.
InputScriptDef loadInputScript(const std::string& path);
/// The script's events, in time order (a key's up after its down when both fall together).
std::vector<platform::InputEvent> scriptEvents(const InputScriptDef& script);

} // namespace ob::game
