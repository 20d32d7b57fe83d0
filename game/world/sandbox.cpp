// The sandbox's phase table and the systems that connect the platform and renderer.
#include "world/sandbox.h"

#include "world/camera.h"
#include "behaviours/cannon.h"
#include "world/controls.h"
#include "core/hash.h"
#include "ecs/components.h"
#include "gfx/renderer.h"
#include "interaction/ripple_patch.h"
#include "gfx/ui_overlay.h"
#include "behaviours/fish.h"
#include "sim/objects.h"
#include "behaviours/spawning.h"
#include "ocean/ocean_fft_cpu.h"
#include "world/script.h"
#include "behaviours/ship.h"
#include "splash/splash_particles.h"
#include "sim/splash_foam_system.h"
#include "ui/ui_panels.h"
#include "water/composite_water.h"
#include "sim/water_systems.h"

#include <algorithm>
#include <cmath>

namespace ob::game {

namespace {

// Input phase, first: the platform's events into the input queue, stamped with the clock
// time the frame started at (they came since then), so this frame's first step sees them.
// Presses, clicks, wheel and motion the UI takes are not the game's.
void platformInputSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* res = world.resource<FrameResources>();
    auto* input = world.resource<platform::InputState>();
    auto* queue = world.resource<platform::InputQueue>();
    if (!res || !res->platform || !input || !queue) return;
    if (res->ui) res->ui->captureFlags(input->uiCapturesMouse, input->uiCapturesKeyboard);
    std::vector<platform::InputEvent> events;
    res->platform->pollEvents(events);
    using T = platform::InputEvent::Type;
    for (platform::InputEvent& e : events) {
        if (input->uiCapturesKeyboard && e.type == T::KeyDown) continue;
        if (input->uiCapturesMouse && (e.type == T::ButtonDown || e.type == T::Move || e.type == T::Scroll)) continue;
        e.time = tick.clock - tick.dt;
        queue->push(e);
    }
}

// Render phase: the passes, then the UI, then present.
void renderSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* res = world.resource<FrameResources>();
    if (!res || !res->renderer) return;
    glm::ivec2 size = res->platform->framebufferSize();
    if (size.x <= 0 || size.y <= 0) return;  // minimised
    res->renderer->def() = res->scene->render;
    // Dynamic resolution: the last frame's time sets this frame's internal scale.
    if (auto* dynamic = world.resource<DynamicScale>(); dynamic && res->scene->render.target_fps > 0.0f) {
        auto& control = dynamic->control;
        if (!control || std::abs(control->targetSeconds() * res->scene->render.target_fps - 1.0) > 1e-6)
            control.emplace(res->scene->render.target_fps, res->scene->render.resolution_scale);
        else if (!res->timer->frameSamples().empty())
            control->update(res->timer->frameSamples().back() / 1000.0);
        res->renderer->def().resolution_scale = control->scale();
    }
    gfx::CameraView camera = cameraView(world, size);
    if (const OceanState* ocean = world.resource<OceanState>(); ocean && ocean->water)
        camera.waterHeight = ocean->water->sample(camera.position.x, camera.position.z).height;
    std::vector<gfx::ObjectDraw> draws = objectDraws(world);
    appendFishDraws(world, draws);
    if (const OceanState* ocean = world.resource<OceanState>(); ocean && ocean->water)
        for (gfx::ObjectDraw& d : draws) {
            const water::WaterSample s = ocean->water->sample(d.model[3].x, d.model[3].z);
            d.waterHeight = s.height;
            d.waterSlope = -glm::vec2(s.normal.x, s.normal.z) / s.normal.y;
        }
    std::vector<gfx::SplashDrop> drops;
    if (const splash::SplashParticles* particles = splashParticles(world); particles && res->scene->render.splash_drops) {
        drops.resize(size_t(particles->size()));
        for (size_t i = 0; i < drops.size(); ++i)
            drops[i] = gfx::SplashDrop(particles->x()[i], particles->y()[i], particles->z()[i], particles->radius()[i]);
    }
    res->renderer->render(camera, prepareWaterView(world, tick.time), draws, tick.time, size, drops);
    gfx::PassTimes passes = res->renderer->takePassTimes();
    double gpuMs = 0.0;
    for (const auto& [pass, ms] : passes) {
        res->timer->addGpuPass(pass, ms);
        gpuMs += ms;
    }
    if (!passes.empty()) res->timer->setGpu(ecs::Phase::Render, gpuMs);
    if (res->ui) {
        res->ui->begin();
        drawPanels(world, *res->scene, *res->timer, *res->restart);
        res->ui->end();
    }
}

