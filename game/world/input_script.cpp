// Scripted input: the TOML file through the Def schema, then one event list in time order.
#include "world/input_script.h"

#include "core/error.h"
#include "core/toml_reader.h"

#include <algorithm>

namespace ob::game {

InputScriptDef loadInputScript(const std::string& path) {
    std::vector<std::string> errors;
    TomlDocument doc = TomlDocument::fromFile(path, errors);
    InputScriptDef script;
    if (errors.empty()) {
        TomlReader reader(doc, errors);
        describe(reader, script);
        reader.finish();
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
        if (m.scroll != 0.0f) events.push_back({T::Scroll, double(m.at), platform::Key::W, button, glm::vec2(0.0f, m.scroll)});
        if (held) events.push_back({T::ButtonDown, double(m.at), platform::Key::W, button});
        if (m.drag != glm::vec2(0.0f)) events.push_back({T::Move, double(m.at) + 0.5 * double(m.hold), platform::Key::W, button, m.drag});
        if (held) events.push_back({T::ButtonUp, double(m.at) + double(m.hold), platform::Key::W, button});
    }
    // Stable: what falls at one time keeps its order (a tap's down before its up).
    std::stable_sort(events.begin(), events.end(), [](const InputEvent& a, const InputEvent& b) { return a.time < b.time; });
    return events;
}

} // namespace ob::game
