// The run loop: platform, sandbox, clock, progress line, screenshot and stats.
#include "tools/app.h"
#include "world/live_keys.h"
#include "platform/platform.h"

#include "core/clock.h"
#include "core/error.h"
#include "core/file_identity.h"
#include "core/file_write.h"
#include "core/log.h"
#include "core/toml_writer.h"
#include "gfx/gl.h"
#include "gfx/renderer.h"
#include "view_data/scene_view.h"
#include "ecs/components.h"
#include "behaviours/cannon.h"
#include "behaviours/spawning.h"
#include "behaviours/fish.h"
#include "goals/goals.h"
#include "world/controls.h"
#include "world/input_script.h"
#include "sim/objects.h"
#include "view/sandbox_view.h"
#include "sim/splash_foam_system.h"
#include "splash/splash_particles.h"
#include "ui/hud.h"
#include "world/sandbox.h"
#include "world/scene_budget.h"
#include "world/script.h"
#include "world/tools.h"
#include "world/camera.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace ob::game {

// The input the world's steps consumed, as a script that replays them (`play --record`).
static InputScriptDef recordingOf(Sandbox& sandbox, const platform::Platform& platform, bool clockWaits) {
    const auto* recorder = sandbox.world().resource<InputRecorder>();
    const auto* viewport = sandbox.world().resource<Viewport>();
    const auto* script = sandbox.world().resource<ScriptState>();
    InputScriptDef recording = recordedScript(recorder ? recorder->events : std::vector<platform::InputEvent>{},
                                              script ? script->liveChanges : std::vector<LiveChange>{}, sandbox.schedule().steps(),
                                              sandbox.schedule().stepSeconds(), viewport ? viewport->size : platform.framebufferSize());
    recording.goal_clock_waits = clockWaits;
    return recording;
}

// The overlay's level in a world (H's choice).
static OverlayLevel overlayLevel(Sandbox& sandbox) {
    const auto* controls = sandbox.world().resource<WindowControls>();
    return controls ? controls->overlay : OverlayLevel::Folded;
}

// Whether two [camera] sections say the same (compared as the TOML they write).
static bool sameCamera(const CameraDef& a, const CameraDef& b) {
    SceneDef x, y;
    x.camera = a;
    y.camera = b;
    return writeToml(x) == writeToml(y);
}

static nlohmann::json phaseStats(const std::vector<double>& samples) {
    return {{"mean_ms", ecs::mean(samples)}, {"median_ms", ecs::median(samples)}};
}

// The goal's result and what the mode counts (docs/games.md).
static nlohmann::json gameStats(const GameState& game) {
    nlohmann::json j = {{"mode", enumName(game.def.mode)}, {"result", enumName(game.result)},
                        {"score", game.goal ? game.goal->score() : 0}, {"time_s", game.time},
                        {"time_limit_s", game.def.time_limit}, {"reason", game.reason}};
    if (game.goal) game.goal->addStats(j);
    return j;
}

