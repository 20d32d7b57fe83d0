// ImGui overlay and the Def editor.
#include "gfx/ui_overlay.h"

#include "gfx/ui_draw.h"

#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

namespace ob::gfx {

UiOverlay::UiOverlay(void* glfwWindow) : m_window(glfwWindow != nullptr) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    if (m_window) {
        ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(glfwWindow), true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
    } else {
        ImGui::GetIO().BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
        m_draw = std::make_unique<UiDraw>();
    }
}

UiOverlay::~UiOverlay() {
    if (m_window) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
    }
    m_draw.reset();
    ImGui::DestroyContext();
}

void UiOverlay::begin(glm::ivec2 size, float scale) {
    constexpr float HEADLESS_FRAME_S = 1.0f / 60.0f;  // a headless frame's UI time step
    if (std::abs(scale - m_scale) > 1e-3f) {
        // The style's sizes from the dark style's, never scaled twice.
        ImGuiStyle style;
        ImGui::StyleColorsDark(&style);
        style.ScaleAllSizes(scale);
        ImGui::GetStyle() = style;
        ImGui::GetIO().FontGlobalScale = scale;
        m_scale = scale;
    }
    m_size = size;
    if (m_window) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
    } else {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(float(size.x), float(size.y));
        io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
        io.DeltaTime = HEADLESS_FRAME_S;
    }
    ImGui::NewFrame();
}

void UiOverlay::end() {
    ImGui::Render();
    if (m_window) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    else m_draw->draw(*ImGui::GetDrawData(), m_size);
}

void UiOverlay::captureFlags(bool& mouse, bool& keyboard) const {
    mouse = ImGui::GetIO().WantCaptureMouse;
    keyboard = ImGui::GetIO().WantCaptureKeyboard;
}

static void tooltip(const char* doc) {
    if (doc && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", doc);
}

bool UiEditor::checkboxes(const char* key, Words words, std::vector<bool>& on, const char* doc) {
    bool changed = false;
    ImGui::PushID(key);
    ImGui::TextUnformatted(key);
    tooltip(doc);
    for (std::size_t i = 0; i < words.size(); ++i) {
        ImGui::SameLine();
        bool value = on[i];
        if (ImGui::Checkbox(words[i], &value)) {
            on[i] = value;
            changed = true;
        }
    }
    ImGui::PopID();
    m_changed |= changed;
    return changed;
}

// Slider bounds: the key's range where finite, else a span around the value.
static void sliderBounds(const Limits& l, float value, float& lo, float& hi) {
    lo = std::isfinite(l.min) ? float(l.min) : std::min(value, 0.0f) - 100.0f;
    hi = std::isfinite(l.max) ? float(l.max) : std::max(value, 0.0f) + 100.0f;
}

void UiEditor::field(const char* key, bool& value, const char* doc, Change change) {
    if (hidden(change)) return;
    m_changed |= ImGui::Checkbox(key, &value);
    tooltip(doc);
}

void UiEditor::field(const char* key, int& value, Limits limits, const char* doc, Change change) {
    if (hidden(change)) return;
    int lo = std::isfinite(limits.min) ? int(limits.min) : -1000000;
    int hi = std::isfinite(limits.max) ? int(limits.max) : 1000000;
    if (limits.orZero) lo = 0;  // 0 = auto; a value dragged between 0 and the range goes to its start
    m_changed |= ImGui::DragInt(key, &value, 1.0f, lo, hi);
    if (limits.orZero && value > 0 && value < int(limits.min)) value = int(limits.min);
    tooltip(doc);
}

void UiEditor::field(const char* key, uint64_t& value, const char* doc, Change change) {
    if (hidden(change)) return;
    ImGui::Text("%s = %llu", key, static_cast<unsigned long long>(value));
    tooltip(doc);
}

void UiEditor::field(const char* key, float& value, Limits limits, const char* doc, Change change) {
    if (hidden(change)) return;
    float lo, hi;
    sliderBounds(limits, value, lo, hi);
    m_changed |= ImGui::SliderFloat(key, &value, lo, hi, "%.3f", hi / std::max(lo, 1e-6f) > 100.0f && lo > 0 ? ImGuiSliderFlags_Logarithmic : 0);
    tooltip(doc);
}

void UiEditor::field(const char* key, glm::vec2& value, Limits limits, const char* doc, Change change) {
    if (hidden(change)) return;
    float lo, hi;
    sliderBounds(limits, 0.0f, lo, hi);
    m_changed |= ImGui::DragFloat2(key, &value.x, 0.01f, lo, hi);
    tooltip(doc);
}

void UiEditor::field(const char* key, glm::vec3& value, Limits limits, const char* doc, Change change) {
    if (hidden(change)) return;
    float lo, hi;
    sliderBounds(limits, 0.0f, lo, hi);
    if (lo == 0.0f && hi == 1.0f) m_changed |= ImGui::ColorEdit3(key, &value.x, ImGuiColorEditFlags_Float);
    else m_changed |= ImGui::DragFloat3(key, &value.x, 0.01f, lo, hi);
    if (limits.nonZero && value.x == 0.0f && value.y == 0.0f && value.z == 0.0f) value.y = 1e-3f;
    tooltip(doc);
}

void UiEditor::field(const char* key, std::string& value, const char* doc, Change change) {
    if (hidden(change)) return;
    ImGui::Text("%s = %s", key, value.c_str());
    tooltip(doc);
}

void UiEditor::choice(const char* key, Words words, std::size_t& index, const char* doc) {
    if (ImGui::BeginCombo(key, words[index])) {
        for (std::size_t i = 0; i < words.size(); ++i)
            if (ImGui::Selectable(words[i], i == index) && i != index) {
                index = i;
                m_changed = true;
            }
        ImGui::EndCombo();
    }
    tooltip(doc);
}

void UiEditor::field(const char* key, std::vector<glm::vec2>& points, Limits limits, const char* doc, Change change) {
    if (hidden(change)) return;
    float lo, hi;
    sliderBounds(limits, 0.0f, lo, hi);
    ImGui::PushID(key);
    ImGui::Text("%s (%zu)", key, points.size());
    tooltip(doc);
    for (size_t i = 0; i < points.size(); ++i) {
        ImGui::PushID(int(i));
        m_changed |= ImGui::DragFloat2("##p", &points[i].x, 0.1f, lo, hi);
        ImGui::PopID();
    }
    ImGui::PopID();
}

bool UiEditor::beginSection(const char* key) {
    if (!ImGui::CollapsingHeader(key)) return false;
    ImGui::PushID(key);
    return true;
}

void UiEditor::endSection() { ImGui::PopID(); }

bool UiEditor::beginItem(int index) {
    ImGui::PushID(index);
    if (ImGui::TreeNode("item", "[%d]", index)) return true;
    ImGui::PopID();
    return false;
}

void UiEditor::endItem() {
    ImGui::TreePop();
    ImGui::PopID();
}

} // namespace ob::gfx
