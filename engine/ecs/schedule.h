// The frame: a fixed phase table (input → script → physics → interaction → ocean → render).
// Input and render run once per frame; the simulation phases run at a fixed step.
#pragma once
#include "core/schema.h"
#include "ecs/world.h"

#include <array>
#include <map>
#include <string>
#include <chrono>
#include <cstdint>
#include <vector>

namespace ob {
class Clock;
}

namespace ob::ecs {

/// The fastest fixed simulation rate a scene may ask for (Hz): sim.step_hz's maximum.
constexpr double MAX_STEP_HZ = 1000.0;

/// Simulation timing, section [sim].
struct SimDef {
    float step_hz = 60.0f;          ///< fixed simulation rate (Hz), [1, 1000]
    int max_steps_per_frame = 8;    ///< catch-up limit when a frame is slow, [1, 64]
    uint64_t seed = 1;              ///< seed for every random choice of the scene
    float end_time = 0.0f;          ///< simulated seconds a run lasts, [0, 1e6] (0: none): `run` without --frames stops there; a
                                    ///< goal still running is lost; `play` stops stepping and shows the result
    bool pipelined = true;          ///< the ocean's maps of the next step and the ripples' coarse levels computed on worker
                                    ///< threads while the frame goes on (docs/frame.md#pipelined); the state is the same bits
};

template <class V> void describe(V& v, SimDef& d) {
    v.field("step_hz", d.step_hz, range(1, MAX_STEP_HZ), "fixed simulation rate (Hz)");
    v.field("max_steps_per_frame", d.max_steps_per_frame, range(1, 64), "catch-up limit when a frame is slow");
    v.field("seed", d.seed, "seed for every random choice of the scene");
    v.field("end_time", d.end_time, range(0, 1e6), "simulated seconds a run lasts; play then shows the result (0: none)");
    v.field("pipelined", d.pipelined,
            "the next step's ocean maps and the ripples' coarse levels on worker threads while the frame draws (same state bits)");
}

/// The phases of a frame, in execution order.
enum class Phase : uint8_t { Input, Script, Physics, Interaction, Ocean, Render, Count };
constexpr int PHASE_COUNT = int(Phase::Count);
/// Lower-case phase names ("input", "script", ...), as in stats and benchmarks.
const char* phaseName(Phase p);

/// Pause and single steps, a resource the input phase may set (window controls): while
/// paused, frames run input and render only, plus one step per request; once stopped (by a
/// system, checked before every step) no step runs again.
struct SimControl {
    bool paused = false;   ///< no simulation steps while true
    bool held = false;     ///< no steps either while a window holds the game (the scene picker is open)
    int stepRequests = 0;  ///< steps to run while paused (consumed by the schedule)
    bool stopped = false;  ///< the run is over (a goal's result, [sim] end_time): no more steps, not even asked for
};

/// What a system sees of time. For per-frame systems dt is the frame's clock time.
struct Tick {
    double time = 0;     ///< simulated seconds at the start of this step (per frame: now)
    double dt = 0;       ///< step length (s); per frame: the clock time since the last frame
    uint64_t step = 0;   ///< index of this simulation step (per frame: the next one)
    double clock = 0;    ///< the run's clock time this step or frame reaches: input stamped
                         ///< before it belongs to it (platform::InputQueue)
    double end = 0;      ///< simulated seconds at the end of this step (per frame: = time)
    double alpha = 1;    ///< per frame after the steps: the clock's fraction of a step past the step before
                         ///< the latest, [0, 1] (render interpolation); 1 while time stands still
};

/// A system: a free function over the world.
using SystemFn = void (*)(World&, const Tick&);

/// How often a system runs: once per frame, or once per fixed simulation step.
enum class Rate : uint8_t { Frame, Step };

/// One row of the phase table. A frame runs the per-frame rows before the first per-step
/// row, then the steps due (every per-step row, in order, each step), then the per-frame
/// rows after them; the phase names the row's timing bucket and must not decrease.
struct SystemEntry {
    Phase phase;
    Rate rate;
    const char* name;
    SystemFn fn;
};

/// Per-phase CPU (and GPU where measured) milliseconds, one sample per frame. A series
/// keeps its latest samples only, between MAX_SAMPLES and 2·MAX_SAMPLES of them once that
/// many frames ran, so a window left open for days holds a bounded amount of memory.
class FrameTimer {
public:
    /// Samples a series keeps at least (10 minutes at 60 fps) before its oldest are dropped.
    static constexpr size_t MAX_SAMPLES = 36000;

