// The frame timer keeps a bounded number of samples per series: a window left open for
// hours does not grow without end, and the latest samples are always there.
#include "core/thread_cpu.h"
#include "ecs/schedule.h"
#include "ecs/world.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

using ob::ecs::FrameTimer;
using ob::ecs::Phase;

TEST_CASE("FrameTimer keeps between MAX_SAMPLES and 2 MAX_SAMPLES of the latest samples per series", "[timer]") {
    FrameTimer timer;
    const size_t frames = 5 * FrameTimer::MAX_SAMPLES + 123;
    for (size_t f = 0; f < frames; ++f) {
        timer.beginFrame();
        timer.addCpu(Phase::Ocean, double(f));
        timer.setGpu(Phase::Render, double(f));
        timer.addGpuPass("water", double(f));
        timer.endFrame(double(f));
    }
    for (const std::vector<double>* series : {&timer.frameSamples(), &timer.cpuSamples(Phase::Ocean), &timer.gpuSamples(Phase::Render),
                                              &timer.gpuPassSamples().at("water")}) {
        CHECK(series->size() >= FrameTimer::MAX_SAMPLES);
        CHECK(series->size() < 2 * FrameTimer::MAX_SAMPLES);
        CHECK(series->back() == double(frames - 1));  // the newest sample, in order
        CHECK(series->front() == double(frames - series->size()));
    }
    CHECK(timer.lastCpu(Phase::Ocean) == double(frames - 1));
}

namespace {
// 2 ms of this thread's CPU time, however long the machine takes to give it.
void spinTwoMs(ob::ecs::World&, const ob::ecs::Tick&) {
    const double end = ob::threadCpuSeconds() + 2e-3;
    while (ob::threadCpuSeconds() < end) {
    }
}
// 5 ms of waiting: wall time, next to no CPU.
void sleepFiveMs(ob::ecs::World&, const ob::ecs::Tick&) { std::this_thread::sleep_for(std::chrono::milliseconds(5)); }
} // namespace

TEST_CASE("a phase's main-thread CPU counts the work its systems did, not their waiting, and the phases fit in main_cpu",
          "[timer]") {
    ob::ecs::SimDef def;
    ob::ecs::Schedule schedule(def);
    ob::ecs::World world;
    schedule.add({Phase::Physics, ob::ecs::Rate::Step, "spin", spinTwoMs});
    schedule.add({Phase::Interaction, ob::ecs::Rate::Step, "sleep", sleepFiveMs});
    for (int f = 0; f < 6; ++f) schedule.runFrame(world, (f + 1) / 60.0);
    schedule.finish();
    const FrameTimer& t = schedule.timer();
    REQUIRE(t.mainCpuSamples().size() == 6);
    for (size_t f = 0; f < 6; ++f) {
        INFO("frame " << f);
        const double spin = t.threadCpuSamples(Phase::Physics)[f], sleep = t.threadCpuSamples(Phase::Interaction)[f];
        CHECK(spin >= 2.0);
        CHECK(spin <= t.cpuSamples(Phase::Physics)[f] + 0.05);  // CPU time never exceeds the wall time it ran in
        CHECK(t.cpuSamples(Phase::Interaction)[f] >= 5.0);
        CHECK(sleep < 1.0);  // waiting is not work
        double phases = 0.0;
        for (int p = 0; p < ob::ecs::PHASE_COUNT; ++p) phases += t.threadCpuSamples(Phase(p))[f];
        CHECK(phases <= t.mainCpuSamples()[f] + 0.05);
    }
}
