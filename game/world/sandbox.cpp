// The sandbox's phase table, its world's set-up and its state hash.
#include "world/sandbox.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "world/controls.h"
#include "core/hash.h"
#include "currents/current_layer.h"
#include "sim/currents_system.h"
#include "ecs/components.h"
#include "interaction/ripple_patch.h"
#include "behaviours/fish.h"
#include "goals/goals.h"
#include "behaviours/mooring.h"
#include "sim/objects.h"
#include "behaviours/spawning.h"
#include "ocean/ocean_fft_cpu.h"
#include "world/interpolation.h"
#include "world/scene_settings.h"
#include "world/righting.h"
#include "world/script.h"
#include "world/tools.h"
#include "behaviours/ship.h"
#include "sim/splash_foam_system.h"
#include "sim/stamp_sources.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>

namespace ob::game {

namespace {

// The view's two rows (nothing without a view): the platform's events first in the input
// phase, the passes and the UI last in the render phase.
void platformInputSystem(ecs::World& world, const ecs::Tick& tick) {
    if (View* view = world.resource<View>()) view->pollInput(world, tick);
}
// The goal (goals/goals.h), told whether the player's input this step acts in the world (a
// goal clock that waits for the player starts there).
void gameSystem(ecs::World& world, const ecs::Tick& tick) {
    const auto* input = world.resource<StepInput>();
    gameStep(world, tick, input && actsInWorld(*input));
}

void renderSystem(ecs::World& world, const ecs::Tick& tick) {
    if (View* view = world.resource<View>()) view->render(world, tick);
}

// The frame's phase table: every system in execution order, its phase and its rate.
using ecs::Phase;
using ecs::Rate;
const ecs::SystemEntry SYSTEMS[] = {
    {Phase::Input, Rate::Frame, "platform input", platformInputSystem},
    {Phase::Input, Rate::Frame, "frame input", frameInputSystem},
    {Phase::Input, Rate::Frame, "controls", controlsSystem},
    {Phase::Script, Rate::Step, "step poses", rememberPosesSystem},  // what the frames until the next step draw from
    {Phase::Script, Rate::Step, "step input", stepInputSystem},
    {Phase::Script, Rate::Step, "tools", toolsSystem},
    {Phase::Script, Rate::Step, "righting", rightingSystem},  // T: a capsized ship upright
    {Phase::Script, Rate::Step, "events", scriptSystem},
    {Phase::Script, Rate::Step, "settings", settingsSystem},  // after the timeline's and the UI's live changes
    {Phase::Script, Rate::Step, "spawn requests", spawnRequestsSystem},
    {Phase::Script, Rate::Step, "ships", shipSystem},
    {Phase::Script, Rate::Step, "cannons", cannonSystem},
    {Phase::Script, Rate::Step, "fish", fishSystem},
    {Phase::Script, Rate::Step, "moorings", mooringSystem},
    {Phase::Script, Rate::Step, "flooding", floodingSystem},  // a target hit sinks
    {Phase::Script, Rate::Step, "game", gameSystem},  // after the behaviours: judges the last physics step
    {Phase::Physics, Rate::Step, "bodies", physicsSystem},
    {Phase::Interaction, Rate::Step, "patch follows", patchFollowSystem},
    {Phase::Interaction, Rate::Step, "currents", currentsSystem},  // after the bodies' impulses, before the foam it carries
    {Phase::Interaction, Rate::Step, "ripples", interactionSystem},
    {Phase::Interaction, Rate::Step, "splashes and foam", splashFoamSystem},
    {Phase::Ocean, Rate::Step, "ocean", oceanSystem},
    {Phase::Ocean, Rate::Step, "camera", cameraSystem},
    {Phase::Render, Rate::Frame, "drawn alpha", drawnAlphaSystem},  // where between the last two steps the frame draws
    {Phase::Render, Rate::Frame, "paused camera", pausedCameraSystem},
    {Phase::Render, Rate::Frame, "render", renderSystem},
};

} // namespace

Sandbox::Sandbox(const SceneDef& scene) : m_schedule(scene.sim) {
    for (const ecs::SystemEntry& s : SYSTEMS) m_schedule.add(s);
    // The one scene of this world: everything below reads it there.
    SceneDef& def = addSceneSettings(m_world, scene).def;
    applyEnvironment(def);  // a scene edited in the UI comes here unread
    addControls(m_world, def.controls);
    spawnCamera(m_world, def.camera);
    addOcean(m_world, def.ocean, def.gerstner);
    addRipples(m_world, def.ripples, float(m_schedule.stepSeconds()));
    addCurrents(m_world, def.currents, def.physics.water_density);
    addSplashFoam(m_world, def.splash, def.foam, def.sim.seed);
    if (def.sim.pipelined) pipelineWater(m_world);  // after the foam: its sweep on a worker too
    for (const StampSource& source : {bodySource(), cannonSource(), fishSource()}) addStampSource(m_world, source);
    spawnObjects(m_world, def.physics, def.objects, def.sim.seed);
    addScript(m_world);
    addPlayerTools(m_world, def.tools, {def.window.width, def.window.height}, fishSchoolOf(def.controls), droppedShip(def));
    allowTools(m_world, allowedTools(def.game));
    addGame(m_world, def.game, def.objects, def.sim.end_time);
}

const SceneDef& Sandbox::scene() { return sceneSettings(m_world).def; }

Sandbox::~Sandbox() = default;

void Sandbox::setScriptedInput(std::vector<platform::InputEvent> events) {
    m_world.setResource(std::make_unique<ScriptedInput>(ScriptedInput{std::move(events), 0}));
}

std::optional<CameraPose> Sandbox::cameraPose() {
    auto& rigs = m_world.pool<CameraRig>();
    if (rigs.size() == 0) return std::nullopt;
    return CameraPose{rigs.components()[0], m_world.get<ecs::Transform>(rigs.entities()[0])};
}

void Sandbox::setCameraPose(const CameraPose& pose, bool keepMode) {
    auto& rigs = m_world.pool<CameraRig>();
    if (rigs.size() == 0) return;
    CameraRig& rig = rigs.components()[0];
    const CameraDef def = rig.def;
    const CameraMode startMode = rig.startMode;
    rig = pose.rig;
    rig.lastSimTime = 0.0;  // the new world's clock starts again
    if (!keepMode) {
        rig.def = def;
        rig.startMode = startMode;
    }
    m_world.get<ecs::Transform>(rigs.entities()[0]) = pose.transform;
}

std::vector<std::string> Sandbox::takeScreenshotRequests() {
    std::vector<std::string> files;
    if (auto* script = m_world.resource<ScriptState>()) files.swap(script->screenshots);
    return files;
}

bool Sandbox::takeRestartKey() {
    auto* controls = m_world.resource<WindowControls>();
    return controls && std::exchange(controls->restart, false);
}

std::string Sandbox::takeSceneSwitch() {
    auto* controls = m_world.resource<WindowControls>();
    return controls ? std::exchange(controls->sceneSwitch, std::string()) : std::string();
}

std::vector<platform::InputEvent> Sandbox::remainingScriptedInput(double now) {
    std::vector<platform::InputEvent> rest;
    if (const auto* script = m_world.resource<ScriptedInput>())
        for (size_t i = script->next; i < script->events.size(); ++i) {
            rest.push_back(script->events[i]);
            rest.back().time = std::max(0.0, rest.back().time - now);
        }
    return rest;
}

bool Sandbox::over() {
    const GameState* game = gameState(m_world);
    return game && game->over();
}

bool Sandbox::quitRequested() {
    auto* input = m_world.resource<platform::InputState>();
    return input && input->quit;
}

std::vector<std::pair<std::string, double>> Sandbox::timings(size_t skipFrames) const {
    const ecs::FrameTimer& timer = m_schedule.timer();
    const auto median = [skipFrames](const std::vector<double>& samples) {
        const size_t skip = std::min(skipFrames, samples.size() > 0 ? samples.size() - 1 : 0);
        return ecs::median(std::vector<double>(samples.begin() + long(skip), samples.end()));
    };
    std::vector<std::pair<std::string, double>> out;
    if (timer.frameSamples().empty()) return out;
    out.emplace_back("frame", median(timer.frameSamples()));
    out.emplace_back("main_cpu", median(timer.mainCpuSamples()));
    out.emplace_back("workers_cpu", median(timer.workerCpuSamples()));
    for (int p = 0; p < ecs::PHASE_COUNT; ++p)
        out.emplace_back(std::string("main_cpu.") + ecs::phaseName(ecs::Phase(p)), median(timer.threadCpuSamples(ecs::Phase(p))));
    for (int p = 0; p < ecs::PHASE_COUNT; ++p) out.emplace_back(ecs::phaseName(ecs::Phase(p)), median(timer.cpuSamples(ecs::Phase(p))));
    for (int p = 0; p < ecs::PHASE_COUNT; ++p)
        if (!timer.gpuSamples(ecs::Phase(p)).empty())
            out.emplace_back(std::string("gpu.") + ecs::phaseName(ecs::Phase(p)), median(timer.gpuSamples(ecs::Phase(p))));
    for (const auto& [pass, samples] : timer.gpuPassSamples()) out.emplace_back("gpu.pass." + pass, median(samples));
    return out;
}

void Sandbox::present() {
    if (View* view = m_world.resource<View>()) view->present();
}

uint64_t Sandbox::stateHash() {
    StateHasher h;
    h.u64(m_schedule.steps());
    auto& transforms = m_world.pool<ecs::Transform>();
    for (size_t i = 0; i < transforms.size(); ++i) {
        const ecs::Transform& t = transforms.components()[i];
        h.u64(uint32_t(transforms.entities()[i]));
        h.f32s(&t.position.x, 3);
        h.f32s(&t.rotation.x, 4);
    }
    for (const FishSchool& school : m_world.pool<FishSchool>().components()) {
        h.u64(school.size());
        for (const glm::vec3& p : school.position) h.f32s(&p.x, 3);
    }
    if (auto* patch = m_world.resource<interaction::RipplePatch>()) patch->hashState(h);
    if (auto* layer = m_world.resource<currents::CurrentLayer>()) layer->hashState(h);
    auto& motions = m_world.pool<ecs::Motion>();
    for (size_t i = 0; i < motions.size(); ++i) h.f32s(&motions.components()[i].velocity.x, 3);
    hashSplashFoam(m_world, h);
    if (auto* ocean = m_world.resource<OceanState>()) {
        h.f64(ocean->mapsTime);
        // The maps themselves: FFTW's plan and the worker split must not change a bit of them.
        const ocean::OceanFftCpu& fft = *ocean->cpu;
        const size_t count = size_t(fft.resolution()) * size_t(fft.resolution());
        for (int c = 0; c < fft.cascadeCount(); ++c)
            for (int ch = 0; ch < ocean::OCEAN_CHANNEL_COUNT; ++ch) h.f32s(fft.channel(c, ocean::OceanChannel(ch)), count);
    }
    return h.value();
}

} // namespace ob::game