    void beginFrame();
    /// Adds a system's run to its phase: wall ms and the main thread's CPU ms.
    void addCpu(Phase p, double ms, double threadMs = 0.0) {
        m_current[size_t(p)] += ms;
        m_currentThread[size_t(p)] += threadMs;
    }
    /// GPU time of a phase for the latest frame whose queries have resolved.
    void setGpu(Phase p, double ms) { record(m_gpu[size_t(p)], ms); }
    /// GPU time of one render pass for the latest frame whose queries have resolved.
    void addGpuPass(const std::string& pass, double ms) { record(m_gpuPasses[pass], ms); }
    /// Closes the frame: its wall ms, the main thread's CPU ms over it and the simulation
    /// workers' (core/thread_cpu.h).
    void endFrame(double frameMs, double mainCpuMs = 0.0, double workerCpuMs = 0.0);
    /// Samples of the phase's CPU ms, one per frame.
    const std::vector<double>& cpuSamples(Phase p) const { return m_cpu[size_t(p)]; }
    /// Samples of the main thread's CPU ms in the phase's systems, one per frame (their wall
    /// time less what they waited or were preempted).
    const std::vector<double>& threadCpuSamples(Phase p) const { return m_threadCpu[size_t(p)]; }
    const std::vector<double>& gpuSamples(Phase p) const { return m_gpu[size_t(p)]; }
    const std::vector<double>& frameSamples() const { return m_frames; }
    /// Samples of the main thread's CPU ms per frame (frame start to the next frame's start).
    const std::vector<double>& mainCpuSamples() const { return m_mainCpu; }
    /// Samples of the simulation workers' CPU ms per frame, summed over them.
    const std::vector<double>& workerCpuSamples() const { return m_workerCpu; }
    /// Samples of each render pass's GPU ms, by pass name.
    const std::map<std::string, std::vector<double>>& gpuPassSamples() const { return m_gpuPasses; }
    /// The latest frame's CPU ms of a phase (0 before the first frame).
    double lastCpu(Phase p) const { return m_cpu[size_t(p)].empty() ? 0.0 : m_cpu[size_t(p)].back(); }

private:
    // Appends; at 2·MAX_SAMPLES drops the oldest MAX_SAMPLES (amortised O(1) per sample).
    static void record(std::vector<double>& series, double ms);

    std::array<double, PHASE_COUNT> m_current{}, m_currentThread{};
    std::array<std::vector<double>, PHASE_COUNT> m_cpu, m_threadCpu;
    std::array<std::vector<double>, PHASE_COUNT> m_gpu;
    std::vector<double> m_frames;
    std::vector<double> m_mainCpu, m_workerCpu;
    std::map<std::string, std::vector<double>> m_gpuPasses;
};

/// Mean and median of samples (0 when empty).
double mean(const std::vector<double>& samples);
double median(std::vector<double> samples);

/// The phase table and the fixed-step loop.
class Schedule {
public:
    explicit Schedule(const SimDef& def) : m_def(def) {}
    /// Appends a row to the phase table (see SystemEntry); throws std::logic_error if the
    /// table would break its order (a phase before the last one's, a per-frame row between
    /// per-step rows).
    void add(const SystemEntry& entry);
    /// Runs one frame at clock time `now` (s): input, the simulation steps due, render.
    void runFrame(World& world, double now);
    /// Closes the open frame's timing (runFrame does it for the previous frame; call it
    /// after the last frame's present).
    void finish();
    /// Runs only the simulation phases for one step (headless simulation without a frame);
    /// its input is what was stamped before the end of the step on the simulated clock.
    void runStep(World& world) { runStep(world, simTime() + stepSeconds()); }
    /// The first frame's clock interval (s; default one step): a run that advances K steps a
    /// frame starts with K.
    void setFirstFrameSeconds(double seconds) { m_firstFrameSeconds = seconds; }
    const FrameTimer& timer() const { return m_timer; }
    FrameTimer& timer() { return m_timer; }
    double simTime() const { return double(m_step) / m_def.step_hz; }
    uint64_t steps() const { return m_step; }
    uint64_t frames() const { return m_frames; }
    /// The latest frame's Tick::alpha: how far its clock is between the last two steps.
    double alpha() const { return m_alpha; }
    double stepSeconds() const { return 1.0 / m_def.step_hz; }

private:
    void run(World& world, const SystemEntry& entry, const Tick& tick);
    void runStep(World& world, double clock);

    SimDef m_def;
    std::vector<SystemEntry> m_systems;
    FrameTimer m_timer;
    uint64_t m_step = 0;
    uint64_t m_frames = 0;
    double m_lastNow = -1;
    std::chrono::steady_clock::time_point m_frameStart;
    double m_frameCpuStart = 0.0;     // the main thread's CPU clock at the frame's start, s
    double m_frameWorkerStart = 0.0;  // the workers' CPU clock then, s
    bool m_frameOpen = false;
    double m_accumulator = 0;
    double m_firstFrameSeconds = 0;  // 0: one step
    double m_alpha = 1;              // the latest frame's Tick::alpha
};

} // namespace ob::ecs
