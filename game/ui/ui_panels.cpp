// Stats (per-phase ms and their graph), the player's ship and cannon, the sea (ui/sea_panel),
// live settings (the [render] keys), every other scene key on a copy applied by restarting,
// "save scene as", the scene picker; the goal's HUD and result panel.
#include "ui/ui_panels.h"

#include "currents/current_layer.h"
#include "world/camera.h"
#include "world/interpolation.h"
#include "behaviours/cannon.h"
#include "world/controls.h"
#include "world/sandbox.h"
#include "world/scene_settings.h"
#include "core/error.h"
#include "ecs/components.h"
#include "gfx/ui_overlay.h"
#include "world/tools.h"
#include "behaviours/ship.h"
#include "ui/sea_panel.h"
#include "ui/hud.h"
#include "ui/ui_state.h"
#include "goals/goals.h"

#include <cfloat>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <cstdio>
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

// Every other section, edited on the world's copy (UiState); applied by rebuilding the world
// from it.
static void sceneEditor(ecs::World& world, std::optional<SceneDef>& restart) {
    UiState& ui = uiState(world);
    if (!ImGui::CollapsingHeader("scene (applied on restart)")) return;
    SceneDef& edited = ui.edited;
    gfx::UiEditor editor;
    editor.section("sim", edited.sim);
    editor.section("environment", edited.environment);
    editor.section("camera", edited.camera);
    editor.section("ocean", edited.ocean);
    editor.section("gerstner", edited.gerstner);
    editor.section("ripples", edited.ripples);
    editor.section("physics", edited.physics);
    editor.section("splash", edited.splash);
    editor.section("foam", edited.foam);
    editor.section("game", edited.game);
    editor.list("objects", edited.objects, "");
    editor.list("events", edited.events, "");
    if (ImGui::Button("restart with these settings")) {
        edited.render = sceneSettings(world).def.render;  // the live [render] keys carry over
        ui.editProblem = checkEditedScene(edited);
        if (ui.editProblem.empty()) restart = edited;
    }
    ImGui::SameLine();
    if (ImGui::Button("revert")) {
        edited = sceneSettings(world).def;
        ui.editProblem.clear();
    }
    if (!ui.editProblem.empty()) ImGui::TextWrapped("%s", ui.editProblem.c_str());
}

UiState& uiState(ecs::World& world) {
    if (auto* ui = world.resource<UiState>()) return *ui;
    auto& ui = world.setResource(std::make_unique<UiState>());
    ui.edited = sceneSettings(world).def;
    return ui;
}

SceneDef sceneToSave(ecs::World& world) {
    SceneDef scene = uiState(world).edited;
    scene.render = sceneSettings(world).def.render;
    return scene;
}

std::vector<std::string> keyHelp(ecs::World& world) {
    const bool flying = cameraFlies(world);
    bool ship = false, cannon = false;
    for (const Ship& s : world.pool<Ship>().components()) ship = ship || s.def.player;
    for (const Cannon& c : world.pool<Cannon>().components()) cannon = cannon || c.def.player;
    std::vector<std::string> lines;
    if (flying) lines.push_back("W/S/A/D move  Q/E down/up  Shift fast  hold Q at the surface: dive");
    else if (ship) lines.push_back("W/S throttle  A/D rudder");
    if (cannon) lines.push_back("arrows aim  Space fire");
    lines.push_back("left button: the tool  1 grab  2 stir  3 drop (again: next object)  4 erase  5 cannon");
    lines.push_back(std::string("right drag ") + (flying ? "look" : "orbit") + "  wheel " + (flying ? "forward" : "zoom") +
                    "  C camera mode (now " + cameraMode(world) + ")");
    lines.push_back("F fish  P pause  N step (paused)  R restart  F12 screenshot  H hide this  Esc quit");
    return lines;
}

static void playerPanel(ecs::World& world) {
    if (const auto* sim = world.resource<ecs::SimControl>(); sim && sim->paused)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "paused: P resumes, N steps");
    auto& ships = world.pool<Ship>();
    for (size_t i = 0; i < ships.size(); ++i) {
        const Ship& ship = ships.components()[i];
        if (!ship.def.player) continue;
        const glm::vec3 v = world.get<ecs::Motion>(ships.entities()[i]).velocity;
        ImGui::Text("ship: throttle %+.0f%%  rudder %+.0f  speed %.1f m/s", 100.0 * ship.throttle, double(ship.rudder),
                    double(std::hypot(v.x, v.z)));
    }
    auto& cannons = world.pool<Cannon>();
    for (size_t i = 0; i < cannons.size(); ++i) {
        const Cannon& c = cannons.components()[i];
        if (c.def.player) ImGui::Text("cannon: yaw %.0f  elevation %.0f  shots %d", double(c.yawDeg), double(c.elevationDeg), c.shots);
    }
    for (const std::string& line : keyHelp(world)) ImGui::TextDisabled("%s", line.c_str());
}

