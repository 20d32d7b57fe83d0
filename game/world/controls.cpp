// The player's controls: the input queue's two consumers and the keys of the frame.
#include "world/controls.h"

#include "world/camera.h"
#include "core/log.h"
#include "sim/objects.h"
#include "behaviours/spawning.h"
#include "world/script.h"

#include <cstdio>
#include <filesystem>

namespace ob::game {

void addControls(ecs::World& world, const ControlsDef& def) {
    world.setResource(std::make_unique<platform::InputQueue>());
    world.setResource(std::make_unique<platform::InputState>());
    world.setResource(std::make_unique<StepInput>());
    world.setResource(std::make_unique<WindowControls>()).def = def;
    world.setResource(std::make_unique<ecs::SimControl>());
}

void frameInputSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* queue = world.resource<platform::InputQueue>();
    auto* input = world.resource<platform::InputState>();
    if (!queue || !input) return;
    if (auto* script = world.resource<ScriptedInput>())
        for (; script->next < script->events.size() && script->events[script->next].time <= tick.clock; ++script->next)
            queue->push(script->events[script->next]);
    input->beginConsume();
    queue->drainFrame(tick.clock, *input);
}

void controlsSystem(ecs::World& world, const ecs::Tick&) {
    const auto* input = world.resource<platform::InputState>();
    auto* controls = world.resource<WindowControls>();
    auto* sim = world.resource<ecs::SimControl>();
    if (!input || !controls || !sim) return;
    using platform::Key;
    for (int i = 0; i < input->pressCount(Key::P); ++i) {
        sim->paused = !sim->paused;
        logInfo("%s", sim->paused ? "paused (P resumes, N steps)" : "running");
    }
    if (sim->paused) sim->stepRequests += input->pressCount(Key::N);
    if (input->wasPressed(Key::H)) controls->showOverlay = !controls->showOverlay;
    if (input->wasPressed(Key::R)) controls->restart = true;
    for (int i = 0; i < input->pressCount(Key::C); ++i) cycleCameraMode(world);
    for (int i = 0; i < input->pressCount(Key::F12); ++i) {
        // The first free name in the current folder; the frame is written after it is drawn.
        std::string name;
        do {
            char buf[64];
            std::snprintf(buf, sizeof buf, "oceanbox_shot_%03d.png", ++controls->screenshotCount);
            name = buf;
        } while (std::filesystem::exists(name));
        if (auto* script = world.resource<ScriptState>()) script->screenshots.push_back(name);
    }
}

void stepInputSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* queue = world.resource<platform::InputQueue>();
    auto* input = world.resource<StepInput>();
    if (!queue || !input) return;
    input->beginConsume();
    queue->drainStep(tick.clock, *input);
    input->keysMoveCamera = cameraFlies(world);
    if (auto* controls = world.resource<WindowControls>()) controls->spawnFish += input->pressCount(platform::Key::F);
}

void spawnRequestsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* controls = world.resource<WindowControls>();
    if (!controls || controls->spawnFish == 0) return;
    glm::vec3 focus(0.0f);
    auto& rigs = world.pool<CameraRig>();
    if (rigs.size() > 0) focus = rigs.components()[0].focus;
    for (; controls->spawnFish > 0; --controls->spawnFish) {
        const ControlsDef& def = controls->def;
        ObjectDef fish;
        fish.type = ObjectType::FishSchool;
        fish.position = focus;
        fish.school.radius = def.fish_radius;
        fish.school.count = def.fish_count;
        fish.school.speed = def.fish_speed;
        fish.school.jump_interval = def.fish_jump_interval;
        fish.school.length = def.fish_length;
        fish.color = def.fish_color;
        spawnObject(world, fish, tick.step * 31ull + uint64_t(controls->spawnFish));
        logInfo("fish school spawned at (%.0f, %.0f)", double(focus.x), double(focus.z));
    }
}

} // namespace ob::game
