// Scripted input: the TOML file through the Def schema, then one event list in time order.
#include "world/input_script.h"

#include "core/error.h"
#include "core/toml_reader.h"

#include <algorithm>
#include <array>

namespace ob::game {

InputScriptDef loadInputScript(const std::string& path) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromFile(path, errors);
    InputScriptDef script;
    if (errors.empty()) {
        TomlReader reader(doc, errors);
        describe(reader, script);
        reader.finish();
        if (script.steps > MAX_RECORDED_STEPS)
            errors.push_back(doc.where("steps", path) + ": steps: at most " + std::to_string(MAX_RECORDED_STEPS) +
                             " (a day of play at the fastest step rate, " + rangeNumber(ecs::MAX_STEP_HZ) + " Hz), got " + std::to_string(script.steps));
    }
    if (!errors.empty()) {
        std::string message;
        for (const std::string& e : errors) message += (message.empty() ? "" : "\n") + e;
        throw InputError(message);
    }
    return script;
}

std::vector<platform::InputEvent> scriptEvents(const InputScriptDef& script) {
    using platform::InputEvent;
    using T = InputEvent::Type;
    std::vector<InputEvent> events;
    for (const PressDef& p : script.press) {
        events.push_back({T::KeyDown, double(p.at), p.key});
        events.push_back({T::KeyUp, double(p.at) + double(p.hold), p.key});
    }
    for (const MouseDef& m : script.mouse) {
        const auto button = m.button == ScriptButton::Right ? platform::MouseButton::Right : platform::MouseButton::Left;
        const bool held = m.button != ScriptButton::None;
        const bool placed = m.pos.x >= 0.0f && m.pos.y >= 0.0f;
        const auto event = [&](T type, double time, glm::vec2 value, glm::vec2 pos) {
            InputEvent e{type, time, platform::Key::W, button, value};
            e.hasPos = placed;
            e.pos = pos;
            events.push_back(e);
        };
        if (placed) event(T::Move, double(m.at), glm::vec2(0.0f), m.pos);
        if (m.scroll != 0.0f) event(T::Scroll, double(m.at), glm::vec2(0.0f, m.scroll), m.pos);
        if (held) event(T::ButtonDown, double(m.at), glm::vec2(0.0f), m.pos);
        if (m.drag != glm::vec2(0.0f)) event(T::Move, double(m.at) + 0.5 * double(m.hold), m.drag, m.pos + m.drag);
        if (held) events.push_back({T::ButtonUp, double(m.at) + double(m.hold), platform::Key::W, button});  // where the cursor is
    }
    for (const MoveDef& m : script.move) {
        InputEvent e{T::Move, double(m.at), platform::Key::W, platform::MouseButton::Left, m.drag};
        e.hasPos = m.pos.x >= 0.0f && m.pos.y >= 0.0f;
        e.pos = m.pos;
        events.push_back(e);
    }
    // Stable: what falls at one time keeps its order (a tap's down before its up).
    std::stable_sort(events.begin(), events.end(), [](const InputEvent& a, const InputEvent& b) { return a.time < b.time; });
    return events;
}

InputScriptDef recordedScript(const std::vector<platform::InputEvent>& events, const std::vector<LiveChange>& changes,
                              uint64_t steps, double stepSeconds, glm::ivec2 size) {
    using T = platform::InputEvent::Type;
    InputScriptDef script;
    script.steps = steps;
    script.size = glm::vec2(size);
    const float end = float(double(steps) * stepSeconds);
    // The open press of each key and button: its index in the script's list.
    std::array<long, platform::KEY_COUNT> key;
    std::array<long, platform::BUTTON_COUNT> button;
    key.fill(-1);
    button.fill(-1);
    glm::vec2 cursor(-1.0f);
    for (const platform::InputEvent& e : events) {
        const float at = float(e.time);
        if (e.hasPos) cursor = e.pos;
        switch (e.type) {
        case T::KeyDown:
            if (key[size_t(e.key)] < 0) {
                key[size_t(e.key)] = long(script.press.size());
                script.press.push_back({at, e.key, 0.0f});
            }
            break;
        case T::KeyUp:
            if (long k = key[size_t(e.key)]; k >= 0) {
                script.press[size_t(k)].hold = at - script.press[size_t(k)].at;
                key[size_t(e.key)] = -1;
            }
            break;
        case T::ButtonDown:
            if (button[size_t(e.button)] < 0) {
                button[size_t(e.button)] = long(script.mouse.size());
                MouseDef m;
                m.at = at;
                m.button = e.button == platform::MouseButton::Right ? ScriptButton::Right : ScriptButton::Left;
                m.hold = 0.0f;
                m.pos = cursor;
                script.mouse.push_back(m);
            }
            break;
        case T::ButtonUp:
            if (long b = button[size_t(e.button)]; b >= 0) {
                script.mouse[size_t(b)].hold = at - script.mouse[size_t(b)].at;
                button[size_t(e.button)] = -1;
            }
            break;
        case T::Move: script.move.push_back({at, e.hasPos ? e.pos : glm::vec2(-1.0f), e.value}); break;
        case T::Scroll: {
            MouseDef m;
            m.at = at;
            m.button = ScriptButton::None;
            m.scroll = e.value.y;
            m.pos = cursor;
            script.mouse.push_back(m);
            break;
        }
        case T::Close: break;
        }
    }
    for (const LiveChange& c : changes) script.set.push_back({float(c.time), c.key, c.value});
    for (long k : key)
        if (k >= 0) script.press[size_t(k)].hold = end - script.press[size_t(k)].at;
    for (long b : button)
        if (b >= 0) script.mouse[size_t(b)].hold = end - script.mouse[size_t(b)].at;
    return script;
}

} // namespace ob::game
