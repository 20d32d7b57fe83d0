// The sandbox: one scene's world, its phase table and, when attached, the view (platform,
// renderer and UI: view/sandbox_view.*) that draws it and brings the player's input in.
#pragma once
#include "ecs/schedule.h"
#include "ecs/world.h"
#include "world/camera.h"
#include "platform/input.h"
#include "world/scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ob::platform {
class Platform;
}

namespace ob::game {

/// What draws the world and brings the player's input in (view/sandbox_view.cpp: the
/// platform, the renderer and the UI overlay). A resource of the world; a pure simulation has
/// none, and then the two phase-table rows that call it do nothing.
class View {
public:
    virtual ~View() = default;
    /// Input phase, first: the platform's events into the input queue.
    virtual void pollInput(ecs::World& world, const ecs::Tick& tick) = 0;
    /// Render phase, last: presents the previous frame, then this frame's passes and UI, handed
    /// to the GL (flushed) but not presented: a software rasteriser draws it while the next
    /// frame's steps run on the main thread.
    virtual void render(ecs::World& world, const ecs::Tick& tick) = 0;
    /// Presents the latest rendered frame if it is not shown yet.
    virtual void present() = 0;
};

/// Where the camera is and how the player has steered it (kept across a restart).
struct CameraPose {
    CameraRig rig;
    ecs::Transform transform;
};

class Sandbox {
public:
    /// Builds the world from the scene (entities, resources) and the phase table.
    explicit Sandbox(const SceneDef& scene);
    ~Sandbox();
    /// Adds the view: rendering (and the UI overlay when `withUi`) on the current GL context,
    /// and the GPU twins the scene asks for. (Defined in view/, the library that links GL.)
    void attachPlatform(platform::Platform& platform, bool withUi);
    /// One frame at clock time `now` (s): input, the steps due, render.
    void frame(double now) { m_schedule.runFrame(m_world, now); }
    /// Shows the latest frame. A frame's render shows the frame before it, so a loop of frames
    /// calls this only at its end (or before reading back a frame after its swap).
    void present();
    /// One simulation step without input or render.
    void step() { m_schedule.runStep(m_world); }
    /// Hash of the simulation state (bit-exact: equal hashes mean equal states): the step,
    /// every transform and velocity, both ripple levels and every ocean map.
    uint64_t stateHash();
    /// Every timing the sandbox measures, as (name, median ms per frame) over the frames
    /// after the first `skipFrames`: "frame" (wall, frame start to frame start), then each
    /// phase's CPU time ("input", "script", ...), then each GPU-timed span ("gpu.render", ...).
    /// Empty before the first finished frame.
    std::vector<std::pair<std::string, double>> timings(size_t skipFrames = 0) const;
    bool quitRequested();
    /// The scene the UI asked to restart with (validated), once.
    std::optional<SceneDef> takeRestartRequest() { return std::exchange(m_restart, std::nullopt); }
    /// Whether R asked for the scene again (as this world started), once.
    bool takeRestartKey();
    /// The scene file the picker chose ("" = none; its scene is the restart request), once.
    std::string takeSceneSwitch();
    /// The scripted input events not yet queued, their times made relative to the clock time
    /// `now` (a new world's clock starts at 0: the script goes on where it was).
    std::vector<platform::InputEvent> remainingScriptedInput(double now);
    /// The goal is decided (or [sim] end_time reached): no more steps run.
    bool over();
    /// Opens the world on the start card (`text`, and the keys that matter here) until the
    /// first input. (Defined in view/.)
    void showStartCard(const std::string& text);
    /// The internal scale follows the frame time to hold [render] target_fps (play; a `run`
    /// only when asked, so its frames stay reproducible). (Defined in view/.)
    void enableDynamicResolution();
    /// Input events (clock time order) fed to the input queue as the clock reaches them.
    void setScriptedInput(std::vector<platform::InputEvent> events);
    /// The camera's pose (none without a camera).
    std::optional<CameraPose> cameraPose();
    /// Puts the camera where `pose` says; `keepMode`: its mode and settings too (else this
    /// scene's [camera] keeps them).
    void setCameraPose(const CameraPose& pose, bool keepMode);
    /// PNG files the timeline asked for since the last call (write them after the frame).
    std::vector<std::string> takeScreenshotRequests();

    ecs::World& world() { return m_world; }
    ecs::Schedule& schedule() { return m_schedule; }
    /// The scene as the world runs it (live changes included): world/scene_settings.h.
    const SceneDef& scene();

private:
    ecs::World m_world;
    ecs::Schedule m_schedule;
    std::optional<SceneDef> m_restart;
};

} // namespace ob::game
