// Stats (per-phase ms and their graph), the player's ship and cannon, the sea (ui/sea_panel),
// live settings (the [render] keys), every other scene key on a copy applied by restarting,
// "save scene as".
#include "ui/ui_panels.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "world/controls.h"
#include "world/sandbox.h"
#include "core/error.h"
#include "ecs/components.h"
#include "gfx/ui_overlay.h"
#include "world/tools.h"
#include "behaviours/ship.h"
#include "ui/sea_panel.h"

#include <cfloat>
#include <filesystem>
#include <imgui.h>

namespace ob::game {

// The last frames' CPU ms per phase and frame ms, as lines.
static void timingGraph(const ecs::FrameTimer& timer) {
    static constexpr size_t HISTORY = 240;
    auto plot = [](const char* label, const std::vector<double>& samples) {
        const size_t n = std::min(samples.size(), HISTORY);
        if (n == 0) return;
        float values[HISTORY];
        for (size_t i = 0; i < n; ++i) values[i] = float(samples[samples.size() - n + i]);
        ImGui::PlotLines(label, values, int(n), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 36));
    };
    plot("frame ms", timer.frameSamples());
    for (int p = 0; p < ecs::PHASE_COUNT; ++p) plot(ecs::phaseName(ecs::Phase(p)), timer.cpuSamples(ecs::Phase(p)));
}

// Every other section, edited on a copy; applied by rebuilding the world from it. Returns
// the copy as the panel shows it (with the live [render] keys).
static SceneDef sceneEditor(const SceneDef& scene, std::optional<SceneDef>& restart) {
    static SceneDef edited;
    static const SceneDef* source = nullptr;
    static std::string problem;
    if (source != &scene) {
        edited = scene;
        source = &scene;
        problem.clear();
    }
    edited.render = scene.render;  // the live [render] keys carry over
    if (!ImGui::CollapsingHeader("scene (applied on restart)")) return edited;
    gfx::UiEditor editor;
    editor.section("sim", edited.sim);
    editor.section("camera", edited.camera);
    editor.section("ocean", edited.ocean);
    editor.section("gerstner", edited.gerstner);
    editor.section("ripples", edited.ripples);
    editor.section("physics", edited.physics);
    editor.section("splash", edited.splash);
    editor.section("foam", edited.foam);
    editor.list("objects", edited.objects, "");
    editor.list("events", edited.events, "");
    if (ImGui::Button("restart with these settings")) {
        problem = checkEditedScene(edited);
        if (problem.empty()) restart = edited;
    }
    ImGui::SameLine();
    if (ImGui::Button("revert")) {
        edited = scene;
        problem.clear();
    }
    if (!problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
    return edited;
}

std::vector<std::string> keyHelp(ecs::World& world) {
    const bool flying = cameraFlies(world);
    bool ship = false, cannon = false;
    for (const Ship& s : world.pool<Ship>().components()) ship = ship || s.player;
    for (const Cannon& c : world.pool<Cannon>().components()) cannon = cannon || c.player;
    std::vector<std::string> lines;
    if (flying) lines.push_back("W/S/A/D move  Q/E down/up  Shift fast  hold Q at the surface: dive");
    else if (ship) lines.push_back("W/S throttle  A/D rudder");
    if (cannon) lines.push_back("arrows aim  Space fire");
    lines.push_back("left button: the tool  1 grab  2 stir  3 drop (again: next object)  4 erase  5 cannon");
    lines.push_back(std::string("right drag ") + (flying ? "look" : "orbit") + "  wheel " + (flying ? "forward" : "zoom") +
                    "  C camera mode (now " + cameraMode(world) + ")");
    lines.push_back("F fish  P pause  N step (paused)  F12 screenshot  H hide this  Esc quit");
    return lines;
}

static void playerPanel(ecs::World& world) {
    if (const auto* sim = world.resource<ecs::SimControl>(); sim && sim->paused)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "paused: P resumes, N steps");
    auto& ships = world.pool<Ship>();
    for (size_t i = 0; i < ships.size(); ++i) {
        const Ship& ship = ships.components()[i];
        if (!ship.player) continue;
        const glm::vec3 v = world.get<ecs::Motion>(ships.entities()[i]).velocity;
        ImGui::Text("ship: throttle %+.0f%%  rudder %+.0f  speed %.1f m/s", 100.0 * ship.throttle, double(ship.rudder),
                    double(std::hypot(v.x, v.z)));
    }
    auto& cannons = world.pool<Cannon>();
    for (size_t i = 0; i < cannons.size(); ++i) {
        const Cannon& c = cannons.components()[i];
        if (c.player) ImGui::Text("cannon: yaw %.0f  elevation %.0f  shots %d", double(c.yawDeg), double(c.elevationDeg), c.shots);
    }
    for (const std::string& line : keyHelp(world)) ImGui::TextDisabled("%s", line.c_str());
}

