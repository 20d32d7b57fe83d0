// The frame timer keeps a bounded number of samples per series: a window left open for
// hours does not grow without end, and the latest samples are always there.
#include "ecs/schedule.h"

#include <catch2/catch.hpp>

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
