// Camera: the scene's viewpoint, section [camera]; fixed, orbiting, flown by the player, or
// following a ship.
#pragma once
#include "core/schema.h"
#include "ecs/components.h"
#include "ecs/schedule.h"
#include "view_data/scene_view.h"

#include <string>

namespace ob::game {

/// How the camera moves (C cycles through them in a window).
enum class CameraMode : uint8_t {
    Fixed,   ///< stays at its position, looking at its target
    Orbit,   ///< circles the target
    Fly,     ///< flown by the player (WASD QE, right drag looks)
    Follow,  ///< behind a ship
};
constexpr std::array<const char*, 4> names(CameraMode) { return {"fixed", "orbit", "fly", "follow"}; }

/// The scene camera.
struct CameraDef {
    CameraMode mode = CameraMode::Orbit;   ///< "fixed", "orbit" (circles the target), "fly" (player) or "follow" (behind a ship)
    glm::vec3 position{0.0f, 6.0f, -40.0f};///< start eye position (world m)
    glm::vec3 target{0.0f, 0.0f, 0.0f};    ///< point looked at (world m)
    float fov_deg = 60.0f;                 ///< vertical field of view (degrees), [10, 120]
    float near_m = 0.1f;                   ///< near clip distance (m), [0.001, 10]
    float far_m = 20000.0f;                ///< far clip distance (m), [10, 1e6]
    float orbit_speed_deg_s = 4.0f;        ///< orbit mode: angular speed about the target (deg/s)
    float fly_speed_m_s = 20.0f;           ///< fly mode: speed (m/s), Shift ×4
    std::string follow;                    ///< follow mode: name of the object followed ("" = the player's ship, else the first ship)
    float follow_distance_m = 28.0f;       ///< follow mode: eye distance behind the object (m), [1, 10000]
    float follow_height_m = 9.0f;          ///< follow mode: eye height above the object (m), [-100, 10000]
};

template <class V> void describe(V& v, CameraDef& d) {
    v.field("mode", d.mode, "fixed, orbit the target, fly (WASD QE, right drag looks), or follow a ship; C cycles");
    v.field("position", d.position, any(), "start eye position (world m)");
    v.field("target", d.target, any(), "point looked at (world m)");
    v.field("fov_deg", d.fov_deg, range(10, 120), "vertical field of view (degrees)", LIVE);
    v.field("near_m", d.near_m, range(0.001, 10), "near clip distance (m)", LIVE);
    v.field("far_m", d.far_m, range(10, 1e6), "far clip distance (m)", LIVE);
    v.field("orbit_speed_deg_s", d.orbit_speed_deg_s, range(-360, 360), "orbit mode: angular speed (deg/s)", LIVE);
    v.field("fly_speed_m_s", d.fly_speed_m_s, range(0.1, 1000), "fly mode: speed (m/s)", LIVE);
    v.field("follow", d.follow, "follow mode: object name (\"\" = the player's ship)");
    v.field("follow_distance_m", d.follow_distance_m, range(1, 10000), "follow mode: distance behind (m)", LIVE);
    v.field("follow_height_m", d.follow_height_m, range(-100, 10000), "follow mode: height above (m)", LIVE);
}

/// How close the camera comes to the water from above (m): follow and orbit eyes stay this
/// far above the surface below them, the fly camera FLY_CLEARANCE_M.
constexpr float CAMERA_CLEARANCE_M = 1.0f;
constexpr float FLY_CLEARANCE_M = 0.5f;
/// Fixed and orbit eyes stay this far above the highest crest within CREST_SEARCH_M of them (m).
constexpr float CREST_MARGIN_M = 1.5f;
constexpr float CREST_SEARCH_M = 5.0f;
/// Fly mode: seconds Q is held against the surface before the camera dives through it.
constexpr float DIVE_HOLD_S = 0.6f;

/// Camera state on the camera entity (with a Transform).
struct CameraRig {
    CameraDef def;
    CameraMode startMode = CameraMode::Orbit;  ///< the scene's mode (C cycles through it when it is "fixed")
    float yaw = 0.0f;    ///< radians about +y; 0 looks along +z
    float pitch = 0.0f;  ///< radians above the horizon
    glm::vec3 focus{0.0f};  ///< the point looked at (world m): the target, or the followed object
    bool placed = false;    ///< follow mode: the eye has been put behind the object once
    // The player's steering (mouse drag, wheel) of the follow camera's arm.
    float followYaw = 0.0f;    ///< radians the arm is turned about the object from straight behind
    float followLift = 0.0f;   ///< radians the arm is raised above the scene's elevation
    float followZoom = 1.0f;   ///< arm length over the scene's
    // Fly mode: below the water only on purpose.
    bool underwater = false;   ///< the player dived (Q held at the surface)
    float diveHold = 0.0f;     ///< seconds Q has been held against the surface
    double lastSimTime = 0.0;  ///< simulated time at the last update (automatic motion follows it)
    // Fixed and orbit: the eye on its own path (the orbit, the player's steering) and how far it
    // is lifted above that path to clear the crests near it (eased).
    glm::vec3 pathEye{0.0f};
    float lift = 0.0f;         ///< m
    glm::vec3 lastEye{0.0f};   ///< where the camera system left the eye (moved since: the path starts again there)
    bool pathKnown = false;
    // Follow: the heading the arm trails, eased; kept while the followed hull lies on its side.
    glm::vec2 heading{0.0f, 1.0f};
    bool headingKnown = false;
};

/// Creates the camera entity from its Def.
ecs::Entity spawnCamera(ecs::World& world, const CameraDef& def);
/// Points the camera at `target` from `eye` (events, the UI).
void placeCamera(CameraRig& rig, ecs::Transform& transform, glm::vec3 eye, glm::vec3 target);
/// Ocean phase, last, every step (so a recorded session replays the camera, and what the
/// player's tools pick, exactly; after the ocean, so it keeps above the water drawn): moves the camera from the steps' input (right drag orbits or looks,
/// wheel zooms, fly keys) and its mode's motion (orbit, follow), and keeps it above the
/// water unless the player dived.
void cameraSystem(ecs::World& world, const ecs::Tick& tick);
/// Render phase: while the simulation is paused or stopped (a goal decided), the same from the
/// frame's input (the player looks around a frozen world; nothing of it is recorded).
void pausedCameraSystem(ecs::World& world, const ecs::Tick& tick);
/// C: the next mode of follow (when there is a ship to follow) → orbit → fly (→ fixed when
/// the scene starts fixed).
void cycleCameraMode(ecs::World& world);
/// Whether the camera flies (W/S/A/D/Q/E move it, not the ship).
bool cameraFlies(ecs::World& world);
/// Interaction phase, before the ripples: a patch that follows the camera or the point it
/// looks at is centred under it ([ripples] follow).
void patchFollowSystem(ecs::World& world, const ecs::Tick& tick);
/// The camera's mode now ("" without a camera).
std::string cameraMode(ecs::World& world);
/// The object the follow mode tracks (None when there is none).
ecs::Entity followedObject(ecs::World& world, const std::string& name);
/// The view of the first camera entity for a framebuffer of `size`, `alpha` of the way through
/// the latest step (sim/step_poses.h; 1: where the step left it).
gfx::CameraView cameraView(ecs::World& world, glm::ivec2 size, float alpha = 1.0f);

} // namespace ob::game