// A key press as the window would give it: the palette's choices go through the input queue,
// so the steps see them when they see keys and a recording holds them.
static void pressKey(ecs::World& world, platform::Key key, double now) {
    if (auto* queue = world.resource<platform::InputQueue>()) {
        queue->push({platform::InputEvent::Type::KeyDown, now, key});
        queue->push({platform::InputEvent::Type::KeyUp, now, key});
    }
}

// The tools' palette: the tool (keys 1–5), what it drops, its sizes, what it last said.
static void toolsPanel(ecs::World& world, double now) {
    auto* tools = world.resource<PlayerTools>();
    if (!tools) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + viewport->WorkSize.y - 10),
                            ImGuiCond_Always, ImVec2(1.0f, 1.0f));  // bottom right, clear of the main panel
    ImGui::Begin("tools", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    constexpr platform::Key KEYS[] = {platform::Key::Num1, platform::Key::Num2, platform::Key::Num3, platform::Key::Num4,
                                      platform::Key::Num5};
    for (size_t k = 0; k < std::size(KEYS); ++k) {
        if (k > 0) ImGui::SameLine();
        const std::string label = std::to_string(k + 1) + " " + enumNames<Tool>[k];
        if (ImGui::RadioButton(label.c_str(), tools->def.tool == Tool(k)) && tools->def.tool != Tool(k)) pressKey(world, KEYS[k], now);
    }
    ToolsDef& def = tools->def;
    switch (def.tool) {
    case Tool::Grab:
        ImGui::TextDisabled("left drag a body; wheel: nearer/farther; release throws");
        ImGui::SliderFloat("spring Hz", &def.grab_frequency_hz, 0.1f, 20.0f, "%.1f");
        break;
    case Tool::Stir:
        ImGui::TextDisabled("hold left on the water; wheel: radius, Shift + wheel: depth");
        ImGui::SliderFloat("radius m", &def.stir_radius, 0.05f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
        ImGui::SliderFloat("depth m", &def.stir_depth, -10.0f, 10.0f, "%.2f");
        break;
    case Tool::Drop: {
        ImGui::TextDisabled("left click on the water drops it %.0f m above", double(def.drop_height));
        const size_t count = enumNames<DropKind>.size();
        for (size_t k = 0; k < count; ++k) {
            if (k > 0 && k % 4 != 0) ImGui::SameLine();
            if (ImGui::RadioButton(enumNames<DropKind>[k], def.drop == DropKind(k)))
                for (size_t n = (k + count - size_t(def.drop)) % count; n > 0; --n) pressKey(world, platform::Key::Num3, now);
        }
        if (def.drop == DropKind::Ball) {
            ImGui::SliderFloat("ball radius m", &def.ball_radius, 0.05f, 5.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
            ImGui::SliderFloat("density kg/m3", &def.ball_density, 10.0f, 20000.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
            ImGui::TextDisabled(def.ball_density < 1025.0f ? "floats (water: 1025 kg/m3)" : "sinks (water: 1025 kg/m3)");
        }
        break;
    }
    case Tool::Erase: ImGui::TextDisabled("left click removes the body under the cursor (a ship, a school)"); break;
    case Tool::Cannon: ImGui::TextDisabled("left click on the water: the cannon aims there and fires"); break;
    }
    ImGui::Text("drops %d  throws %d  erased %d  shots %d", tools->drops, tools->throws, tools->erased, tools->shots);
    if (!tools->message.empty()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", tools->message.c_str());
    ImGui::End();
}

void drawPanels(ecs::World& world, SceneDef& scene, const ecs::FrameTimer& timer, std::optional<float> dynamicScale,
                std::optional<SceneDef>& restart, double now) {
    if (const auto* controls = world.resource<WindowControls>(); controls && !controls->showOverlay) return;
    toolsPanel(world, now);
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("oceanbox");
    const auto& frames = timer.frameSamples();
    double frameMs = frames.empty() ? 0.0 : frames.back();
    ImGui::Text("frame %.2f ms (%.0f fps)", frameMs, frameMs > 0 ? 1000.0 / frameMs : 0.0);
    if (dynamicScale)
        ImGui::Text("resolution scale %.2f (dynamic, holding %.0f fps)", double(*dynamicScale), double(scene.render.target_fps));
    else
        ImGui::Text("resolution scale %.2f", double(scene.render.resolution_scale));
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
    if (ImGui::CollapsingHeader("timing graph")) timingGraph(timer);
    playerPanel(world);
    seaPanel(world, scene);
    gfx::UiEditor editor;
    editor.section("render", scene.render);
    const SceneDef shown = sceneEditor(scene, restart);

    // --- save scene as
    static char path[256] = "saved_scene.toml";
    static std::string status;
    ImGui::InputText("##path", path, sizeof path);
    ImGui::SameLine();
    if (ImGui::Button("save scene as")) {
        std::string error = saveScene(shown, path);
        status = error.empty() ? std::string("saved ") + path : error;
    }
    if (!status.empty()) ImGui::TextUnformatted(status.c_str());
    ImGui::End();
}

} // namespace ob::game
