// The player's controls: the input queue's two consumers and the keys of the frame.
#include "world/controls.h"

#include "assets/model.h"
#include "world/camera.h"
#include "core/log.h"
#include "sim/objects.h"
#include "behaviours/spawning.h"
#include "world/script.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace ob::game {

bool isWindowKey(platform::Key key) {
    using platform::Key;
    return key == Key::Escape || key == Key::P || key == Key::N || key == Key::H || key == Key::F12 || key == Key::R;
}

bool actsInWorld(const platform::InputState& input) {
    for (size_t k = 0; k < platform::KEY_COUNT; ++k)
        if (input.presses[k] > 0 && !isWindowKey(platform::Key(k))) return true;
    for (uint8_t c : input.clicks)
        if (c > 0) return true;
    return input.scroll != 0.0f;
}

bool anyPress(const platform::InputState& input) {
    for (uint8_t p : input.presses)
        if (p > 0) return true;
    for (uint8_t c : input.clicks)
        if (c > 0) return true;
    return input.scroll != 0.0f;
}

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

void controlsSystem(ecs::World& world, const ecs::Tick& tick) {
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
    if (input->wasPressed(Key::H))
        controls->overlay = controls->overlay == OverlayLevel::Full ? OverlayLevel::Folded : OverlayLevel::Full;
    if (input->wasPressed(Key::R)) controls->restart = true;
    if (anyPress(*input)) controls->card = false;
    sim->held = controls->pickerOpen;
    if (sim->paused || sim->held || sim->stopped) {
        // The steps would see this frame's events after the pause (or never, once the goal is
        // decided): they are the frame's alone (held keys stay held), and C, a step's key, works here.
        for (int i = 0; i < input->pressCount(Key::C); ++i) cycleCameraMode(world);
        if (auto* queue = world.resource<platform::InputQueue>(); queue && world.resource<StepInput>())
            queue->drainStep(tick.clock + 1e-6, *world.resource<StepInput>());
    }
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
    auto* recorder = world.resource<InputRecorder>();
    const size_t recorded = recorder ? recorder->events.size() : 0;
    queue->drainStep(tick.clock, *input, recorder ? &recorder->events : nullptr);
    if (recorder) {
        using platform::Key;
        using T = platform::InputEvent::Type;
        const auto windowKey = [](const platform::InputEvent& e) {
            const bool key = e.type == T::KeyDown || e.type == T::KeyUp;
            return e.type == T::Close || (key && e.key != Key::R && isWindowKey(e.key));  // R restarts: recorded
        };
        auto& events = recorder->events;
        events.erase(std::remove_if(events.begin() + long(recorded), events.end(), windowKey), events.end());
        for (size_t i = recorded; i < events.size(); ++i) events[i].time = tick.time + 0.5 * tick.dt;
    }
    for (int i = 0; i < input->pressCount(platform::Key::C); ++i) cycleCameraMode(world);
    input->keysMoveCamera = cameraFlies(world);
    if (auto* controls = world.resource<WindowControls>()) controls->spawnFish += input->pressCount(platform::Key::F);
}

ObjectDef fishSchoolOf(const ControlsDef& def) {
    ObjectDef fish;
    fish.type = ObjectType::FishSchool;
    fish.school.radius = def.fish_radius;
    fish.school.count = def.fish_count;
    fish.school.speed = def.fish_speed;
    fish.school.jump_interval = def.fish_jump_interval;
    fish.school.length = def.fish_length;
    fish.color = def.fish_color;
    fish.model = assets::projectModel("fish");
    return fish;
}

void spawnRequestsSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* controls = world.resource<WindowControls>();
    if (!controls || controls->spawnFish == 0) return;
    glm::vec3 focus(0.0f);
    auto& rigs = world.pool<CameraRig>();
    if (rigs.size() > 0) focus = rigs.components()[0].focus;
    for (; controls->spawnFish > 0; --controls->spawnFish) {
        ObjectDef fish = fishSchoolOf(controls->def);
        fish.position = focus;
        spawnObject(world, fish, tick.step * 31ull + uint64_t(controls->spawnFish));
        logInfo("fish school spawned at (%.0f, %.0f)", double(focus.x), double(focus.z));
    }
}

} // namespace ob::game
