// The sandbox's phase table and the systems that connect the platform and renderer.
#include "sandbox.h"

#include "camera.h"
#include "core/hash.h"
#include "ecs/components.h"
#include "gfx/renderer.h"
#include "interaction/ripple_patch.h"
#include "gfx/ui_overlay.h"
#include "objects.h"
#include "ocean/ocean_fft_cpu.h"
#include "ui_panels.h"
#include "water/composite_water.h"
#include "water_systems.h"

namespace ob::game {

namespace {

// Input phase: the platform's events into the InputState resource.
void inputSystem(ecs::World& world, const ecs::Tick&) {
    auto* res = world.resource<FrameResources>();
    auto* input = world.resource<platform::InputState>();
    if (!res || !res->platform || !input) return;
    res->platform->pollInput(*input);
    if (res->ui) res->ui->captureFlags(input->uiCapturesMouse, input->uiCapturesKeyboard);
}

// Render phase: the passes, then the UI, then present.
void renderSystem(ecs::World& world, const ecs::Tick& tick) {
    auto* res = world.resource<FrameResources>();
    if (!res || !res->renderer) return;
    glm::ivec2 size = res->platform->framebufferSize();
    if (size.x <= 0 || size.y <= 0) return;  // minimised
    res->renderer->def() = res->scene->render;
    gfx::CameraView camera = cameraView(world, size);
    if (const OceanState* ocean = world.resource<OceanState>(); ocean && ocean->water)
        camera.waterHeight = ocean->water->sample(camera.position.x, camera.position.z).height;
    res->renderer->render(camera, prepareWaterView(world, tick.time), objectDraws(world), tick.time, size);
    gfx::PassTimes passes = res->renderer->takePassTimes();
    double gpuMs = 0.0;
    for (const auto& [pass, ms] : passes) {
        res->timer->addGpuPass(pass, ms);
        gpuMs += ms;
    }
    if (!passes.empty()) res->timer->setGpu(ecs::Phase::Render, gpuMs);
    if (res->ui) {
        res->ui->begin();
        drawPanels(*res->scene, *res->timer);
        res->ui->end();
    }
}

// The frame's phase table: every system, in execution order within its phase.
struct SystemEntry {
    ecs::Phase phase;
    const char* name;
    ecs::SystemFn fn;
};
const SystemEntry SYSTEMS[] = {
    {ecs::Phase::Input, "input", inputSystem},
    {ecs::Phase::Script, "camera", cameraSystem},
    {ecs::Phase::Physics, "bodies", physicsSystem},
    {ecs::Phase::Interaction, "ripples", interactionSystem},
    {ecs::Phase::Ocean, "ocean", oceanSystem},
    {ecs::Phase::Render, "render", renderSystem},
};

} // namespace

Sandbox::Sandbox(const SceneDef& scene) : m_scene(scene), m_schedule(scene.sim) {
    for (const SystemEntry& s : SYSTEMS) m_schedule.add(s.phase, s.name, s.fn);
    m_world.setResource(std::make_unique<platform::InputState>());
    spawnCamera(m_world, m_scene.camera);
    addOcean(m_world, m_scene.ocean, m_scene.gerstner);
    addRipples(m_world, m_scene.ripples, float(m_schedule.stepSeconds()));
    spawnObjects(m_world, m_scene.physics, m_scene.objects);
}

Sandbox::~Sandbox() = default;

void Sandbox::attachPlatform(platform::Platform& platform, bool withUi) {
    m_renderer = std::make_unique<gfx::Renderer>(m_scene.render);
    attachWaterGpu(m_world);
    if (withUi && platform.nativeWindow()) m_ui = std::make_unique<gfx::UiOverlay>(platform.nativeWindow());
    m_world.setResource(std::make_unique<FrameResources>(
        FrameResources{&platform, m_renderer.get(), m_ui.get(), &m_schedule.timer(), &m_scene}));
}

bool Sandbox::quitRequested() {
    auto* input = m_world.resource<platform::InputState>();
    return input && input->quit;
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
    if (auto* patch = m_world.resource<interaction::RipplePatch>()) {
        auto now = patch->field().current(), before = patch->field().previous();
        h.f32s(now.data(), now.size());
        h.f32s(before.data(), before.size());
    }
    auto& motions = m_world.pool<ecs::Motion>();
    for (size_t i = 0; i < motions.size(); ++i) h.f32s(&motions.components()[i].velocity.x, 3);
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
