// Camera: the scene's viewpoint, section [camera]; fixed, orbiting or flown by the player.
#pragma once
#include "core/schema.h"
#include "ecs/schedule.h"
#include "gfx/renderer.h"

#include <string>

namespace ob::game {

/// The scene camera.
struct CameraDef {
    std::string mode = "orbit";            ///< "fixed", "orbit" (circles the target) or "fly" (player)
    glm::vec3 position{0.0f, 6.0f, -40.0f};///< start eye position (world m)
    glm::vec3 target{0.0f, 0.0f, 0.0f};    ///< point looked at (world m)
    float fov_deg = 60.0f;                 ///< vertical field of view (degrees), [10, 120]
    float near_m = 0.1f;                   ///< near clip distance (m), [0.001, 10]
    float far_m = 20000.0f;                ///< far clip distance (m), [10, 1e6]
    float orbit_speed_deg_s = 4.0f;        ///< orbit mode: angular speed about the target (deg/s)
    float fly_speed_m_s = 20.0f;           ///< fly mode: speed (m/s), Shift ×4
};

template <class V> void describe(V& v, CameraDef& d) {
    v.field("mode", d.mode, Choices{"fixed", "orbit", "fly"}, "fixed, orbit the target, or fly (WASD QE, right mouse looks)");
    v.field("position", d.position, any(), "start eye position (world m)");
    v.field("target", d.target, any(), "point looked at (world m)");
    v.field("fov_deg", d.fov_deg, range(10, 120), "vertical field of view (degrees)");
    v.field("near_m", d.near_m, range(0.001, 10), "near clip distance (m)");
    v.field("far_m", d.far_m, range(10, 1e6), "far clip distance (m)");
    v.field("orbit_speed_deg_s", d.orbit_speed_deg_s, range(-360, 360), "orbit mode: angular speed (deg/s)");
    v.field("fly_speed_m_s", d.fly_speed_m_s, range(0.1, 1000), "fly mode: speed (m/s)");
}

/// Camera state on the camera entity (with a Transform).
struct CameraRig {
    CameraDef def;
    float yaw = 0.0f;    ///< radians about +y; 0 looks along +z
    float pitch = 0.0f;  ///< radians above the horizon
};

/// Creates the camera entity from its Def.
ecs::Entity spawnCamera(ecs::World& world, const CameraDef& def);
/// Script phase: moves the camera (orbit, or fly from the input state).
void cameraSystem(ecs::World& world, const ecs::Tick& tick);
/// The view of the first camera entity for a framebuffer of `size`.
gfx::CameraView cameraView(ecs::World& world, glm::ivec2 size);

} // namespace ob::game
