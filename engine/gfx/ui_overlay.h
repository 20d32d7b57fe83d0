// Dear ImGui overlay for window mode (GLFW + OpenGL 3 backends from Debian's libimgui-dev),
// and a schema visitor that edits any Def through its describe().
#pragma once
#include "core/schema.h"

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

namespace ob::gfx {

class UiDraw;

/// ImGui context bound to a GLFW window, or headless (no window: drawn, never given input),
/// so a headless `play` draws what a window shows.
class UiOverlay {
public:
    /// `glfwWindow`: null for a headless overlay.
    explicit UiOverlay(void* glfwWindow);
    ~UiOverlay();
    /// Starts a UI frame on a framebuffer of `size` px (call between the scene's passes and
    /// present); `scale` multiplies the fonts and the style's sizes (1: ImGui's own).
    void begin(glm::ivec2 size, float scale);
    /// Draws the UI over the frame.
    void end();
    /// Whether the UI wants the mouse and keyboard this frame.
    void captureFlags(bool& mouse, bool& keyboard) const;

private:
    bool m_window = false;   // the GLFW backend feeds input, size and time; ImGui's OpenGL 3 backend draws
    float m_scale = 1.0f;    // the scale the style holds now
    glm::ivec2 m_size{0};    // headless: the framebuffer
    std::unique_ptr<UiDraw> m_draw;  // headless: the engine's own renderer of the draw data
};

/// Edits a Def's fields with ImGui widgets: `UiEditor e; describe(e, def);`
class UiEditor {
public:
    /// `liveOnly`: shows only the keys a describe() marks LIVE (a panel applied while the world
    /// runs); otherwise every key.
    explicit UiEditor(bool liveOnly = false) : m_liveOnly(liveOnly) {}
    /// Whether a widget changed a value since the editor was made.
    bool changed() const { return m_changed; }
    void field(const char* key, bool& value, const char* doc, Change = {});
    void field(const char* key, int& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, uint64_t& value, const char* doc, Change = {});
    void field(const char* key, float& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, glm::vec2& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, glm::vec3& value, Limits limits, const char* doc, Change = {});
    void field(const char* key, std::string& value, const char* doc, Change = {});
    template <NamedEnum E> void field(const char* key, E& value, const char* doc, Change change = {}) {
        if (hidden(change)) return;
        std::size_t index = std::size_t(value);
        choice(key, enumNames<E>, index, doc);
        value = E(index);
    }
    /// A list of an enum's words: a checkbox per word.
    template <NamedEnum E> void field(const char* key, std::vector<E>& values, const char* doc, Change change = {}) {
        if (hidden(change)) return;
        std::vector<bool> on(enumNames<E>.size(), false);
        for (E v : values) on[std::size_t(v)] = true;
        if (!checkboxes(key, enumNames<E>, on, doc)) return;
        values.clear();
        for (std::size_t i = 0; i < on.size(); ++i)
            if (on[i]) values.push_back(E(i));
    }
    /// A checkbox per word on one line; true when one changed.
    bool checkboxes(const char* key, Words words, std::vector<bool>& on, const char* doc);
    /// A combo box over `words` (an enum's).
    void choice(const char* key, Words words, std::size_t& index, const char* doc);
    void field(const char* key, std::vector<glm::vec2>& points, Limits limits, const char* doc, Change = {});
    /// Another Def's keys, in this section.
    template <class Def> void fields(Def& def) { describe(*this, def); }
    /// A collapsible header per section.
    template <class Def>
    void section(const char* key, Def& def) {
        if (!beginSection(key)) return;
        describe(*this, def);
        endSection();
    }

    /// A collapsible header per list, one tree node per element.
    template <class Item>
    void list(const char* key, std::vector<Item>& items, const char*) {
        if (!beginSection(key)) return;
        for (size_t i = 0; i < items.size(); ++i) {
            if (!beginItem(int(i))) continue;
            describe(*this, items[i]);
            endItem();
        }
        endSection();
    }

private:
    bool hidden(Change change) const { return m_liveOnly && change != Change::Live; }
    bool beginItem(int index);
    void endItem();
    bool beginSection(const char* key);
    void endSection();
    bool m_liveOnly = false;
    bool m_changed = false;
};

} // namespace ob::gfx
