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
#include "world/interpolation.h"
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

// Every body at the end (where it is, how it leans, how deep it floats), the cannons' shots and
// the schools' fish.
static void addObjectStats(nlohmann::json& j, ecs::World& world) {
    j["bodies"] = nlohmann::json::array();
    auto& bodies = world.pool<Body>();
    for (size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies.components()[i];
        const ecs::Entity e = bodies.entities()[i];
        const ecs::Transform& t = world.get<ecs::Transform>(e);
        const ObjectTag* tag = world.find<ObjectTag>(e);
        const glm::vec2 rollPitch = rollPitchDeg(t.rotation);
        j["bodies"].push_back({{"type", objectTypeName(world, e)},
                               {"name", tag ? tag->name : ""},
                               {"position", {t.position.x, t.position.y, t.position.z}},
                               {"roll_deg", rollPitch.x},
                               {"pitch_deg", rollPitch.y},
                               {"submerged_fraction", b.submergedFraction}});
    }
    j["cannons"] = nlohmann::json::array();
    auto& cannons = world.pool<Cannon>();
    for (size_t i = 0; i < cannons.size(); ++i) {
        const ObjectTag* tag = world.find<ObjectTag>(cannons.entities()[i]);
        j["cannons"].push_back({{"name", tag ? tag->name : ""}, {"shots", cannons.components()[i].shots}});
    }
    j["fish_schools"] = nlohmann::json::array();
    auto& schools = world.pool<FishSchool>();
    for (size_t i = 0; i < schools.size(); ++i) {
        const FishSchool& s = schools.components()[i];
        const ObjectTag* tag = world.find<ObjectTag>(schools.entities()[i]);
        size_t airborne = 0;
        for (const glm::vec3& p : s.position) airborne += p.y > 0.0f ? 1 : 0;
        j["fish_schools"].push_back({{"name", tag ? tag->name : ""}, {"fish", s.size()}, {"jumps", s.jumps},
                                     {"stamps", s.stamps}, {"airborne", airborne}});
    }
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
    addObjectStats(j, sandbox.world());
    if (const splash::SplashParticles* drops = splashParticles(sandbox.world()))
        j["splash"] = {{"emitted", drops->stats().emitted}, {"spray_emitted", drops->stats().spray}, {"landed", drops->stats().landed}};
    if (const auto* script = sandbox.world().resource<ScriptState>()) j["events_run"] = script->fired;
    // The camera as the last frame saw it (a test projects bodies into the screenshot with it).
    const gfx::CameraView view = cameraView(sandbox.world(), platform.framebufferSize(), drawnAlpha(sandbox.world()));
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

namespace {

// The scripted input of a run (--input): its events go through the same queue as the window's,
// and its [[set]] entries join the first world's timeline as `set` events.
struct ScriptedStart {
    SceneDef first;                            ///< the first world's scene: the run's, with the script's sets
    std::vector<platform::InputEvent> events;  ///< the script's events
    bool clockWaits = false;                   ///< the goal clock waits for the player (play; a recording of it too)
};

ScriptedStart scriptedStart(const SceneDef& scene, const RunOptions& options) {
    ScriptedStart start{scene, {}, options.overlay};
    if (options.input.empty()) return start;
    const InputScriptDef input = loadInputScript(options.input);
    start.clockWaits = start.clockWaits || input.goal_clock_waits;
    start.events = scriptEvents(input);
    for (size_t i = 0; i < input.set.size(); ++i) {
        const SetDef& set = input.set[i];
        if (const std::string problem = checkLiveSet(set.key, set.value); !problem.empty())
            throw InputError(options.input + ": set[" + std::to_string(i) + "]." + problem);
        EventDef e;
        e.at = set.at;
        e.action = EventAction::Set;
        e.key = set.key;
        e.value = set.value;
        start.first.events.push_back(e);
    }
    return start;
}

// Where a bounded headless run is: a line that rewrites itself on a terminal, else one line
// every 10 s.
class ProgressLine {
public:
    ProgressLine(const SceneDef& scene, const RunOptions& options, bool on)
        : m_on(on), m_terminal(isatty(STDERR_FILENO)),
          m_expected(options.frames > 0 ? options.frames
                                        : long(std::ceil(options.endTime * scene.sim.step_hz / options.stepsPerFrame - 1e-6))) {}
    /// After frame `f` (from 0); `last`: the run's last frame.
    void report(long f, bool last) {
        if (!m_on) return;
        const double percent = 100.0 * double(f + 1) / double(std::max(m_expected, 1L));
        if (m_terminal && (f % 10 == 0 || last))
            std::fprintf(stderr, "\roceanbox: frame %ld/%ld (%3.0f%%)%s", f + 1, m_expected, percent, last ? "\n" : "");
        if (!m_terminal && std::chrono::steady_clock::now() - m_last > std::chrono::seconds(10)) {
            m_last = std::chrono::steady_clock::now();
            std::fprintf(stderr, "oceanbox: frame %ld/%ld (%3.0f%%)\n", f + 1, m_expected, percent);
        }
    }

private:
    bool m_on;
    bool m_terminal;
    long m_expected;
    std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

// One run of a scene on one platform: the worlds it opens there (R, the scene picker and the
// UI's "restart with these settings" each open the next), their clock, and what it writes.
class SceneRun {
public:
    SceneRun(const SceneDef& scene, const std::string& scenePath, const RunOptions& options);
    /// The frames until the run ends; returns the process exit code.
    int run();

private:
    std::unique_ptr<Sandbox> makeSandbox(const SceneDef& s) const;
    std::unique_ptr<Clock> makeClock(const SceneDef& s) const;
    void opened(Sandbox& made, const SceneDef& s, const std::string& path) const;
    bool lastFrame(long f) const;
    void writeScreenshots(bool last);
    void restartIfAsked(double now);
    int finish();
    void writeRecording();

    const RunOptions& m_options;
    const std::string m_recordedPath;  // the file the recording replays
    std::vector<platform::InputEvent> m_scripted;
    bool m_clockWaits = false;
    std::unique_ptr<platform::Platform> m_platform;
    std::unique_ptr<Sandbox> m_sandbox;
    std::unique_ptr<Clock> m_clock;
    SceneDef m_started;         // what R restarts: the scene this world started from
    std::string m_runningPath;  // and the file it came from
    std::optional<InputScriptDef> m_recording;  // the first world's, once it restarted
    int m_restarts = 0;
    bool m_staysOpen = false;  // a window in real time stays open on the result panel; any other run ends with the goal
    bool m_bounded = false;    // the run ends after `frames` frames, or once the simulation reaches `endTime`
    bool m_slowReported = false;
};

SceneRun::SceneRun(const SceneDef& scene, const std::string& scenePath, const RunOptions& options)
    : m_options(options), m_recordedPath(scenePath), m_started(scene), m_runningPath(scenePath) {
    checkOutputs(scene, scenePath, options);
    ScriptedStart start = scriptedStart(scene, options);
    m_scripted = std::move(start.events);
    m_clockWaits = start.clockWaits;
    m_platform = openPlatform(scene, scenePath, options);
    m_staysOpen = options.realTime && !m_platform->headless();
    m_bounded = options.frames > 0 || options.endTime > 0.0;
    m_sandbox = makeSandbox(start.first);
    opened(*m_sandbox, start.first, scenePath);
    m_clock = makeClock(scene);
}

// A fixed clock advances stepsPerFrame steps a frame (what a slow machine does in play); the
// catch-up limit must let it.
std::unique_ptr<Sandbox> SceneRun::makeSandbox(const SceneDef& s) const {
    SceneDef withSteps = s;
    withSteps.sim.max_steps_per_frame = std::max(s.sim.max_steps_per_frame, m_options.stepsPerFrame);
    auto made = std::make_unique<Sandbox>(withSteps);
    made->attachPlatform(*m_platform, m_options.overlay);
    if (m_clockWaits) goalClockWaitsForPlayer(made->world());
    made->setScriptedInput(m_scripted);
    if (!m_options.record.empty()) made->world().setResource(std::make_unique<InputRecorder>());
    if (m_options.dynamicResolution) made->enableDynamicResolution();
    if (m_options.autoExposure) made->world().setResource(std::make_unique<AutoExposureByDefault>());
    if (!m_options.realTime) made->schedule().setFirstFrameSeconds(m_options.stepsPerFrame / double(s.sim.step_hz));
    return made;
}

std::unique_ptr<Clock> SceneRun::makeClock(const SceneDef& s) const {
    if (m_options.realTime) return std::make_unique<SteadyClock>();
    return std::make_unique<FixedStepClock>(m_options.stepsPerFrame / double(s.sim.step_hz),
                                            double(m_options.steps) / double(s.sim.step_hz));
}

// Each world opens on its card (the overlay's level, H's choice, carries over).
void SceneRun::opened(Sandbox& made, const SceneDef& s, const std::string& path) const {
    if (m_options.overlay) made.showStartCard(startCardText(s, path));
}

int SceneRun::run() {
    ProgressLine progress(m_started, m_options, m_bounded && m_platform->headless());
    for (long f = 0; m_bounded || !m_sandbox->quitRequested(); ++f) {
        const double now = m_clock->now();
        m_sandbox->frame(now);
        reportSlowFrame(m_sandbox->schedule().timer(), m_slowReported);
        // The wall clock starts once the first frame is drawn (shaders compiled, maps made):
        // the simulation does not make up for the loading time with a burst of steps.
        if (m_options.realTime && m_sandbox->schedule().frames() == 1) m_clock = makeClock(m_sandbox->scene());
        if (m_sandbox->quitRequested()) break;
        const bool last = lastFrame(f);
        writeScreenshots(last);
        progress.report(f, last);
        if (last) break;
        restartIfAsked(now);
    }
    return finish();
}

bool SceneRun::lastFrame(long f) const {
    return (m_options.frames > 0 && f + 1 >= m_options.frames) ||
           (m_options.endTime > 0.0 && m_sandbox->schedule().simTime() >= m_options.endTime - 1e-9) ||
           (!m_staysOpen && m_sandbox->over());
}

// Read back before present: the window's back buffer is undefined after a swap. The frame is
// presented by the next one's render phase, after that frame's steps.
void SceneRun::writeScreenshots(bool last) {
    for (const std::string& file : m_sandbox->takeScreenshotRequests()) {
        gfx::writeScreenshot(file, m_platform->framebufferSize());
        logInfo("screenshot written to %s", file.c_str());
    }
    if (last && !m_options.screenshot.empty()) gfx::writeScreenshot(m_options.screenshot, m_platform->framebufferSize());
}

// A new world on the same window: the UI's "restart with these settings", the scene picker's
// file, or R (the scene again, as this world started).
void SceneRun::restartIfAsked(double now) {
    std::optional<SceneDef> next = m_sandbox->takeRestartRequest();
    const bool edited = next.has_value();
    const std::string picked = m_sandbox->takeSceneSwitch();
    const bool again = m_sandbox->takeRestartKey();
    if (!next && again) next = m_started;
    if (!next) return;
    if (!picked.empty()) logInfo("opening %s", picked.c_str());
    else logInfo("%s", edited ? "restarting the scene with the edited settings" : "restarting the scene");
    m_sandbox->present();
    // Another scene starts from its own [camera]; this one keeps the player's view (in the
    // edited mode, if they edited it).
    const std::optional<CameraPose> pose = picked.empty() ? m_sandbox->cameraPose() : std::nullopt;
    const bool cameraEdited = !sameCamera(m_sandbox->scene().camera, next->camera);
    m_scripted = m_sandbox->remainingScriptedInput(now);
    const OverlayLevel level = overlayLevel(*m_sandbox);
    // A recording replays one world: the first, up to its restart.
    if (!m_options.record.empty() && !m_recording) m_recording = recordingOf(*m_sandbox, *m_platform, m_clockWaits);
    ++m_restarts;
    m_sandbox.reset();
    m_sandbox = makeSandbox(*next);
    if (auto* controls = m_sandbox->world().resource<WindowControls>()) controls->overlay = level;
    if (!picked.empty()) m_platform->setTitle("oceanbox — " + picked);
    opened(*m_sandbox, *next, picked.empty() ? m_runningPath : picked);
    if (pose) m_sandbox->setCameraPose(*pose, !cameraEdited);
    m_clock = makeClock(*next);
    m_started = *next;
    if (!picked.empty()) m_runningPath = picked;
}

// The last frame shown, its timing closed; the stats, the recording; GL errors fail the run.
int SceneRun::finish() {
    m_sandbox->present();
    m_sandbox->schedule().finish();
    reportSlowFrame(m_sandbox->schedule().timer(), m_slowReported);
    if (!m_bounded && !m_options.screenshot.empty())
        logWarn("--screenshot needs --frames N (or [sim] end_time); no screenshot written");
    if (!m_options.stats.empty()) writeStats(m_options.stats, *m_sandbox, m_runningPath, *m_platform);
    if (!m_options.record.empty()) writeRecording();
    if (!m_options.screenshot.empty() && m_bounded) logInfo("screenshot written to %s", m_options.screenshot.c_str());
    if (gfx::glErrorCount() > 0) {
        logWarn("%d GL error(s) were reported during the run", gfx::glErrorCount());
        return EXIT_FAILURE_RUNTIME;
    }
    return EXIT_OK;
}

void SceneRun::writeRecording() {
    if (!m_recording) m_recording = recordingOf(*m_sandbox, *m_platform, m_clockWaits);
    writeTextFile(m_options.record,
                  "# oceanbox input recorded from " + m_recordedPath + ": `oceanbox run SCENE --input FILE` replays it\n" +
                      writeToml(*m_recording),
                  "recording");
    logInfo("input recorded to %s (%llu steps)", m_options.record.c_str(), static_cast<unsigned long long>(m_recording->steps));
    if (m_restarts > 0)
        logWarn("the recording holds the first world, up to its restart at step %llu; the %d restart(s) after it are not recorded",
                static_cast<unsigned long long>(m_recording->steps), m_restarts);
}

} // namespace

int runScene(const SceneDef& scene, const std::string& scenePath, const RunOptions& options) {
    return SceneRun(scene, scenePath, options).run();
}

} // namespace ob::game