// --- the scene picker: config/scenes/*.toml, each with its first comment line

static std::vector<SceneEntry> sceneFiles() {
    namespace fs = std::filesystem;
    std::vector<SceneEntry> scenes;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::path(defaultScenePath()).parent_path(), ec)) {
        if (entry.path().extension() != ".toml") continue;
        SceneEntry scene{entry.path().string(), entry.path().stem().string(), ""};
        std::ifstream in(entry.path());
        for (std::string text; std::getline(in, text) && text.rfind('#', 0) == 0;) {
            const size_t from = text.find_first_not_of("# ");
            if (from != std::string::npos) scene.description += (scene.description.empty() ? "" : " ") + text.substr(from);
        }
        scenes.push_back(scene);
    }
    std::sort(scenes.begin(), scenes.end(), [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
    return scenes;
}

// Its own window at the bottom left, folded at first; open, it holds the game (no steps, the
// goal clock stops). Each scene with its whole opening comment, wrapped. Choosing a scene
// loads it (a file that does not load says why and nothing restarts) and asks for a restart.
static void scenePicker(ecs::World& world, std::optional<SceneDef>& restart) {
    UiState& ui = uiState(world);
    auto* controls = world.resource<WindowControls>();
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10.0f, screen.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(screen.x * 0.3f, 0.0f), ImVec2(screen.x * 0.6f, screen.y * 0.7f));
    const bool open = ImGui::Begin("scenes: click one to open it (the game waits)", nullptr, ImGuiWindowFlags_NoSavedSettings);
    if (controls) controls->pickerOpen = open;
    if (!open) {
        ImGui::End();
        return;
    }
    if (ui.scenes.empty() || ImGui::SmallButton("refresh")) ui.scenes = sceneFiles();
    ImGui::PushTextWrapPos(0.0f);
    for (const SceneEntry& s : ui.scenes) {
        if (ImGui::Selectable(s.name.c_str())) {
            try {
                restart = loadScene(s.path);
                if (controls) controls->sceneSwitch = s.path;
                ui.pickProblem.clear();
            } catch (const std::exception& e) {
                ui.pickProblem = e.what();
            }
        }
        if (!s.description.empty()) ImGui::TextDisabled("%s", s.description.c_str());
    }
    ImGui::PopTextWrapPos();
    if (!ui.pickProblem.empty()) ImGui::TextWrapped("%s", ui.pickProblem.c_str());
    ImGui::End();
}

// A key press as the window would give it: the palette's choices go through the input queue,
// so the steps see them when they see keys and a recording holds them.
static void pressKey(ecs::World& world, platform::Key key, double now) {
    if (auto* queue = world.resource<platform::InputQueue>()) {
        queue->push({platform::InputEvent::Type::KeyDown, now, key});
        queue->push({platform::InputEvent::Type::KeyUp, now, key});
    }
}

