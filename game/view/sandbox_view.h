// The sandbox's view: the platform's input, the renderer and the UI overlay over a world
// (Sandbox::attachPlatform makes it). The one part of the gameplay that needs a GL context.
#pragma once
#include "gfx/dynamic_resolution.h"
#include "world/sandbox.h"
#include "world/scene_settings.h"

#include <memory>
#include <optional>

namespace ob::gfx {
class Renderer;
class UiOverlay;
}

namespace ob::game {

/// Dynamic resolution, when on (a resource): the controller, made at the first frame and
/// again when [render] target_fps changes.
struct DynamicScale {
    std::optional<gfx::DynamicResolution> control;
};

/// Present (a resource) where render.auto_exposure = "auto" means on: `play` in a window.
struct AutoExposureByDefault {};

class SandboxView final : public View {
public:
    /// Draws `world` (its scene: world/scene_settings.h); `restart` is where the UI puts a
    /// scene to rebuild the world from. The UI overlay only when `withUi` and there is a window.
    SandboxView(platform::Platform& platform, bool withUi, ecs::World& world, ecs::FrameTimer& timer,
                std::optional<SceneDef>& restart);
    ~SandboxView() override;
    void pollInput(ecs::World& world, const ecs::Tick& tick) override;
    void render(ecs::World& world, const ecs::Tick& tick) override;
    void present() override;

private:
    platform::Platform& m_platform;
    ecs::FrameTimer& m_timer;
    std::optional<SceneDef>& m_restart;
    std::unique_ptr<gfx::Renderer> m_renderer;
    std::unique_ptr<gfx::UiOverlay> m_ui;
    bool m_presentPending = false;  // a frame is drawn and not yet presented
    SectionSeen m_renderSeen;       // the [render] version the renderer has
    SectionSeen m_skySeen;          // the [sky] version the renderer has
};

} // namespace ob::game
