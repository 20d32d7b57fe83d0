// Stats (per-phase ms) and live settings (the [render] keys, edited through their schema).
#include "ui_panels.h"

#include "gfx/ui_overlay.h"

#include <imgui.h>

namespace ob::game {

void drawPanels(SceneDef& scene, const ecs::FrameTimer& timer) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("oceanbox");
    const auto& frames = timer.frameSamples();
    double frameMs = frames.empty() ? 0.0 : frames.back();
    ImGui::Text("frame %.2f ms (%.0f fps)", frameMs, frameMs > 0 ? 1000.0 / frameMs : 0.0);
    if (ImGui::BeginTable("phases", 3)) {
        ImGui::TableSetupColumn("phase");
        ImGui::TableSetupColumn("cpu ms");
        ImGui::TableSetupColumn("gpu ms");
        ImGui::TableHeadersRow();
        for (int p = 0; p < ecs::PHASE_COUNT; ++p) {
            auto phase = ecs::Phase(p);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(ecs::phaseName(phase));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", timer.lastCpu(phase));
            ImGui::TableNextColumn();
            const auto& gpu = timer.gpuSamples(phase);
            if (gpu.empty()) ImGui::TextUnformatted("-");
            else ImGui::Text("%.3f", gpu.back());
        }
        ImGui::EndTable();
    }
    gfx::UiEditor editor;
    editor.section("render", scene.render);
    ImGui::End();
}

} // namespace ob::game
