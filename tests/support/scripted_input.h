// Driving a sandbox as a window does, for the tests: input events pushed in simulated time,
// frames run to a time, and the pixel a world point is drawn at in a 640 × 360 view.
#pragma once
#include "platform/input.h"
#include "world/camera.h"
#include "world/sandbox.h"

#include <glm/glm.hpp>

namespace ob::test {

constexpr double DT = 1.0 / 60.0;
inline const glm::ivec2 SIZE{640, 360};

inline void push(game::Sandbox& sandbox, platform::InputEvent e) { sandbox.world().resource<platform::InputQueue>()->push(e); }

/// A pointer event at pixel `pos` (the left button's).
inline platform::InputEvent at(platform::InputEvent::Type type, double time, glm::vec2 pos, platform::Key key = platform::Key::W) {
    platform::InputEvent e{type, time, key, platform::MouseButton::Left};
    e.hasPos = true;
    e.pos = pos;
    return e;
}

/// Runs frames (one step each) up to time `until`.
inline void runTo(game::Sandbox& sandbox, double until) {
    for (double t = sandbox.schedule().simTime() + DT; t <= until + 1e-9; t += DT) sandbox.frame(t);
}

inline gfx::CameraView view(game::Sandbox& sandbox) { return game::cameraView(sandbox.world(), SIZE); }

/// The pixel a world point is drawn at.
inline glm::vec2 pixelOf(game::Sandbox& sandbox, glm::vec3 p) {
    const gfx::CameraView v = view(sandbox);
    const glm::vec4 clip = v.projection * v.view * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(SIZE.x), (1.0f - ndc.y) * 0.5f * float(SIZE.y)};
}

} // namespace ob::test