// A slider on the [tools] key `key`, its range the key's own (ToolsDef's describe()), moved
// through the live path.
static void toolSlider(ecs::World& world, const char* label, const char* key, float value, const char* format) {
    const Limits limits = keyLimits<ToolsDef>(key);
    liveSlider(world, label, ("tools." + std::string(key)).c_str(), value, float(limits.min), float(limits.max), format, nullptr);
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
    const ToolsDef& def = tools->def;
    switch (def.tool) {
    case Tool::Grab:
        ImGui::TextDisabled("left drag a body; wheel: nearer/farther; release throws");
        toolSlider(world, "spring Hz", "grab_frequency_hz", def.grab_frequency_hz, "%.1f");
        break;
    case Tool::Stir:
        ImGui::TextDisabled("hold left on the water; wheel: radius, Shift + wheel: depth");
        toolSlider(world, "radius m", "stir_radius", def.stir_radius, "%.2f");
        toolSlider(world, "depth m", "stir_depth", def.stir_depth, "%.2f");
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
            // Through the live path (recorded as tools.* sets): a session that used them replays.
            toolSlider(world, "ball radius m", "ball_radius", def.ball_radius, "%.2f");
            toolSlider(world, "density kg/m3", "ball_density", def.ball_density, "%.0f");
            const float water = sceneSettings(world).def.environment.water_density;
            ImGui::TextDisabled("%s (water: %.0f kg/m3)", def.ball_density < water ? "floats" : "sinks", double(water));
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

// The current layer's flow as arrows on the water (currents.arrows): every 8th cell, from the
// cell's centre on the mean level to where the water there goes in 4 s, behind the windows.
static void currentArrows(ecs::World& world) {
    const auto* layer = world.resource<currents::CurrentLayer>();
    if (!layer || !layer->def().arrows) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const gfx::CameraView view = cameraView(world, {int(size.x), int(size.y)}, drawnAlpha(world));
    const glm::mat4 clip = view.projection * view.view;
    const auto toScreen = [&](glm::vec3 p, ImVec2& out) {
        const glm::vec4 c = clip * glm::vec4(p, 1.0f);
        if (c.w <= 0.1f) return false;
        out = ImVec2((c.x / c.w * 0.5f + 0.5f) * size.x, (0.5f - c.y / c.w * 0.5f) * size.y);
        return true;
    };
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    constexpr int EVERY = 8;
    constexpr float SECONDS = 4.0f;
    const ImU32 colour = IM_COL32(120, 230, 255, 220);
    for (int j = EVERY / 2; j < layer->resolution(); j += EVERY)
        for (int i = EVERY / 2; i < layer->resolution(); i += EVERY) {
            const glm::vec2 at = layer->origin() + glm::vec2(float(i), float(j)) * layer->cellSize();
            const glm::vec2 u = layer->velocityAt(at);
            const glm::vec2 to = at + SECONDS * u;
            ImVec2 a, b;
            if (!toScreen({at.x, 0.0f, at.y}, a) || !toScreen({to.x, 0.0f, to.y}, b)) continue;
            draw->AddLine(a, b, colour, 1.5f);
            const glm::vec2 d(b.x - a.x, b.y - a.y);
            const float len = glm::length(d);
            if (len < 3.0f) continue;
            const glm::vec2 n = d / len, side(-n.y, n.x);
            const glm::vec2 tip(b.x, b.y), l = tip - 6.0f * n + 3.5f * side, r = tip - 6.0f * n - 3.5f * side;
            draw->AddTriangleFilled(b, ImVec2(l.x, l.y), ImVec2(r.x, r.y), colour);
        }
}

// The full panel (H): timings, the player's keys, the Sea, the live [render] keys, the scene
// editor and "save scene as".
static void mainPanel(ecs::World& world, SceneSettings& settings, const ecs::FrameTimer& timer, std::optional<float> dynamicScale,
                      std::optional<SceneDef>& restart) {
    const SceneDef& scene = settings.def;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(screen.x * 0.5f, screen.y * 0.8f));
    ImGui::Begin("oceanbox (H folds)", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_AlwaysAutoResize);
    if (dynamicScale)
        ImGui::Text("resolution scale %.2f (dynamic, holding %.0f fps)", double(*dynamicScale), double(scene.render.target_fps));
    else
        ImGui::Text("resolution scale %.2f", double(scene.render.resolution_scale));
    if (ImGui::CollapsingHeader("timings")) {
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
        timingGraph(timer);
    }
    playerPanel(world);
    seaPanel(world, scene);
    // The live settings: the [render] keys marked LIVE, applied from the next frame on.
    if (ImGui::CollapsingHeader("render (live)")) {
        gfx::UiEditor live(true);
        live.section("render", settings.def.render);
        if (live.changed()) settings.changed(SceneSection::Render);
    }
    sceneEditor(world, restart);

    // --- save scene as: this world's scene, as edited
    UiState& ui = uiState(world);
    char path[256];
    std::snprintf(path, sizeof path, "%s", ui.savePath.c_str());
    if (ImGui::InputText("##path", path, sizeof path)) ui.savePath = path;
    ImGui::SameLine();
    if (ImGui::Button("save scene as")) {
        const std::string error = saveScene(sceneToSave(world), ui.savePath);
        ui.saveStatus = error.empty() ? "saved " + ui.savePath : error;
    }
    if (!ui.saveStatus.empty()) ImGui::TextUnformatted(ui.saveStatus.c_str());
    ImGui::End();
}

void drawPanels(ecs::World& world, SceneSettings& settings, const ecs::FrameTimer& timer, std::optional<float> dynamicScale,
                std::optional<SceneDef>& restart, double now) {
    const auto* controls = world.resource<WindowControls>();
    const OverlayLevel level = controls ? controls->overlay : OverlayLevel::Full;
    if (level == OverlayLevel::Hidden) return;
    currentArrows(world);
    goalCues(world);
    if (level == OverlayLevel::Full) {
        toolsPanel(world, now);
        mainPanel(world, settings, timer, dynamicScale, restart);
        scenePicker(world, restart);
    } else if (auto* c = world.resource<WindowControls>()) {
        c->pickerOpen = false;
    }
    // The HUD, the card and the result come last, in front.
    compactHud(world, timer);
    startCard(world);
    resultPanel(world);
}

} // namespace ob::game
