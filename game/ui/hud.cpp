// The compact HUD, the start card, the result panel and the goal's cues (ui/hud.h).
#include "ui/hud.h"

#include "behaviours/cannon.h"
#include "behaviours/ship.h"
#include "goals/goals.h"
#include "view/goal_looks.h"
#include "world/camera.h"
#include "world/interpolation.h"
#include "world/controls.h"
#include "world/tools.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <imgui.h>

namespace ob::game {

namespace {

const ImVec4 WON_COLOR{0.3f, 1.0f, 0.4f, 1.0f}, LOST_COLOR{1.0f, 0.35f, 0.3f, 1.0f}, NOTE_COLOR{1.0f, 0.8f, 0.3f, 1.0f};
constexpr double CUE_S = 1.5;               // a goal event's ring fades over this (goal-clock s)
constexpr float CUE_RADIUS_M = 6.0f;        // and grows to this radius on the water
constexpr float CARD_WIDTH = 0.5f;          // the start card's width, of the view's
constexpr size_t CARD_TEXT_MAX = 160;       // characters of a file's comment the card shows
constexpr float MARGIN_PX = 8.0f;           // the windows' distance from the view's edges (at scale 1)
constexpr ImGuiWindowFlags HUD_FLAGS = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                       ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;

// "12.3 s" or "12.3 / 60 s".
std::string clockText(double time, float limit) {
    char text[64];
    if (limit > 0.0f) std::snprintf(text, sizeof text, "%.1f / %.0f s", time, double(limit));
    else std::snprintf(text, sizeof text, "%.1f s", time);
    return text;
}

// The goal's count and clock in one line ("" without a goal): "TARGETS  hits 2 / 5  12.3 / 60 s".
std::string goalLine(const GameState& game) {
    if (!game.goal) return "";
    const std::string clock = game.started || !game.waitsForPlayer ? clockText(game.time, game.def.time_limit)
                                                                     : clockText(0.0, game.def.time_limit) + " (starts with you)";
    std::string mode = enumName(game.def.mode);
    for (char& c : mode) c = char(std::toupper(static_cast<unsigned char>(c)));
    return mode + "  " + game.goal->count() + "  " + clock;
}

float uiScale() { return ImGui::GetIO().FontGlobalScale; }

} // namespace

float overlayScale(const platform::WindowDef& window, glm::ivec2 size, float contentScale) {
    constexpr float REFERENCE_HEIGHT_PX = 720.0f, MIN_AUTO = 0.75f, MAX_AUTO = 3.0f;
    if (window.ui_scale > 0.0f) return window.ui_scale;
    return std::clamp(contentScale * float(size.y) / REFERENCE_HEIGHT_PX, MIN_AUTO, MAX_AUTO);
}

std::string startCardText(const SceneDef& scene, const std::string& path) {
    if (!scene.game.intro.empty()) return scene.game.intro;
    // The opening comment, to the end of its first sentence.
    std::ifstream in(path);
    std::string text;
    for (std::string line; std::getline(in, line) && line.rfind('#', 0) == 0;) {
        const size_t from = line.find_first_not_of("# ");
        if (from != std::string::npos) text += (text.empty() ? "" : " ") + line.substr(from);
    }
    const size_t stop = text.find(". ");
    if (stop != std::string::npos) text = text.substr(0, stop + 1);
    if (text.size() > CARD_TEXT_MAX) text = text.substr(0, text.rfind(' ', CARD_TEXT_MAX)) + " ...";
    return text;
}

std::string startCardKeys(ecs::World& world) {
    bool ship = false, cannon = false;
    for (const Ship& s : world.pool<Ship>().components()) ship = ship || s.def.player;
    for (const Cannon& c : world.pool<Cannon>().components()) cannon = cannon || c.def.player;
    std::string keys;
    const auto add = [&keys](const std::string& k) { keys += (keys.empty() ? "" : "   ") + k; };
    if (ship && !cameraFlies(world)) add("W/S throttle  A/D rudder");
    const auto* tools = world.resource<PlayerTools>();
    if (tools && tools->def.tool == Tool::Cannon) add("click the water: fire");
    else if (cannon) add("arrows aim  Space fire");
    if (tools && tools->allowed.size() > 1) {
        std::string list;
        for (Tool t : tools->allowed) list += (list.empty() ? "" : "/") + std::to_string(int(t) + 1);
        add(list + " tools");
    }
    // Every camera reaches fly mode with C (world/camera.cpp cycleCameraMode), and a flying
    // camera dives with Q: every scene has its under-water view, and its card says how.
    auto& rigs = world.pool<CameraRig>();
    if (rigs.size() > 0)
        add(rigs.components()[0].def.mode == CameraMode::Fly ? "hold Q: under water, E: up" : "C until fly, hold Q: under water, E: up");
    add("H all keys");
    return keys;
}

void compactHud(ecs::World& world, const ecs::FrameTimer& timer) {
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    const float margin = MARGIN_PX * uiScale();
    ImGui::SetNextWindowPos(ImVec2(screen.x - margin, margin), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.45f);
    ImGui::Begin("hud", nullptr, HUD_FLAGS);
    const auto& frames = timer.frameSamples();
    const double ms = frames.empty() ? 0.0 : frames.back();
    const auto* tools = world.resource<PlayerTools>();
    const auto* sim = world.resource<ecs::SimControl>();
    ImGui::Text("%.0f fps   tool %s   H panels%s", ms > 0.0 ? 1000.0 / ms : 0.0, tools ? enumName(tools->def.tool) : "-",
                sim && sim->paused ? "   PAUSED (P)" : "");
    if (const GameState* game = gameState(world); game && game->goal && !game->over()) {
        ImGui::TextUnformatted(goalLine(*game).c_str());
        if (const std::string note = game->goal->note(game->time); !note.empty()) ImGui::TextColored(LOST_COLOR, "%s", note.c_str());
    }
    if (tools && !tools->message.empty()) ImGui::TextColored(NOTE_COLOR, "%s", tools->message.c_str());
    ImGui::End();
}

void startCard(ecs::World& world) {
    const auto* controls = world.resource<WindowControls>();
    if (!controls || !controls->card) return;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    const float width = screen.x * CARD_WIDTH;
    ImGui::SetNextWindowPos(ImVec2(screen.x * 0.5f, screen.y - MARGIN_PX * uiScale()), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("card", nullptr, HUD_FLAGS & ~ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(controls->cardText.c_str());
    ImGui::TextColored(NOTE_COLOR, "%s", controls->cardKeys.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void resultPanel(ecs::World& world) {
    const GameState* game = gameState(world);
    if (!game || !game->over()) return;
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(screen.x * 0.5f, screen.y * 0.08f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));  // over the sky
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("result", nullptr, HUD_FLAGS & ~ImGuiWindowFlags_NoInputs);
    ImGui::SetWindowFontScale(2.0f);
    switch (game->result) {
    case GameResult::Won: ImGui::TextColored(WON_COLOR, "YOU WON"); break;
    case GameResult::Lost: ImGui::TextColored(LOST_COLOR, "%s", game->reason == "time is up" ? "TIME IS UP" : "LOST"); break;
    default: ImGui::TextUnformatted("THE END"); break;
    }
    ImGui::SetWindowFontScale(1.0f);
    if (!game->goal) {
        // A scene without a goal: only its end_time ends it.
        ImGui::Text("the scene ends at its end_time, %.0f s", double(game->endTime));
    } else {
        ImGui::Text("ended by: %s", game->reason == "time is up" ? "the goal's time limit" : game->reason.c_str());
        ImGui::TextUnformatted(game->goal->summary().c_str());
        ImGui::Text("time %s", clockText(game->time, game->def.time_limit).c_str());
    }
    ImGui::Separator();
    ImGui::TextUnformatted("R restarts, Esc quits");
    ImGui::End();
}

void goalCues(ecs::World& world) {
    const GameState* game = gameState(world);
    if (!game || game->events.latest().empty()) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const gfx::CameraView view = cameraView(world, {int(size.x), int(size.y)}, drawnAlpha(world));
    const glm::mat4 clip = view.projection * view.view;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    constexpr int SEGMENTS = 32;
    for (const GoalEvent& e : game->events.latest()) {
        const double age = game->time - e.time;
        if (age < 0.0 || age > CUE_S) continue;
        const float f = float(age / CUE_S), radius = CUE_RADIUS_M * (0.2f + 0.8f * f);
        const glm::vec3 c = cueColor(e.state);
        const ImU32 colour = IM_COL32(int(255 * c.x), int(255 * c.y), int(255 * c.z), int(255 * (1.0f - f)));
        std::vector<ImVec2> ring;
        for (int k = 0; k < SEGMENTS; ++k) {
            const float a = 2.0f * float(M_PI) * float(k) / SEGMENTS;
            const glm::vec4 p = clip * glm::vec4(e.at.x + radius * std::cos(a), e.at.y, e.at.z + radius * std::sin(a), 1.0f);
            if (p.w <= 0.1f) {
                ring.clear();
                break;
            }
            ring.emplace_back((p.x / p.w * 0.5f + 0.5f) * size.x, (0.5f - p.y / p.w * 0.5f) * size.y);
        }
        if (!ring.empty()) draw->AddPolyline(ring.data(), int(ring.size()), colour, ImDrawFlags_Closed, 3.0f * uiScale());
    }
}

} // namespace ob::game
