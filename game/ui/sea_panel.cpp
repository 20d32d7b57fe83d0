// The Sea panel: sliders over the sea's live keys and the weather presets. A slider requests
// its value when released (a drag is one change, one cross-fade), and shows the dragged value
// until the step has applied it.
#include "ui/sea_panel.h"

#include "sim/water_systems.h"
#include "world/script.h"
#include "world/sea_presets.h"
#include "ui/ui_state.h"

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <imgui.h>

namespace ob::game {

namespace {

constexpr int DRAFT_FRAMES = 30;

void request(ecs::World& world, const char* key, float value) {
    uiState(world).seaStatus = requestLiveSet(world, key, value);
}

float windHeadingDeg(const SceneDef& scene) {
    const glm::vec2 w = scene.ocean.wind_direction;
    float deg = float(std::atan2(double(w.y), double(w.x)) * 180.0 / std::numbers::pi);
    return deg < 0.0f ? deg + 360.0f : deg;
}

} // namespace

void liveSlider(ecs::World& world, const char* label, const char* key, float current, float lo, float hi, const char* format,
                const char* tip) {
    // A value dragged but not yet seen back in the scene; dropped once it is (or after a
    // while, should the step have refused it).
    auto& drafts = uiState(world).drafts;
    auto it = drafts.find(key);
    if (it != drafts.end() && (std::abs(it->second.value - current) <= 1e-4f * std::max(1.0f, std::abs(current)) || --it->second.framesLeft <= 0)) {
        drafts.erase(it);
        it = drafts.end();
    }
    float v = it != drafts.end() ? it->second.value : current;
    ImGui::SliderFloat(label, &v, lo, hi, format);
    if (tip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    if (ImGui::IsItemActive()) drafts[key] = {v, DRAFT_FRAMES};
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        drafts[key] = {v, DRAFT_FRAMES};
        request(world, key, v);
    }
}

void seaPanel(ecs::World& world, const SceneDef& scene) {
    if (!ImGui::CollapsingHeader("sea (live)", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (SeaPreset p : {SeaPreset::Calm, SeaPreset::Breeze, SeaPreset::Storm}) {
        if (p != SeaPreset::Calm) ImGui::SameLine();
        if (ImGui::Button(enumName(p))) uiState(world).seaStatus = requestPreset(world, p);
    }
    liveSlider(world, "wind m/s", "ocean.wind_speed", scene.ocean.wind_speed, 0.0f, 30.0f, "%.1f", "wind speed 10 m above the sea");
    liveSlider(world, "wind toward deg", "ocean.wind_direction_deg", windHeadingDeg(scene), 0.0f, 360.0f, "%.0f",
               "heading the wind blows toward, degrees from +x toward +z");
    liveSlider(world, "choppiness", "ocean.choppiness", scene.ocean.choppiness, 0.0f, 3.0f, "%.2f", "sharpness of the crests (horizontal displacement)");
    liveSlider(world, "swell", "gerstner.amplitude_scale", scene.gerstner.amplitude_scale, 0.0f, 3.0f, "%.2f",
               "Gerstner amplitude scale (gerstner.count long waves; a preset sets 8 when there are none)");
    if (scene.ripples.enabled) {
        // The running model's own knob (its registration's KNOB).
        interaction::RippleModels::visit(size_t(scene.ripples.model), [&]<class Model>() {
            const auto& k = Model::KNOB;
            liveSlider(world, k.label, k.key, static_cast<const typename Model::Def&>(scene.ripples).*k.value, k.lo, k.hi, k.format, k.help);
            return 0;
        });
    }
    if (scene.currents.enabled) {
        const glm::vec2 u = scene.currents.uniform;
        float heading = float(std::atan2(double(u.y), double(u.x)) * 180.0 / std::numbers::pi);
        if (heading < 0.0f) heading += 360.0f;
        liveSlider(world, "current m/s", "currents.speed", std::hypot(u.x, u.y), 0.0f, 3.0f, "%.2f",
                   "the uniform current (a tide, a river) everywhere, m/s");
        liveSlider(world, "current toward deg", "currents.direction_deg", heading, 0.0f, 360.0f, "%.0f",
                   "heading the current runs toward, degrees from +x toward +z");
        bool arrows = scene.currents.arrows;
        if (ImGui::Checkbox("current arrows", &arrows)) request(world, "currents.arrows", arrows ? 1.0f : 0.0f);
    }
    if (scene.render.time_of_day >= 0.0f) {
        liveSlider(world, "time of day h", "render.time_of_day", scene.render.time_of_day, 0.0f, 24.0f, "%.2f",
                   "local solar time: sun, sky and light follow");
        if (ImGui::SmallButton("sun as in the scene")) request(world, "render.time_of_day", -1.0f);
    } else if (ImGui::SmallButton("set the time of day")) {
        request(world, "render.time_of_day", 12.0f);
    }
    if (const auto* ocean = world.resource<OceanState>(); ocean && ocean->fade) {
        const double s = ocean->fade->weight(ocean->mapsTime);
        if (s < 1.0) ImGui::Text("sea changing: %.0f%%", 100.0 * s);
    }
    if (!uiState(world).seaStatus.empty()) ImGui::TextWrapped("%s", uiState(world).seaStatus.c_str());
}

} // namespace ob::game
