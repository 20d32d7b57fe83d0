// The input queue: events in order, each consumer (frame, step) sees each edge once, an
// event belongs to the step whose clock interval holds it, a tap inside one step counts.
#include "ecs/schedule.h"
#include "ecs/world.h"
#include "platform/input.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>
#include <vector>

using namespace ob;
using platform::InputEvent;
using platform::Key;
using T = InputEvent::Type;

TEST_CASE("a tap inside one step is one press for that step and for the frame, and no held key", "[input]") {
    platform::InputQueue queue;
    queue.push({T::KeyDown, 0.100, Key::Space});
    queue.push({T::KeyUp, 0.105, Key::Space});
    platform::InputState frame, step;
    // Steps of 1/60 s: the tap falls in the one ending at 7/60 = 0.1167 s.
    for (int j = 0; j < 10; ++j) {
        step.beginConsume();
        queue.drainStep((j + 1) / 60.0, step);
        INFO("step " << j);
        CHECK(step.pressCount(Key::Space) == (j == 6 ? 1 : 0));
        CHECK_FALSE(step.isDown(Key::Space));
    }
    frame.beginConsume();
    queue.drainFrame(10 / 60.0, frame);
    CHECK(frame.pressCount(Key::Space) == 1);
    CHECK(queue.empty());
}

TEST_CASE("a held key is down for the steps between its press and release, wherever frames fall", "[input]") {
    // Held from 0.5 s to 1.5 s: 60 steps of 1/60 s see it down, whether the steps are run
    // one by one or in groups (the steps' clock ends are the same).
    platform::InputQueue queue;
    queue.push({T::KeyDown, 0.5, Key::W});
    queue.push({T::KeyUp, 1.5, Key::W});
    platform::InputState step;
    int held = 0, presses = 0;
    for (int j = 0; j < 180; ++j) {
        step.beginConsume();
        queue.drainStep((j + 1) / 60.0, step);
        held += step.isDown(Key::W);
        presses += step.pressCount(Key::W);
    }
    CHECK(held == 60);
    CHECK(presses == 1);
}

TEST_CASE("events keep their order, one stamped before the last is raised to it", "[input]") {
    platform::InputQueue queue;
    queue.push({T::KeyDown, 1.0, Key::P});
    queue.push({T::KeyUp, 0.5, Key::P});  // out of order: raised to 1.0, still after the press
    platform::InputState frame;
    queue.drainFrame(0.9, frame);
    CHECK(frame.pressCount(Key::P) == 0);
    queue.drainFrame(1.0, frame);
    CHECK(frame.pressCount(Key::P) == 1);
    CHECK_FALSE(frame.isDown(Key::P));
}

TEST_CASE("mouse: clicks, motion and wheel add up until consumed, Escape and Close quit", "[input]") {
    platform::InputState s;
    s.apply({T::ButtonDown, 0, Key::W, platform::MouseButton::Right});
    s.apply({T::Move, 0, Key::W, platform::MouseButton::Left, {3.0f, -2.0f}});
    s.apply({T::Move, 0, Key::W, platform::MouseButton::Left, {1.0f, 1.0f}});
    s.apply({T::Scroll, 0, Key::W, platform::MouseButton::Left, {0.0f, 2.0f}});
    CHECK(s.wasClicked(platform::MouseButton::Right));
    CHECK(s.isDown(platform::MouseButton::Right));
    CHECK(s.mouseDelta == glm::vec2(4.0f, -1.0f));
    CHECK(s.scroll == 2.0f);
    s.beginConsume();
    CHECK_FALSE(s.wasClicked(platform::MouseButton::Right));
    CHECK(s.isDown(platform::MouseButton::Right));
    CHECK(s.mouseDelta == glm::vec2(0.0f));
    CHECK_FALSE(s.quit);
    s.apply({T::KeyDown, 0, Key::Escape});
    CHECK(s.quit);
    platform::InputState closed;
    closed.apply({T::Close});
    CHECK(closed.quit);
}

namespace {
struct StepClocks {
    std::vector<double> clocks;
};
void recordClock(ecs::World& world, const ecs::Tick& tick) { world.resource<StepClocks>()->clocks.push_back(tick.clock); }
} // namespace

TEST_CASE("the schedule spreads a frame's clock over its steps: step j of n ends at j+1/n of the frame", "[input]") {
    // K steps a frame on a fixed clock that starts one frame in (FixedStepClock): the steps'
    // clock ends are those of one step a frame, (j + 1)/60 s.
    for (int k : {1, 3, 8}) {
        ecs::SimDef def;
        def.max_steps_per_frame = 8;
        ecs::Schedule schedule(def);
        ecs::World world;
        world.setResource(std::make_unique<StepClocks>());
        schedule.add({ecs::Phase::Script, ecs::Rate::Step, "clock", recordClock});
        schedule.setFirstFrameSeconds(k / 60.0);
        for (int f = 0; f < 24 / k; ++f) schedule.runFrame(world, (f + 1) * (k / 60.0));
        const auto& clocks = world.resource<StepClocks>()->clocks;
        INFO("steps per frame " << k);
        REQUIRE(clocks.size() == 24);
        for (size_t j = 0; j < clocks.size(); ++j) CHECK(clocks[j] == Approx((double(j) + 1.0) / 60.0).margin(1e-9));
    }
}

namespace {
struct RunOrder {
    std::vector<std::string> rows;
};
template <char Name> void recordRow(ecs::World& world, const ecs::Tick& tick) {
    world.resource<RunOrder>()->rows.push_back(std::string(1, Name) + (tick.end > tick.time ? "+" : "="));
}
} // namespace

TEST_CASE("the phase table's rates: per-frame rows around the steps, every per-step row each step, rows kept in order",
          "[input]") {
    ecs::SimDef def;
    def.max_steps_per_frame = 8;
    ecs::Schedule schedule(def);
    ecs::World world;
    world.setResource(std::make_unique<RunOrder>());
    schedule.add({ecs::Phase::Input, ecs::Rate::Frame, "a", recordRow<'a'>});
    schedule.add({ecs::Phase::Script, ecs::Rate::Step, "b", recordRow<'b'>});
    schedule.add({ecs::Phase::Ocean, ecs::Rate::Step, "c", recordRow<'c'>});
    schedule.add({ecs::Phase::Render, ecs::Rate::Frame, "d", recordRow<'d'>});
    schedule.setFirstFrameSeconds(2.0 / 60.0);
    schedule.runFrame(world, 2.0 / 60.0);  // two steps due
    // A step's tick ends one step after it starts; a frame's does not advance.
    CHECK(world.resource<RunOrder>()->rows == std::vector<std::string>{"a=", "b+", "c+", "b+", "c+", "d="});
    // A phase before the last row's, or a per-step row after the per-frame rows that follow
    // the steps, is refused.
    CHECK_THROWS_AS(schedule.add({ecs::Phase::Physics, ecs::Rate::Frame, "e", recordRow<'e'>}), std::logic_error);
    CHECK_THROWS_AS(schedule.add({ecs::Phase::Render, ecs::Rate::Step, "f", recordRow<'f'>}), std::logic_error);
}