// The frame's phase table: every system in execution order, its phase and its rate.
using ecs::Phase;
using ecs::Rate;
const ecs::SystemEntry SYSTEMS[] = {
    {Phase::Input, Rate::Frame, "platform input", platformInputSystem},
    {Phase::Input, Rate::Frame, "frame input", frameInputSystem},
    {Phase::Input, Rate::Frame, "controls", controlsSystem},
    {Phase::Script, Rate::Step, "step input", stepInputSystem},
    {Phase::Script, Rate::Step, "events", scriptSystem},
    {Phase::Script, Rate::Step, "spawn requests", spawnRequestsSystem},
    {Phase::Script, Rate::Step, "ships", shipSystem},
    {Phase::Script, Rate::Step, "cannons", cannonSystem},
    {Phase::Script, Rate::Step, "fish", fishSystem},
    {Phase::Physics, Rate::Step, "bodies", physicsSystem},
    {Phase::Interaction, Rate::Step, "fish stamps", fishStampSystem},
    {Phase::Interaction, Rate::Step, "ripples", interactionSystem},
    {Phase::Interaction, Rate::Step, "splashes and foam", splashFoamSystem},
    {Phase::Ocean, Rate::Step, "ocean", oceanSystem},
    {Phase::Render, Rate::Frame, "camera", cameraSystem},
    {Phase::Render, Rate::Frame, "render", renderSystem},
};

} // namespace

Sandbox::Sandbox(const SceneDef& scene) : m_scene(scene), m_schedule(scene.sim) {
    for (const ecs::SystemEntry& s : SYSTEMS) m_schedule.add(s);
    addControls(m_world);
    spawnCamera(m_world, m_scene.camera);
    addOcean(m_world, m_scene.ocean, m_scene.gerstner);
    addRipples(m_world, m_scene.ripples, float(m_schedule.stepSeconds()));
    addSplashFoam(m_world, m_scene.splash, m_scene.foam, m_scene.sim.seed);
    spawnObjects(m_world, m_scene.physics, m_scene.objects, m_scene.sim.seed);
    addScript(m_world, m_scene);
}

Sandbox::~Sandbox() = default;

void Sandbox::attachPlatform(platform::Platform& platform, bool withUi) {
    m_renderer = std::make_unique<gfx::Renderer>(m_scene.render);
    attachWaterGpu(m_world);
    if (withUi && platform.nativeWindow()) m_ui = std::make_unique<gfx::UiOverlay>(platform.nativeWindow());
    m_world.setResource(std::make_unique<FrameResources>(
        FrameResources{&platform, m_renderer.get(), m_ui.get(), &m_schedule.timer(), &m_scene, &m_restart}));
}

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
    const std::string startMode = rig.startMode;
    rig = pose.rig;
    rig.lastSimTime = 0.0;  // the new world's clock starts again
    if (!keepMode) {
        rig.def = def;
        rig.startMode = startMode;
    }
    m_world.get<ecs::Transform>(rigs.entities()[0]) = pose.transform;
}

void Sandbox::enableDynamicResolution() { m_world.setResource(std::make_unique<DynamicScale>()); }

std::vector<std::string> Sandbox::takeScreenshotRequests() {
    std::vector<std::string> files;
    if (auto* script = m_world.resource<ScriptState>()) files.swap(script->screenshots);
    return files;
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
    for (int p = 0; p < ecs::PHASE_COUNT; ++p) out.emplace_back(ecs::phaseName(ecs::Phase(p)), median(timer.cpuSamples(ecs::Phase(p))));
    for (int p = 0; p < ecs::PHASE_COUNT; ++p)
        if (!timer.gpuSamples(ecs::Phase(p)).empty())
            out.emplace_back(std::string("gpu.") + ecs::phaseName(ecs::Phase(p)), median(timer.gpuSamples(ecs::Phase(p))));
    for (const auto& [pass, samples] : timer.gpuPassSamples()) out.emplace_back("gpu.pass." + pass, median(samples));
    return out;
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
    if (auto* patch = m_world.resource<interaction::RipplePatch>()) {
        if (const interaction::EWaveField* ewave = patch->ewave()) {
            // ewave: the height and vertical velocity (the whole state of the dispersive model)
            h.bytes(ewave->heightState().data(), ewave->heightState().size_bytes());
            h.bytes(ewave->velocityState().data(), ewave->velocityState().size_bytes());
        } else {
            auto now = patch->field().current(), before = patch->field().previous();
            h.f32s(now.data(), now.size());
            h.f32s(before.data(), before.size());
        }
    }
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
