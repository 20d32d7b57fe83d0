// Camera behaviour: fixed, orbit about the target, free fly from the input state, or follow a
// ship from behind (smoothed, so the eye does not copy the hull's roll and pitch).
#include "camera.h"

#include "ecs/components.h"
#include "objects.h"
#include "platform/platform.h"
#include "ship.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ob::game {

static glm::vec3 forwardOf(float yaw, float pitch) {
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
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
    transform.rotation = glm::quatLookAtRH(forwardOf(rig.yaw, rig.pitch), glm::vec3(0, 1, 0));
}

// The entity the follow mode tracks: the named object, else the player's ship, else the first ship.
static ecs::Entity followed(ecs::World& world, const std::string& name) {
    if (!name.empty()) return findObject(world, name);
    auto& ships = world.pool<Ship>();
    for (size_t i = 0; i < ships.size(); ++i)
        if (ships.components()[i].player) return ships.entities()[i];
    return ships.size() > 0 ? ships.entities()[0] : ecs::Entity::None;
}

ecs::Entity spawnCamera(ecs::World& world, const CameraDef& def) {
    ecs::Entity e = world.create();
    CameraRig rig{def};
    rig.focus = def.target;
    lookAt(rig, def.position, def.target);
    world.add<ecs::Transform>(e, {def.position});
    world.add<CameraRig>(e, rig);
    return e;
}

void cameraSystem(ecs::World& world, const ecs::Tick& tick) {
    auto& rigs = world.pool<CameraRig>();
    const auto* input = world.resource<platform::InputState>();
    for (size_t i = 0; i < rigs.size(); ++i) {
        CameraRig& rig = rigs.components()[i];
        ecs::Transform& t = world.get<ecs::Transform>(rigs.entities()[i]);
        const float dt = float(tick.dt);
        if (rig.def.mode == "fixed") {
            rig.focus = rig.def.target;
        } else if (rig.def.mode == "orbit") {
            // Rotate the eye about the vertical axis through the target.
            float angle = glm::radians(rig.def.orbit_speed_deg_s) * dt;
            glm::vec3 arm = t.position - rig.def.target;
            float c = std::cos(angle), s = std::sin(angle);
            t.position = rig.def.target + glm::vec3(c * arm.x + s * arm.z, arm.y, -s * arm.x + c * arm.z);
            lookAt(rig, t.position, rig.def.target);
            rig.focus = rig.def.target;
        } else if (rig.def.mode == "follow") {
            ecs::Entity target = followed(world, rig.def.follow);
            const ecs::Transform* object = target == ecs::Entity::None ? nullptr : world.find<ecs::Transform>(target);
            if (object) {
                glm::vec3 bow = object->rotation * glm::vec3(0, 0, 1);
                bow.y = 0.0f;
                bow = glm::dot(bow, bow) > 1e-6f ? glm::normalize(bow) : glm::vec3(0, 0, 1);
                const glm::vec3 eye = object->position - bow * rig.def.follow_distance_m + glm::vec3(0, rig.def.follow_height_m, 0);
                // Ease toward the spot behind the object (time constant 0.6 s); jump there at first.
                const float blend = rig.placed ? 1.0f - std::exp(-dt / 0.6f) : 1.0f;
                t.position += (eye - t.position) * blend;
                rig.focus += (object->position + bow * 6.0f - rig.focus) * blend;
                rig.placed = true;
                lookAt(rig, t.position, rig.focus);
            }
        } else if (rig.def.mode == "fly" && input && !input->uiCapturesKeyboard) {
            using platform::Key;
            if (input->mouseRight && !input->uiCapturesMouse) {
                rig.yaw -= input->mouseDelta.x * 0.003f;
                rig.pitch = glm::clamp(rig.pitch - input->mouseDelta.y * 0.003f, -1.55f, 1.55f);
            }
            glm::vec3 fwd = forwardOf(rig.yaw, rig.pitch);
            glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
            glm::vec3 move(0.0f);
            move += fwd * float(input->isDown(Key::W) - input->isDown(Key::S));
            move += right * float(input->isDown(Key::D) - input->isDown(Key::A));
            move.y += float(input->isDown(Key::E) - input->isDown(Key::Q));
            float speed = rig.def.fly_speed_m_s * (input->isDown(Key::Shift) ? 4.0f : 1.0f);
            t.position += move * speed * dt;
            rig.focus = t.position + forwardOf(rig.yaw, rig.pitch) * 20.0f;
        }
        t.rotation = glm::quatLookAtRH(forwardOf(rig.yaw, rig.pitch), glm::vec3(0, 1, 0));
    }
}

gfx::CameraView cameraView(ecs::World& world, glm::ivec2 size) {
    auto& rigs = world.pool<CameraRig>();
    gfx::CameraView view;
    if (rigs.size() == 0) return view;
    const CameraRig& rig = rigs.components()[0];
    const ecs::Transform& t = world.get<ecs::Transform>(rigs.entities()[0]);
    view.position = t.position;
    view.view = glm::lookAtRH(t.position, t.position + forwardOf(rig.yaw, rig.pitch), glm::vec3(0, 1, 0));
    float aspect = float(size.x) / float(std::max(size.y, 1));
    view.projection = glm::perspectiveRH_NO(glm::radians(rig.def.fov_deg), aspect, rig.def.near_m, rig.def.far_m);
    view.nearM = rig.def.near_m;
    view.farM = rig.def.far_m;
    return view;
}

} // namespace ob::game
