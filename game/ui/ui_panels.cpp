// Stats (per-phase ms and their graph), the player's ship and cannon, the sea (ui/sea_panel),
// live settings (the [render] keys), every other scene key on a copy applied by restarting,
// "save scene as", the scene picker; the goal's HUD and result panel.
#include "ui/ui_panels.h"

#include "currents/current_layer.h"
#include "world/camera.h"
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
#include "goals/goals.h"

#include <cfloat>
#include <algorithm>
#include <filesystem>
#include <fstream>
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

// --- the goal: the HUD (top right) while it runs, the result panel (over the sky) once it is over

static const ImVec4 WON_COLOR{0.3f, 1.0f, 0.4f, 1.0f}, LOST_COLOR{1.0f, 0.35f, 0.3f, 1.0f}, MISSED_COLOR{1.0f, 0.4f, 0.3f, 1.0f};
constexpr double MISSED_SHOWN_S = 4.0;  // how long "gate N missed" stays on the HUD

// "12.3 s" or "12.3 / 60 s".
static std::string clockText(double time, float limit) {
    char text[64];
    if (limit > 0.0f) std::snprintf(text, sizeof text, "%.1f / %.0f s", time, double(limit));
    else std::snprintf(text, sizeof text, "%.1f s", time);
    return text;
}

// Top right: the overlay's panel holds the top left.
static void gameHud(const GameState& game) {
    if (game.def.mode == GameMode::None || game.over()) return;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(screen.x - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.55f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    ImGui::Begin("goal", nullptr, flags);
    ImGui::SetWindowFontScale(1.5f);
    const std::string clock = clockText(game.time, game.def.time_limit);
    switch (game.def.mode) {
    case GameMode::None: break;
    case GameMode::Targets:
        ImGui::Text("TARGETS   hits %d / %zu   time %s", game.score, game.targets.size(), clock.c_str());
        break;
    case GameMode::Race: {
        const size_t shown = std::min(game.nextGate + 1, game.gates.size());
        ImGui::Text("RACE   gate %zu / %zu   time %s", shown, game.gates.size(), clock.c_str());
        if (game.missed > 0 && game.def.race.missed_gate == MissedGate::Penalty)
            ImGui::Text("%d missed: +%.0f s   race time %.1f s", game.missed, double(game.missed) * double(game.def.race.miss_penalty),
                        game.raceTime());
        if (game.time - game.lastMissedTime < MISSED_SHOWN_S) ImGui::TextColored(MISSED_COLOR, "%s", game.lastMissed.c_str());
        break;
    }
    case GameMode::Herd:
        ImGui::Text("HERD   %ss in the ring %d / %d   time %s", game.def.herd.herd_prefix.c_str(), game.score, game.needed,
                    clock.c_str());  // the herded objects by their name: crates, balls
        break;
    }
    ImGui::End();
}

static void resultPanel(const GameState& game) {
    if (!game.over()) return;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(screen.x * 0.5f, screen.y * 0.08f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));  // over the sky
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoNav;
    ImGui::Begin("result", nullptr, flags);
    ImGui::SetWindowFontScale(2.5f);
    switch (game.result) {
    case GameResult::Won: ImGui::TextColored(WON_COLOR, "YOU WON"); break;
    case GameResult::Lost: ImGui::TextColored(LOST_COLOR, "%s", game.reason == "time is up" ? "TIME IS UP" : "LOST"); break;
    default: ImGui::TextUnformatted("THE END"); break;
    }
    ImGui::SetWindowFontScale(1.5f);
    if (!game.reason.empty() && game.reason != "time is up") ImGui::TextUnformatted(game.reason.c_str());
    switch (game.def.mode) {
    case GameMode::None: break;
    case GameMode::Targets: ImGui::Text("score: %d of %zu targets hit", game.score, game.targets.size()); break;
    case GameMode::Race:
        ImGui::Text("score: %d of %zu gates passed, %d missed", game.score, game.gates.size(), game.missed);
        ImGui::Text("race time %.1f s", game.raceTime());
        break;
    case GameMode::Herd: ImGui::Text("score: %d in the ring, %d needed", game.score, game.needed); break;
    }
    ImGui::Text("time %s", clockText(game.time, game.def.time_limit).c_str());
    ImGui::Separator();
    ImGui::TextUnformatted("R restarts, Esc quits");
    ImGui::End();
}

// --- the scene picker: config/scenes/*.toml, each with its first comment line

struct SceneEntry {
    std::string path, name, line;
};

static std::vector<SceneEntry> sceneFiles() {
    namespace fs = std::filesystem;
    std::vector<SceneEntry> scenes;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::path(defaultScenePath()).parent_path(), ec)) {
        if (entry.path().extension() != ".toml") continue;
        SceneEntry scene{entry.path().string(), entry.path().stem().string(), ""};
        std::ifstream in(entry.path());
        for (std::string text; std::getline(in, text);)
            if (text.rfind('#', 0) == 0) {
                scene.line = text.substr(text.find_first_not_of("# ") == std::string::npos ? text.size() : text.find_first_not_of("# "));
                break;
            }
        scenes.push_back(scene);
    }
    std::sort(scenes.begin(), scenes.end(), [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
    return scenes;
}

// Its own window at the bottom left, folded at first. Choosing a scene loads it (a file that
// does not load says why and nothing restarts) and asks for a restart with it.
static void scenePicker(ecs::World& world, std::optional<SceneDef>& restart) {
    static std::vector<SceneEntry> scenes;
    static std::string problem;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(10.0f, screen.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    const bool open = ImGui::Begin("scenes: click one to open it", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (!open) {
        ImGui::End();
        return;
    }
    if (scenes.empty() || ImGui::SmallButton("refresh")) scenes = sceneFiles();
    for (const SceneEntry& s : scenes) {
        if (ImGui::Selectable(s.name.c_str())) {
            try {
                restart = loadScene(s.path);
                if (auto* controls = world.resource<WindowControls>()) controls->sceneSwitch = s.path;
                problem.clear();
            } catch (const std::exception& e) {
                problem = e.what();
            }
        }
        if (!s.line.empty()) {
            ImGui::SameLine(140.0f);
            ImGui::TextDisabled("%s", s.line.c_str());
        }
    }
    if (!problem.empty()) ImGui::TextWrapped("%s", problem.c_str());
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
    const gfx::CameraView view = cameraView(world, {int(size.x), int(size.y)});
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

void drawPanels(ecs::World& world, SceneSettings& settings, const ecs::FrameTimer& timer, std::optional<float> dynamicScale,
                std::optional<SceneDef>& restart, double now) {
    const SceneDef& scene = settings.def;
    currentArrows(world);
    // The goal's windows come last, in front; the panel never comes before them.
    const auto goal = [&world] {
        if (const GameState* game = gameState(world)) {
            gameHud(*game);
            resultPanel(*game);
        }
    };
    if (const auto* controls = world.resource<WindowControls>(); controls && !controls->showOverlay) return goal();
    toolsPanel(world, now);
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("oceanbox", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus);
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
    // The live settings: the [render] keys marked LIVE, applied from the next frame on.
    gfx::UiEditor live(true);
    live.section("render", settings.def.render);
    if (live.changed()) settings.changed(SceneSection::Render);
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
    scenePicker(world, restart);
    goal();
}

} // namespace ob::game
