// Fixed-step frame loop and per-phase timing.
#include "ecs/schedule.h"

#include "core/thread_cpu.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <string>

namespace ob::ecs {

const char* phaseName(Phase p) {
    static const char* NAMES[PHASE_COUNT] = {"input", "script", "physics", "interaction", "ocean", "render"};
    return NAMES[size_t(p)];
}

void FrameTimer::beginFrame() {
    m_current.fill(0.0);
    m_currentThread.fill(0.0);
}

void FrameTimer::record(std::vector<double>& series, double ms) {
    if (series.size() >= 2 * MAX_SAMPLES) series.erase(series.begin(), series.begin() + long(MAX_SAMPLES));
    series.push_back(ms);
}

void FrameTimer::endFrame(double frameMs, double mainCpuMs, double workerCpuMs) {
    for (int p = 0; p < PHASE_COUNT; ++p) {
        record(m_cpu[size_t(p)], m_current[size_t(p)]);
        record(m_threadCpu[size_t(p)], m_currentThread[size_t(p)]);
    }
    record(m_frames, frameMs);
    record(m_mainCpu, mainCpuMs);
    record(m_workerCpu, workerCpuMs);
}

double mean(const std::vector<double>& samples) {
    return samples.empty() ? 0.0 : std::accumulate(samples.begin(), samples.end(), 0.0) / double(samples.size());
}

double median(std::vector<double> samples) {
    if (samples.empty()) return 0.0;
    size_t mid = samples.size() / 2;
    std::nth_element(samples.begin(), samples.begin() + long(mid), samples.end());
    double hi = samples[mid];
    if (samples.size() % 2) return hi;
    double lo = *std::max_element(samples.begin(), samples.begin() + long(mid));
    return 0.5 * (lo + hi);
}

using Ms = std::chrono::duration<double, std::milli>;

void Schedule::add(const SystemEntry& entry) {
    const bool stepsBefore = std::any_of(m_systems.begin(), m_systems.end(), [](const SystemEntry& e) { return e.rate == Rate::Step; });
    const bool afterSteps = !m_systems.empty() && m_systems.back().rate == Rate::Frame && stepsBefore;
    if ((!m_systems.empty() && entry.phase < m_systems.back().phase) || (entry.rate == Rate::Step && afterSteps))
        throw std::logic_error(std::string("phase table: '") + entry.name + "' is out of order");
    m_systems.push_back(entry);
}

void Schedule::run(World& world, const SystemEntry& entry, const Tick& tick) {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuSeconds();
    entry.fn(world, tick);
    m_timer.addCpu(entry.phase, Ms(std::chrono::steady_clock::now() - t0).count(), 1e3 * (threadCpuSeconds() - cpu0));
}

void Schedule::runStep(World& world, double clock) {
    const Tick tick{simTime(), stepSeconds(), m_step, clock, simTime() + stepSeconds()};
    for (const SystemEntry& e : m_systems)
        if (e.rate == Rate::Step) run(world, e, tick);
    ++m_step;
}

void Schedule::runFrame(World& world, double now) {
    // A frame's wall time runs from its start to the next frame's start, so it includes
    // presenting (vsync, the software rasteriser finishing) outside the phases.
    finish();
    m_frameStart = std::chrono::steady_clock::now();
    m_frameCpuStart = threadCpuSeconds();
    m_frameWorkerStart = workerCpuSeconds();
    m_frameOpen = true;
    m_timer.beginFrame();
    const double h = stepSeconds();
    const double frameDt = m_lastNow < 0 ? (m_firstFrameSeconds > 0 ? m_firstFrameSeconds : h) : now - m_lastNow;
    const double before = now - frameDt;
    m_lastNow = now;

    // --- the per-frame rows before the steps (input)
    const auto firstStep = std::find_if(m_systems.begin(), m_systems.end(), [](const SystemEntry& e) { return e.rate == Rate::Step; });
    const Tick frameTick{simTime(), frameDt, m_step, now, simTime()};
    for (auto e = m_systems.begin(); e != firstStep; ++e) run(world, *e, frameTick);

    // --- simulation: the fixed steps due by now, at most max_steps_per_frame (the rest is
    // dropped). Step j of n reaches the clock at before + (j+1)/n of the frame, so the
    // input of the frame is spread over its steps in the order it came.
    SimControl* control = world.resource<SimControl>();
    const auto stopped = [control] { return control && control->stopped; };
    // While time stands still the frame draws the latest step (alpha 1): the camera moves over it.
    m_alpha = 1.0;
    if (stopped()) {
        // Over: time stands still for good (a step of the frame may have stopped it).
        m_accumulator = 0;
        if (control) control->stepRequests = 0;
    } else if (control && (control->paused || control->held)) {
        // Paused: time stands still; each request runs exactly one step.
        m_accumulator = 0;
        for (; control->stepRequests > 0 && !stopped(); --control->stepRequests) runStep(world, now);
    } else {
        m_accumulator += frameDt;
        int due = 0;
        for (double a = m_accumulator; a >= h * (1.0 - 1e-9) && due < m_def.max_steps_per_frame; a -= h) ++due;
        for (int j = 0; j < due && !stopped(); ++j) {
            runStep(world, j + 1 == due ? now : before + frameDt * double(j + 1) / double(due));
            m_accumulator -= h;
        }
        if (due == m_def.max_steps_per_frame && m_accumulator > h) m_accumulator = 0;
        // The clock is this far past the step before the latest: the render's interpolation
        // weight (a step of the frame may have stopped time: then the latest).
        if (!stopped()) m_alpha = std::clamp(m_accumulator / h, 0.0, 1.0);
    }

    // --- the per-frame rows after the steps (render), at the latest simulated state
    const Tick renderTick{simTime(), frameDt, m_step, now, simTime(), m_alpha};
    for (auto e = firstStep; e != m_systems.end(); ++e)
        if (e->rate == Rate::Frame) run(world, *e, renderTick);
    ++m_frames;
}

void Schedule::finish() {
    if (!m_frameOpen) return;
    m_timer.endFrame(Ms(std::chrono::steady_clock::now() - m_frameStart).count(), 1e3 * (threadCpuSeconds() - m_frameCpuStart),
                     1e3 * (workerCpuSeconds() - m_frameWorkerStart));
    m_frameOpen = false;
}

} // namespace ob::ecs
