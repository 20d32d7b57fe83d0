// The sandbox's view: input from the platform, the frame to the renderer, the UI panels.
#include "view/sandbox_view.h"
#include "platform/platform.h"

#include "behaviours/fish.h"
#include "world/tools.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "gfx/ui_overlay.h"
#include "sim/objects.h"
#include "sim/splash_foam_system.h"
#include "sim/water_systems.h"
#include "splash/splash_particles.h"
#include "ui/hud.h"
#include "ui/ui_panels.h"
#include "world/controls.h"
#include "world/interpolation.h"
#include "view/goal_looks.h"
#include "view/water_view.h"
#include "water/composite_water.h"

#include <cmath>
#include <vector>

namespace ob::game {

SandboxView::SandboxView(platform::Platform& platform, bool withUi, ecs::World& world, ecs::FrameTimer& timer,
                         std::optional<SceneDef>& restart)
    : m_platform(platform), m_timer(timer), m_restart(restart),
      m_renderer(std::make_unique<gfx::Renderer>(sceneSettings(world).def.render)),
      m_renderSeen{sceneSettings(world).version(SceneSection::Render)},
      m_skySeen{sceneSettings(world).version(SceneSection::Sky)} {
    m_renderer->sky() = sceneSettings(world).def.sky;
    if (withUi) m_ui = std::make_unique<gfx::UiOverlay>(platform.nativeWindow());  // headless: drawn, no input
}

SandboxView::~SandboxView() = default;

// Input phase, first: the platform's events into the input queue, stamped with the clock
// time the frame started at (they came since then), so this frame's first step sees them.
// Presses, clicks, wheel and motion the UI takes are not the game's.
void SandboxView::pollInput(ecs::World& world, const ecs::Tick& tick) {
    auto* input = world.resource<platform::InputState>();
    auto* queue = world.resource<platform::InputQueue>();
    if (!input || !queue) return;
    if (m_ui) m_ui->captureFlags(input->uiCapturesMouse, input->uiCapturesKeyboard);
    // The tools' rays are cast in the framebuffer the player sees.
    if (auto* viewport = world.resource<Viewport>(); viewport && m_platform.framebufferSize().x > 0)
        viewport->size = m_platform.framebufferSize();
    std::vector<platform::InputEvent> events;
    m_platform.pollEvents(events);
    using T = platform::InputEvent::Type;
    for (platform::InputEvent& e : events) {
        if (input->uiCapturesKeyboard && e.type == T::KeyDown) continue;
        if (input->uiCapturesMouse && (e.type == T::ButtonDown || e.type == T::Move || e.type == T::Scroll)) continue;
        e.time = tick.clock - tick.dt;
        queue->push(e);
    }
}

void SandboxView::present() {
    if (!m_presentPending) return;
    m_platform.present();
    m_presentPending = false;
}

// Render phase: the previous frame presented (its rasterisation overlapped this frame's steps),
// then the passes and the UI, flushed so the rasteriser starts on them.
void SandboxView::render(ecs::World& world, const ecs::Tick& tick) {
    present();
    glm::ivec2 size = m_platform.framebufferSize();
    if (size.x <= 0 || size.y <= 0) return;  // minimised
    SceneSettings& settings = sceneSettings(world);
    const gfx::RenderDef& render = settings.def.render;
    // The renderer keeps its [render]: it gets the section again when a live change moved it.
    if (m_renderSeen.moved(settings, SceneSection::Render)) m_renderer->def() = render;
    if (m_skySeen.moved(settings, SceneSection::Sky)) m_renderer->sky() = settings.def.sky;
    m_renderer->setAutoExposureDefault(world.resource<AutoExposureByDefault>() != nullptr);
    // Dynamic resolution: the last frame's time sets this frame's internal scale.
    if (auto* dynamic = world.resource<DynamicScale>(); dynamic && render.target_fps > 0.0f) {
        auto& control = dynamic->control;
        if (!control || std::abs(control->targetSeconds() * render.target_fps - 1.0) > 1e-6)
            control.emplace(render.target_fps, render.resolution_scale);
        else if (!m_timer.frameSamples().empty())
            control->update(m_timer.frameSamples().back() / 1000.0);
        m_renderer->def().resolution_scale = control->scale();
    }
    const float alpha = drawnAlpha(world);  // bodies and camera between the last two steps; the water etc. at the latest
    gfx::CameraView camera = cameraView(world, size, alpha);
    if (const OceanState* ocean = world.resource<OceanState>(); ocean && ocean->water) {
        const water::WaterSample s = ocean->water->sample(camera.position.x, camera.position.z);
        camera.waterHeight = s.height;
        camera.waterSlope = -glm::vec2(s.normal.x, s.normal.z) / s.normal.y;
    }
    std::vector<gfx::ObjectDraw> draws = objectDraws(world, highlightedBody(world), alpha, goalRestyle(world));
    appendFishDraws(world, draws);
    appendToolDraws(world, draws, camera.position);
    if (const OceanState* ocean = world.resource<OceanState>(); ocean && ocean->water)
        for (gfx::ObjectDraw& d : draws) {
            const water::WaterSample s = ocean->water->sample(d.model[3].x, d.model[3].z);
            d.waterHeight = s.height;
            d.waterSlope = -glm::vec2(s.normal.x, s.normal.z) / s.normal.y;
        }
    std::vector<gfx::SplashDrop> drops;
    if (const splash::SplashParticles* particles = splashParticles(world); particles && render.splash_drops) {
        drops.resize(size_t(particles->size()));
        for (size_t i = 0; i < drops.size(); ++i)
            drops[i] = gfx::SplashDrop(particles->x()[i], particles->y()[i], particles->z()[i], particles->radius()[i]);
    }
    m_renderer->render(camera, prepareWaterView(world, tick.time), draws, tick.time, size, drops);
    gfx::PassTimes passes = m_renderer->takePassTimes();
    double gpuMs = 0.0;
    for (const auto& [pass, ms] : passes) {
        m_timer.addGpuPass(pass, ms);
        gpuMs += ms;
    }
    if (!passes.empty()) m_timer.setGpu(ecs::Phase::Render, gpuMs);
    if (m_ui) {
        m_ui->begin(size, overlayScale(settings.def.window, size, m_platform.contentScale()));
        std::optional<float> dynamicScale;
        if (const auto* dynamic = world.resource<DynamicScale>(); dynamic && dynamic->control && render.target_fps > 0.0f)
            dynamicScale = dynamic->control->scale();
        drawPanels(world, settings, m_timer, dynamicScale, m_restart, tick.clock);
        m_ui->end();
    }
    glFlush();
    m_presentPending = true;
}


void Sandbox::attachPlatform(platform::Platform& platform, bool withUi) {
    m_world.setResource(std::unique_ptr<View>(new SandboxView(platform, withUi, m_world, m_schedule.timer(), m_restart)));
    attachWaterGpu(m_world);
}

void Sandbox::showStartCard(const std::string& text) {
    auto* controls = m_world.resource<WindowControls>();
    if (!controls) return;
    controls->card = true;
    controls->cardText = text;
    controls->cardKeys = startCardKeys(m_world);
}

void Sandbox::enableDynamicResolution() { m_world.setResource(std::make_unique<DynamicScale>()); }

} // namespace ob::game
