// The player's hands: the tools chosen with the number keys (1 grab, 2 stir, 3 drop, 4 erase,
// 5 cannon) acting where the cursor's ray meets the water or a body (world/picking.h), at the
// fixed step from the steps' input, so a scripted or recorded session replays exactly.
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "view_data/scene_view.h"
#include "sim/objects.h"
#include "behaviours/tool_kind.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ob::game {


/// What the drop tool spawns.
enum class DropKind : uint8_t { Ball, Crate, Barrel, Buoy, Raft, FishSchool, Ship };
constexpr std::array<const char*, 7> names(DropKind) { return {"ball", "crate", "barrel", "buoy", "raft", "fish_school", "ship"}; }

/// The tools' palette, section [tools] (the overlay edits it live).
struct ToolsDef {
    Tool tool = Tool::Grab;              ///< the tool at start
    DropKind drop = DropKind::Ball;      ///< what the drop tool spawns
    float ball_radius = 0.4f;            ///< dropped ball: radius, m, [0.05, 5]
    float ball_density = 600.0f;         ///< dropped ball: density, kg/m³, [10, 20000] (water 1025: above it sinks)
    float drop_height = 3.0f;            ///< drops start this far above the water point, m, [0, 100]
    float stir_radius = 0.6f;            ///< stir: the source sphere's radius, m, [0.05, 10] (the wheel while stirring)
    float stir_depth = 0.3f;             ///< stir: how deep its centre is held under the surface, m, [-10, 10] (Shift + wheel)
    float grab_frequency_hz = 2.0f;      ///< grab: natural frequency of the critically damped spring, Hz, [0.1, 20]
};

template <class V> void describe(V& v, ToolsDef& d) {
    v.field("tool", d.tool, "the tool at start: grab, stir, drop, erase or cannon (keys 1-5)");
    v.field("drop", d.drop, "what the drop tool spawns");
    v.field("ball_radius", d.ball_radius, range(0.05, 5), "dropped ball radius, m", LIVE);
    v.field("ball_density", d.ball_density, range(10, 20000), "dropped ball density, kg/m³ (water 1025)", LIVE);
    v.field("drop_height", d.drop_height, range(0, 100), "drops start this far above the water, m", LIVE);
    v.field("stir_radius", d.stir_radius, range(0.05, 10), "stir: source sphere radius, m (wheel)", LIVE);
    v.field("stir_depth", d.stir_depth, range(-10, 10), "stir: depth of its centre under the surface, m (Shift + wheel)", LIVE);
    v.field("grab_frequency_hz", d.grab_frequency_hz, range(0.1, 20), "grab: spring frequency, Hz", LIVE);
}

/// Where the viewport's framebuffer is (a resource): the cursor's pixels become rays in it.
struct Viewport {
    glm::ivec2 size{1280, 720};  ///< framebuffer px
};

/// The tools' state (a resource).
struct PlayerTools {
    ToolsDef def;
    // --- what the cursor points at, this step
    bool cursorKnown = false;
    std::optional<glm::vec3> waterPoint;    ///< the cursor's ray on the water (world m)
    ecs::Entity hoverBody = ecs::Entity::None;  ///< the body or school under the cursor
    // --- grab
    ecs::Entity grabbed = ecs::Entity::None;
    glm::vec3 grabLocal{0.0f};              ///< the held point in the body's frame, m
    float holdDistance = 0.0f;              ///< from the eye along the cursor's ray, m
    glm::vec3 target{0.0f};                 ///< where the held point is pulled (world m)
    glm::vec3 targetVelocity{0.0f};         ///< its velocity, smoothed over ~0.1 s (the throw), m/s
    // --- stir
    ecs::Entity stirrer = ecs::Entity::None;  ///< the moving source sphere while the button is held
    // --- what the drop tool makes of a school and a ship (the scene's [controls] fish, its ship model)
    ObjectDef fishTemplate, shipTemplate;
    std::vector<Tool> allowed;              ///< the tools the scene allows (its [game] tools)
    // --- counts and what the overlay says
    int drops = 0, erased = 0, throws = 0, shots = 0;
    std::string message;                    ///< the latest note for the player ("" = none)
};

/// Creates the tools resource and the viewport (framebuffer `viewportSize`); the drop tool's
/// fish school and ship are copies of the templates.
void addPlayerTools(ecs::World& world, const ToolsDef& def, glm::ivec2 viewportSize, const ObjectDef& fishTemplate,
                    const ObjectDef& shipTemplate);
/// Limits the player to `allowed` (a goal scene's [game] tools); a tool held at start that is
/// not among them gives way to the first that is.
void allowTools(ecs::World& world, const std::vector<Tool>& allowed);
/// What the drop tool drops at `at` (on the water; the body starts drop_height above it),
/// turned `yawDeg`: the palette's choice with its size, density and model.
ObjectDef dropDef(const PlayerTools& tools, glm::vec3 at, float yawDeg);
/// Script phase, after the steps' input: 1–5 choose the tool; the cursor's ray is picked
/// against the water and the bodies; the tool acts (grab's spring, stir's source, a drop,
/// an erase, the cannon's aim and shot).
void toolsSystem(ecs::World& world, const ecs::Tick& tick);
/// The elevation (deg) at which a ball leaving `from` at `speed` m/s under gravity `g`
/// reaches `to` on the low arc (or the `high` one; no air drag), or nothing when it is out
/// of reach.
std::optional<float> ballisticElevationDeg(glm::vec3 from, glm::vec3 to, float speed, float g, bool high = false);
/// The body the overlay lights up: the one held, else the one under the cursor (None: none).
ecs::Entity highlightedBody(ecs::World& world);
/// What the renderer draws of the tools: the marker on the water and the stir ring.
void appendToolDraws(ecs::World& world, std::vector<gfx::ObjectDraw>& draws, glm::vec3 eye);

} // namespace ob::game