static void writeStats(const std::string& path, Sandbox& sandbox, const std::string& scenePath,
                       const platform::Platform& platform) {
    const ecs::FrameTimer& timer = sandbox.schedule().timer();
    nlohmann::json j;
    j["scene"] = scenePath;
    j["platform"] = platform.name();
    j["renderer"] = gfx::glRendererName();
    j["frames"] = sandbox.schedule().frames();
    j["steps"] = sandbox.schedule().steps();
    j["simulated_seconds"] = sandbox.schedule().simTime();
    j["frame"] = phaseStats(timer.frameSamples());
    double medianFrame = ecs::median(timer.frameSamples());
    j["fps"] = medianFrame > 0 ? 1000.0 / medianFrame : 0.0;
    // Dynamic resolution (play): the internal scale it holds at the end.
    if (const auto* dynamic = sandbox.world().resource<DynamicScale>(); dynamic && dynamic->control)
        j["resolution_scale"] = dynamic->control->scale();
    for (int p = 0; p < ecs::PHASE_COUNT; ++p) {
        auto phase = ecs::Phase(p);
        j["phases"][ecs::phaseName(phase)] = phaseStats(timer.cpuSamples(phase));
        if (!timer.gpuSamples(phase).empty()) j["gpu_phases"][ecs::phaseName(phase)] = phaseStats(timer.gpuSamples(phase));
    }
    for (const auto& [pass, samples] : timer.gpuPassSamples()) j["gpu_passes"][pass] = phaseStats(samples);
    j["entities"] = {{"total", sandbox.world().entityCount()},
                     {"cameras", sandbox.world().pool<CameraRig>().size()},
                     {"bodies", sandbox.world().pool<Body>().size()}};
    // Every body at the end: where it is, how it leans, how deep it floats.
    j["bodies"] = nlohmann::json::array();
    auto& bodies = sandbox.world().pool<Body>();
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies.components()[i];
        const ecs::Entity e = bodies.entities()[i];
        const ecs::Transform& t = sandbox.world().get<ecs::Transform>(e);
        const ObjectTag* tag = sandbox.world().find<ObjectTag>(e);
        const glm::vec2 rollPitch = rollPitchDeg(t.rotation);
        j["bodies"].push_back({{"type", objectTypeName(sandbox.world(), e)},
                               {"name", tag ? tag->name : ""},
                               {"position", {t.position.x, t.position.y, t.position.z}},
                               {"roll_deg", rollPitch.x},
                               {"pitch_deg", rollPitch.y},
                               {"submerged_fraction", b.submergedFraction}});
    }
    j["cannons"] = nlohmann::json::array();
    auto& cannons = sandbox.world().pool<Cannon>();
    for (size_t i = 0; i < cannons.size(); ++i) {
        const ObjectTag* tag = sandbox.world().find<ObjectTag>(cannons.entities()[i]);
        j["cannons"].push_back({{"name", tag ? tag->name : ""}, {"shots", cannons.components()[i].shots}});
    }
    j["fish_schools"] = nlohmann::json::array();
    auto& schools = sandbox.world().pool<FishSchool>();
    for (size_t i = 0; i < schools.size(); ++i) {
        const FishSchool& s = schools.components()[i];
        const ObjectTag* tag = sandbox.world().find<ObjectTag>(schools.entities()[i]);
        size_t airborne = 0;
        for (const glm::vec3& p : s.position) airborne += p.y > 0.0f ? 1 : 0;
        j["fish_schools"].push_back({{"name", tag ? tag->name : ""}, {"fish", s.size()}, {"jumps", s.jumps},
                                     {"stamps", s.stamps}, {"airborne", airborne}});
    }
    if (const splash::SplashParticles* drops = splashParticles(sandbox.world()))
        j["splash"] = {{"emitted", drops->stats().emitted}, {"spray_emitted", drops->stats().spray}, {"landed", drops->stats().landed}};
    if (const auto* script = sandbox.world().resource<ScriptState>()) j["events_run"] = script->fired;
    // The camera as the last frame saw it (a test projects bodies into the screenshot with it).
    const gfx::CameraView view = cameraView(sandbox.world(), platform.framebufferSize());
    const glm::mat4 clip = view.projection * view.view;
    j["camera"] = {{"position", {view.position.x, view.position.y, view.position.z}}, {"mode", cameraMode(sandbox.world())},
                   {"view_projection", std::vector<float>(&clip[0][0], &clip[0][0] + 16)}};  // column-major
    if (const auto* tools = sandbox.world().resource<PlayerTools>())
        j["tools"] = {{"tool", enumName(tools->def.tool)}, {"message", tools->message}};
    if (const GameState* game = gameState(sandbox.world())) j["game"] = gameStats(*game);
    char hash[32];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(sandbox.stateHash()));
    j["state_hash"] = hash;

    writeTextFile(path, j.dump(2) + "\n", "stats");
}

// Every file the run will write can be written, and none is one of its inputs or another
// output (before any work is done).
static void checkOutputs(const SceneDef& scene, const std::string& scenePath, const RunOptions& options) {
    if (!options.screenshot.empty()) checkWritable(options.screenshot, "screenshot");
    if (!options.stats.empty()) checkWritable(options.stats, "stats");
    if (!options.record.empty()) checkWritable(options.record, "recording");
    for (const EventDef& e : scene.events)
        if (e.action == EventAction::Screenshot) checkWritable(e.file, "event screenshot");
    std::vector<NamedPath> inputs = sceneInputs(scene, scenePath);
    inputs.push_back({"--input", options.input});
    std::vector<NamedPath> outputs{{"--screenshot", options.screenshot}, {"--stats", options.stats}, {"--record", options.record}};
    for (const NamedPath& o : sceneOutputs(scene)) outputs.push_back(o);
    checkOutputsApart(inputs, outputs);
}

// Says once why a frame took over SLOW_FRAME_MS (world/scene_budget.h).
static void reportSlowFrame(const ecs::FrameTimer& timer, bool& reported) {
    if (reported) return;
    const std::string note = slowFrameNote(timer, SLOW_FRAME_MS);
    if (note.empty()) return;
    reported = true;
    logWarn("%s", note.c_str());
}

