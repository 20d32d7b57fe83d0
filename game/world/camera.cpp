// Camera behaviour: fixed, orbit about the target, free fly from the input state, or follow a
// ship from behind (smoothed, so the eye does not copy the hull's roll and pitch).
#include "world/camera.h"

#include "core/log.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "sim/objects.h"
#include "sim/step_poses.h"
#include "platform/input.h"
#include "behaviours/ship.h"
#include "behaviours/step_input.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace ob::game {

static glm::vec3 forwardOf(float yaw, float pitch) {
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

// The eye's orientation: its -z turned to forwardOf(yaw, pitch), its up in the vertical plane
// through it (no roll). Built from the angles, it holds straight up and down too, where a
// look-at's cross product with the world's up vanishes.
static glm::quat orientationOf(float yaw, float pitch) {
    return glm::angleAxis(yaw + glm::pi<float>(), glm::vec3(0, 1, 0)) * glm::angleAxis(pitch, glm::vec3(1, 0, 0));
}

static void lookAt(CameraRig& rig, glm::vec3 from, glm::vec3 to) {
    glm::vec3 d = to - from;
    if (glm::dot(d, d) < 1e-12f) return;
    d = glm::normalize(d);
    rig.yaw = std::atan2(d.x, d.z);
    rig.pitch = std::asin(glm::clamp(d.y, -1.0f, 1.0f));
}

void placeCamera(CameraRig& rig, ecs::Transform& transform, glm::vec3 eye, glm::vec3 target) {
    transform.position = eye;
    rig.focus = target;
    lookAt(rig, eye, target);
    transform.rotation = orientationOf(rig.yaw, rig.pitch);
}

ecs::Entity followedObject(ecs::World& world, const std::string& name) {
    if (!name.empty()) return findObject(world, name);
    auto& ships = world.pool<Ship>();
    for (size_t i = 0; i < ships.size(); ++i)
        if (ships.components()[i].def.player) return ships.entities()[i];
    return ships.size() > 0 ? ships.entities()[0] : ecs::Entity::None;
}

ecs::Entity spawnCamera(ecs::World& world, const CameraDef& def) {
    ecs::Entity e = world.create();
    CameraRig rig;
    rig.def = def;
    rig.startMode = def.mode;
    rig.focus = def.target;
    rig.underwater = def.position.y < 0.0f;  // a scene that starts below the water means it
    lookAt(rig, def.position, def.target);
    // Oriented as the camera system leaves it: the first step's interpolation starts from here.
    world.add<ecs::Transform>(e, {def.position, orientationOf(rig.yaw, rig.pitch)});
    world.add<CameraRig>(e, rig);
    return e;
}

namespace {

constexpr float DRAG_RAD_PER_PX = 0.005f;  // right drag: orbit (follow, orbit, fixed)
constexpr float LOOK_RAD_PER_PX = 0.003f;  // right drag: look (fly)
constexpr float ZOOM_PER_STEP = 0.9f;      // wheel: the arm's length times this per step in
constexpr float FLY_WHEEL_M = 2.0f;        // wheel: fly forward this far per step
constexpr float MIN_ELEVATION = glm::radians(-10.0f), MAX_ELEVATION = glm::radians(89.0f);
// Under water the orbit's eye may go as far below the point looked at as above it: the view
// looks up at the surface from below.
constexpr float MIN_ELEVATION_UNDERWATER = -MAX_ELEVATION;

float waterHeight(ecs::World& world, glm::vec3 p) {
    const OceanState* ocean = world.resource<OceanState>();
    return ocean && ocean->water ? ocean->water->sample(p.x, p.z).height : 0.0f;
}

// The highest water within CREST_SEARCH_M of `p` (m): the eye's point and two rings of eight.
float highestCrestNear(ecs::World& world, glm::vec3 p) {
    constexpr int RING_POINTS = 8;
    float highest = waterHeight(world, p);
    for (float r : {0.5f * CREST_SEARCH_M, CREST_SEARCH_M})
        for (int k = 0; k < RING_POINTS; ++k) {
            const float a = 2.0f * float(M_PI) * float(k) / float(RING_POINTS);
            highest = std::max(highest, waterHeight(world, p + glm::vec3(r * std::cos(a), 0.0f, r * std::sin(a))));
        }
    return highest;
}

// The arm from the point looked at to the eye, turned by `yaw` about the vertical, raised
// by `lift` (elevation kept in [minElevation, MAX_ELEVATION]) and scaled by `zoom`.
glm::vec3 steerArm(glm::vec3 arm, float yaw, float lift, float zoom, float minElevation = MIN_ELEVATION) {
    const float c = std::cos(yaw), s = std::sin(yaw);
    arm = glm::vec3(c * arm.x + s * arm.z, arm.y, -s * arm.x + c * arm.z);
    if (lift == 0.0f && zoom == 1.0f) return arm;
    const float horizontal = std::hypot(arm.x, arm.z);
    const float length = glm::length(arm) * zoom;
    const float elevation = glm::clamp(std::atan2(arm.y, horizontal) + lift, minElevation, MAX_ELEVATION);
    const glm::vec2 dir = horizontal > 1e-6f ? glm::vec2(arm.x, arm.z) / horizontal : glm::vec2(0.0f, -1.0f);
    return {dir.x * length * std::cos(elevation), length * std::sin(elevation), dir.y * length * std::cos(elevation)};
}

// Fixed and orbit: the eye on its path (turned by the orbit and the player), lifted over the
// crests near it: the lift rises in LIFT_RISE_S and falls back in LIFT_FALL_S, and never
// leaves the eye under the water right below it.
void holdAboveCrests(ecs::World& world, CameraRig& rig, ecs::Transform& t, float angle, glm::vec2 drag, float zoom, float dt) {
    constexpr float LIFT_RISE_S = 0.2f, LIFT_FALL_S = 2.0f;
    if (!rig.pathKnown || glm::any(glm::greaterThan(glm::abs(t.position - rig.lastEye), glm::vec3(1e-4f)))) {
        rig.pathEye = t.position;  // first use, or moved by an event or a restart
        rig.lift = 0.0f;
        rig.pathKnown = true;
    }
    rig.pathEye = rig.def.target + steerArm(rig.pathEye - rig.def.target, angle, drag.y * DRAG_RAD_PER_PX, zoom,
                                            rig.underwater ? MIN_ELEVATION_UNDERWATER : MIN_ELEVATION);
    glm::vec3 eye = rig.pathEye;
    if (!rig.underwater) {
        const float needed = std::max(0.0f, highestCrestNear(world, eye) + CREST_MARGIN_M - eye.y);
        const float tau = needed > rig.lift ? LIFT_RISE_S : LIFT_FALL_S;
        rig.lift += (needed - rig.lift) * (1.0f - std::exp(-dt / tau));
        eye.y += rig.lift;
        eye.y = std::max(eye.y, waterHeight(world, eye) + CAMERA_CLEARANCE_M);
    }
    t.position = eye;
    rig.lastEye = eye;
}

// Fly mode: W/S/A/D/Q/E (Shift ×4), right drag looks, the wheel moves forward; 0.5 m above
// the crests unless the player holds Q against the surface (then it dives; rising through
// the surface comes back up).
void fly(ecs::World& world, CameraRig& rig, ecs::Transform& t, const platform::InputState& input, float dt) {
    using platform::Key;
    if (input.isDown(platform::MouseButton::Right)) {
        rig.yaw -= input.mouseDelta.x * LOOK_RAD_PER_PX;
        rig.pitch = glm::clamp(rig.pitch - input.mouseDelta.y * LOOK_RAD_PER_PX, -1.55f, 1.55f);
    }
    const glm::vec3 fwd = forwardOf(rig.yaw, rig.pitch);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
    glm::vec3 move(0.0f);
    move += fwd * float(input.isDown(Key::W) - input.isDown(Key::S));
    move += right * float(input.isDown(Key::D) - input.isDown(Key::A));
    move.y += float(input.isDown(Key::E) - input.isDown(Key::Q));
    const float speed = rig.def.fly_speed_m_s * (input.isDown(Key::Shift) ? 4.0f : 1.0f);
    t.position += move * speed * dt + fwd * (input.scroll * FLY_WHEEL_M);

    const float water = waterHeight(world, t.position);
    if (!rig.underwater) {
        const bool pressing = t.position.y < water + FLY_CLEARANCE_M && input.isDown(Key::Q);
        rig.diveHold = pressing ? rig.diveHold + dt : 0.0f;
        t.position.y = std::max(t.position.y, water + FLY_CLEARANCE_M);
        if (rig.diveHold >= DIVE_HOLD_S) {
            rig.underwater = true;
            rig.diveHold = 0.0f;
            t.position.y = water - 1.0f;
        }
    } else if (t.position.y > water - 0.3f) {
        rig.underwater = false;  // rose through the surface
        t.position.y = std::max(t.position.y, water + FLY_CLEARANCE_M);
    }
    rig.focus = t.position + forwardOf(rig.yaw, rig.pitch) * 20.0f;
}

} // namespace

// Moves every camera from `input` over `dt` seconds (the player's steering, the follow
// camera's easing) and to simulated time `time` (the orbit's automatic motion).
static void steerCameras(ecs::World& world, const platform::InputState* input, float dt, double time) {
    auto& rigs = world.pool<CameraRig>();
    const platform::InputState none;
    if (!input) input = &none;
    const glm::vec2 drag = input->isDown(platform::MouseButton::Right) ? input->mouseDelta : glm::vec2(0.0f);
    const float zoom = std::pow(ZOOM_PER_STEP, input->scroll);
    for (size_t i = 0; i < rigs.size(); ++i) {
        CameraRig& rig = rigs.components()[i];
        ecs::Transform& t = world.get<ecs::Transform>(rigs.entities()[i]);
        const float simDt = float(time - rig.lastSimTime);  // automatic motion stops with the simulation
        rig.lastSimTime = time;
        if (rig.def.mode == CameraMode::Fixed || rig.def.mode == CameraMode::Orbit) {
            // Rotate the eye about the vertical axis through the target (orbit: at its speed),
            // and by the player's drag and wheel.
            const float angle = (rig.def.mode == CameraMode::Orbit ? glm::radians(rig.def.orbit_speed_deg_s) * simDt : 0.0f) -
                                drag.x * DRAG_RAD_PER_PX;
            holdAboveCrests(world, rig, t, angle, drag, zoom, std::max(dt, simDt));
            lookAt(rig, t.position, rig.def.target);
            rig.focus = rig.def.target;
        } else if (rig.def.mode == CameraMode::Follow) {
            ecs::Entity target = followedObject(world, rig.def.follow);
            const ecs::Transform* object = target == ecs::Entity::None ? nullptr : world.find<ecs::Transform>(target);
            if (object) {
                // The heading the arm trails: the bow's on the water, eased over 0.5 s; kept while the
                // hull stands on its bow or stern (its bow then points at the sky or the sea floor).
                glm::vec3 bow3 = object->rotation * glm::vec3(0, 0, 1);
                const glm::vec2 flat(bow3.x, bow3.z);
                if (glm::length(flat) > 0.3f) {
                    const glm::vec2 h = glm::normalize(flat);
                    rig.heading = rig.headingKnown ? glm::normalize(rig.heading + (h - rig.heading) * (1.0f - std::exp(-dt / 0.5f)) + 1e-6f)
                                                   : h;
                    rig.headingKnown = true;
                }
                const glm::vec3 bow(rig.heading.x, 0.0f, rig.heading.y);
                const float elevation = std::atan2(rig.def.follow_height_m, rig.def.follow_distance_m);
                rig.followYaw -= drag.x * DRAG_RAD_PER_PX;
                rig.followLift = glm::clamp(rig.followLift + drag.y * DRAG_RAD_PER_PX, MIN_ELEVATION - elevation,
                                            MAX_ELEVATION - elevation);
                rig.followZoom = glm::clamp(rig.followZoom * zoom, 0.1f, 20.0f);
                const glm::vec3 arm = steerArm(-bow * rig.def.follow_distance_m + glm::vec3(0, rig.def.follow_height_m, 0),
                                               rig.followYaw, rig.followLift, rig.followZoom);
                glm::vec3 eye = object->position + arm;
                eye.y = std::max(eye.y, waterHeight(world, eye) + CAMERA_CLEARANCE_M);
                // Ease toward the spot behind the object (0.6 s; 0.08 s while the player
                // steers); jump there at first.
                const bool steering = drag != glm::vec2(0.0f) || input->scroll != 0.0f;
                const float blend = rig.placed ? 1.0f - std::exp(-dt / (steering ? 0.08f : 0.6f)) : 1.0f;
                t.position += (eye - t.position) * blend;
                // The eased eye may lag into a crest: never below the water.
                t.position.y = std::max(t.position.y, waterHeight(world, t.position) + CAMERA_CLEARANCE_M);
                rig.focus += (object->position + bow * 6.0f - rig.focus) * blend;
                rig.placed = true;
                lookAt(rig, t.position, rig.focus);
            }
        } else if (rig.def.mode == CameraMode::Fly) {
            fly(world, rig, t, *input, dt);
        }
        t.rotation = orientationOf(rig.yaw, rig.pitch);
    }
}

void cameraSystem(ecs::World& world, const ecs::Tick& tick) {
    steerCameras(world, world.resource<StepInput>(), float(tick.dt), tick.time);
}

void pausedCameraSystem(ecs::World& world, const ecs::Tick& tick) {
    const auto* control = world.resource<ecs::SimControl>();
    if (control && (control->paused || control->held || control->stopped)) steerCameras(world, world.resource<platform::InputState>(), float(tick.dt), tick.time);
}

void cycleCameraMode(ecs::World& world) {
    auto& rigs = world.pool<CameraRig>();
    if (rigs.size() == 0) return;
    CameraRig& rig = rigs.components()[0];
    std::vector<CameraMode> modes;
    if (followedObject(world, rig.def.follow) != ecs::Entity::None) modes.push_back(CameraMode::Follow);
    modes.insert(modes.end(), {CameraMode::Orbit, CameraMode::Fly});
    if (rig.startMode == CameraMode::Fixed) modes.push_back(CameraMode::Fixed);
    size_t at = 0;
    while (at < modes.size() && modes[at] != rig.def.mode) ++at;
    const CameraMode next = modes[(at + 1) % modes.size()];
    // The new mode starts where the camera is: orbit and fixed about the point looked at.
    if (next == CameraMode::Orbit || next == CameraMode::Fixed) {
        rig.def.target = rig.focus;
        if (next == CameraMode::Orbit && rig.def.orbit_speed_deg_s == 0.0f) rig.def.orbit_speed_deg_s = 4.0f;
    }
    rig.underwater = rig.underwater && next == CameraMode::Fly;
    rig.def.mode = next;
    logInfo("camera: %s (C: next mode)", enumName(next));
}

std::string cameraMode(ecs::World& world) {
    auto& rigs = world.pool<CameraRig>();
    return rigs.size() > 0 ? enumName(rigs.components()[0].def.mode) : "";
}

bool cameraFlies(ecs::World& world) {
    auto& rigs = world.pool<CameraRig>();
    return rigs.size() > 0 && rigs.components()[0].def.mode == CameraMode::Fly;
}

gfx::CameraView cameraView(ecs::World& world, glm::ivec2 size, float alpha) {
    auto& rigs = world.pool<CameraRig>();
    gfx::CameraView view;
    if (rigs.size() == 0) return view;
    const CameraRig& rig = rigs.components()[0];
    const ecs::Transform& current = world.get<ecs::Transform>(rigs.entities()[0]);
    const ecs::Transform t = drawnTransform(world.resource<StepPoses>(), rigs.entities()[0], current, alpha);
    // The eye looks along its rotation's -z; at the latest step, along yaw and pitch as they are now.
    const glm::quat rotation = alpha < 1.0f ? t.rotation : orientationOf(rig.yaw, rig.pitch);
    view.position = t.position;
    view.view = glm::mat4_cast(glm::conjugate(rotation)) * glm::translate(glm::mat4(1.0f), -t.position);
    float aspect = float(size.x) / float(std::max(size.y, 1));
    view.projection = glm::perspectiveRH_NO(glm::radians(rig.def.fov_deg), aspect, rig.def.near_m, rig.def.far_m);
    view.nearM = rig.def.near_m;
    view.farM = rig.def.far_m;
    return view;
}

void patchFollowSystem(ecs::World& world, const ecs::Tick&) {
    auto* patch = world.resource<interaction::RipplePatch>();
    auto& rigs = world.pool<CameraRig>();
    if (!patch || patch->def().follow == interaction::RippleFollow::Fixed || rigs.size() == 0) return;
    const CameraRig& rig = rigs.components()[0];
    glm::vec3 at = world.get<ecs::Transform>(rigs.entities()[0]).position;
    if (patch->def().follow == interaction::RippleFollow::Target) at = rig.focus;
    if (patch->def().follow == interaction::RippleFollow::Ship) {
        // Under the ship whatever the camera does: every source of its wake lands on every level.
        const ecs::Entity ship = followedObject(world, rig.def.follow);
        const ecs::Transform* t = ship == ecs::Entity::None ? nullptr : world.find<ecs::Transform>(ship);
        if (!t) return;
        at = t->position;
    }
    patch->centerOn(glm::vec2(at.x, at.z));
}

} // namespace ob::game