// A window where one is asked for and a display exists, else a headless context.
static std::unique_ptr<platform::Platform> openPlatform(const SceneDef& scene, const std::string& scenePath, const RunOptions& options) {
    const glm::ivec2 size = options.size.x > 0 ? options.size : glm::ivec2(scene.window.width, scene.window.height);
    std::unique_ptr<platform::Platform> platform;
    if (options.window && platform::displayAvailable()) {
        platform::WindowDef window = scene.window;
        window.width = size.x;
        window.height = size.y;
        platform = platform::createWindowPlatform(window, "oceanbox — " + scenePath);
    } else {
        if (options.window) logInfo("%s", options.fallbackNote.c_str());
        platform = platform::createHeadlessPlatform(size);
    }
    logInfo("%s: %s", platform->name(), gfx::glRendererName());
    return platform;
}

int runScene(const SceneDef& scene, const std::string& scenePath, const RunOptions& options) {
    checkOutputs(scene, scenePath, options);
    // Scripted input goes through the same queue as the window's events.
    // A script's [[set]] entries join the first world's timeline as `set` events.
    std::vector<platform::InputEvent> scripted;
    SceneDef first = scene;
    bool clockWaits = options.overlay;  // play's goal clock waits for the player; a recording of it too
    if (!options.input.empty()) {
        const InputScriptDef input = loadInputScript(options.input);
        clockWaits = clockWaits || input.goal_clock_waits;
        scripted = scriptEvents(input);
        for (size_t i = 0; i < input.set.size(); ++i) {
            const SetDef& set = input.set[i];
            if (const std::string problem = checkLiveSet(set.key, set.value); !problem.empty())
                throw InputError(options.input + ": set[" + std::to_string(i) + "]." + problem);
            EventDef e;
            e.at = set.at;
            e.action = EventAction::Set;
            e.key = set.key;
            e.value = set.value;
            first.events.push_back(e);
        }
    }
    std::unique_ptr<platform::Platform> platform = openPlatform(scene, scenePath, options);

    // A fixed clock advances stepsPerFrame steps a frame (what a slow machine does in play);
    // the catch-up limit must let it.
    auto withSteps = [&](SceneDef s) {
        s.sim.max_steps_per_frame = std::max(s.sim.max_steps_per_frame, options.stepsPerFrame);
        return s;
    };
    auto makeSandbox = [&](const SceneDef& s) {
        auto made = std::make_unique<Sandbox>(withSteps(s));
        made->attachPlatform(*platform, options.overlay);
        if (clockWaits) goalClockWaitsForPlayer(made->world());
        made->setScriptedInput(scripted);
        if (!options.record.empty()) made->world().setResource(std::make_unique<InputRecorder>());
        if (options.dynamicResolution) made->enableDynamicResolution();
        if (options.autoExposure) made->world().setResource(std::make_unique<AutoExposureByDefault>());
        if (!options.realTime) made->schedule().setFirstFrameSeconds(options.stepsPerFrame / double(s.sim.step_hz));
        return made;
    };
    auto makeClock = [&](const SceneDef& s) -> std::unique_ptr<Clock> {
        if (options.realTime) return std::make_unique<SteadyClock>();
        return std::make_unique<FixedStepClock>(options.stepsPerFrame / double(s.sim.step_hz), double(options.steps) / double(s.sim.step_hz));
    };
    // The overlay's level (H) carries over to the next world; each world opens on its card.
    const auto opened = [&](Sandbox& made, const SceneDef& s, const std::string& path) {
        if (options.overlay) made.showStartCard(startCardText(s, path));
    };
    auto sandbox = makeSandbox(first);
    opened(*sandbox, first, scenePath);
    std::unique_ptr<Clock> clock = makeClock(scene);
    // What R restarts (the scene this world started from) and the file it came from.
    SceneDef started = scene;
    std::string runningPath = scenePath;
    const std::string recordedPath = scenePath;
    std::optional<InputScriptDef> recording;  // the first world's, once it restarted
    int restarts = 0;
    // A window in real time stays open on the result panel; any other run ends with the goal.
    const bool staysOpen = options.realTime && !platform->headless();

    // The run ends after `frames` frames, or once the simulation reaches `endTime`.
    const bool bounded = options.frames > 0 || options.endTime > 0.0;
    // Where a headless run is: a line that rewrites itself on a terminal, else one line every 10 s.
    const bool progress = bounded && platform->headless();
    const bool terminal = isatty(STDERR_FILENO);
    auto lastProgress = std::chrono::steady_clock::now();
    const long expected = options.frames > 0 ? options.frames
                                             : long(std::ceil(options.endTime * scene.sim.step_hz / options.stepsPerFrame - 1e-6));
    bool slowReported = false;
    for (long f = 0; bounded || !sandbox->quitRequested(); ++f) {
        const double now = clock->now();
        sandbox->frame(now);
        reportSlowFrame(sandbox->schedule().timer(), slowReported);
        // The wall clock starts once the first frame is drawn (shaders compiled, maps made):
        // the simulation does not make up for the loading time with a burst of steps.
        if (options.realTime && sandbox->schedule().frames() == 1) clock = makeClock(sandbox->scene());
        if (sandbox->quitRequested()) break;
        const bool last = (options.frames > 0 && f + 1 >= options.frames) ||
                          (options.endTime > 0.0 && sandbox->schedule().simTime() >= options.endTime - 1e-9) ||
                          (!staysOpen && sandbox->over());
        // Read back before present: the window's back buffer is undefined after a swap. The
        // frame is presented by the next one's render phase, after that frame's steps.
        for (const std::string& file : sandbox->takeScreenshotRequests()) {
            gfx::writeScreenshot(file, platform->framebufferSize());
            logInfo("screenshot written to %s", file.c_str());
        }
        if (last && !options.screenshot.empty()) gfx::writeScreenshot(options.screenshot, platform->framebufferSize());
        if (progress && terminal && (f % 10 == 0 || last))
            std::fprintf(stderr, "\roceanbox: frame %ld/%ld (%3.0f%%)%s", f + 1, expected,
                         100.0 * double(f + 1) / double(std::max(expected, 1L)), last ? "\n" : "");
        if (progress && !terminal && std::chrono::steady_clock::now() - lastProgress > std::chrono::seconds(10)) {
            lastProgress = std::chrono::steady_clock::now();
            std::fprintf(stderr, "oceanbox: frame %ld/%ld (%3.0f%%)\n", f + 1, expected,
                         100.0 * double(f + 1) / double(std::max(expected, 1L)));
        }
        if (last) break;
        // A new world on the same window: the UI's "restart with these settings", the scene
        // picker's file, or R (the scene again, as this world started).
        std::optional<SceneDef> next = sandbox->takeRestartRequest();
        const bool edited = next.has_value();
        const std::string picked = sandbox->takeSceneSwitch();
        const bool again = sandbox->takeRestartKey();
        if (!next && again) next = started;
        if (next) {
            if (!picked.empty()) logInfo("opening %s", picked.c_str());
            else logInfo("%s", edited ? "restarting the scene with the edited settings" : "restarting the scene");
            sandbox->present();
            // Another scene starts from its own [camera]; this one keeps the player's view (in the
            // edited mode, if they edited it).
            const std::optional<CameraPose> pose = picked.empty() ? sandbox->cameraPose() : std::nullopt;
            const bool cameraEdited = !sameCamera(sandbox->scene().camera, next->camera);
            scripted = sandbox->remainingScriptedInput(now);
            const OverlayLevel level = overlayLevel(*sandbox);
            // A recording replays one world: the first, up to its restart.
            if (!options.record.empty() && !recording) recording = recordingOf(*sandbox, *platform, clockWaits);
            ++restarts;
            sandbox.reset();
            sandbox = makeSandbox(*next);
            if (auto* controls = sandbox->world().resource<WindowControls>()) controls->overlay = level;
            if (!picked.empty()) platform->setTitle("oceanbox — " + picked);
            opened(*sandbox, *next, picked.empty() ? runningPath : picked);
            if (pose) sandbox->setCameraPose(*pose, !cameraEdited);
            clock = makeClock(*next);
            started = *next;
            if (!picked.empty()) runningPath = picked;
        }
    }
    sandbox->present();
    sandbox->schedule().finish();
    reportSlowFrame(sandbox->schedule().timer(), slowReported);
    if (!bounded && !options.screenshot.empty())
        logWarn("--screenshot needs --frames N (or [sim] end_time); no screenshot written");

    if (!options.stats.empty()) writeStats(options.stats, *sandbox, runningPath, *platform);
    if (!options.record.empty()) {
        if (!recording) recording = recordingOf(*sandbox, *platform, clockWaits);
        writeTextFile(options.record,
                      "# oceanbox input recorded from " + recordedPath + ": `oceanbox run SCENE --input FILE` replays it\n" +
                          writeToml(*recording),
                      "recording");
        logInfo("input recorded to %s (%llu steps)", options.record.c_str(), static_cast<unsigned long long>(recording->steps));
        if (restarts > 0)
            logWarn("the recording holds the first world, up to its restart at step %llu; the %d restart(s) after it are not recorded",
                    static_cast<unsigned long long>(recording->steps), restarts);
    }
    if (!options.screenshot.empty() && bounded) logInfo("screenshot written to %s", options.screenshot.c_str());
    if (gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

} // namespace ob::game
