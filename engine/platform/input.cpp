// Input events, per-consumer state and the two-consumer queue.
#include "platform/input.h"

#include <algorithm>

namespace ob::platform {

void InputState::beginConsume() {
    presses.fill(0);
    clicks.fill(0);
    mouseDelta = glm::vec2(0.0f);
    scroll = 0.0f;
}

void InputState::apply(const InputEvent& e) {
    using T = InputEvent::Type;
    if (e.hasPos) {
        cursor = e.pos;
        cursorKnown = true;
    }
    switch (e.type) {
    case T::KeyDown:
        if (!down[size_t(e.key)] && presses[size_t(e.key)] < 255) ++presses[size_t(e.key)];
        down[size_t(e.key)] = true;
        if (e.key == Key::Escape) quit = true;
        break;
    case T::KeyUp: down[size_t(e.key)] = false; break;
    case T::ButtonDown:
        if (!buttonDown[size_t(e.button)] && clicks[size_t(e.button)] < 255) ++clicks[size_t(e.button)];
        buttonDown[size_t(e.button)] = true;
        break;
    case T::ButtonUp: buttonDown[size_t(e.button)] = false; break;
    case T::Move: mouseDelta += e.value; break;
    case T::Scroll: scroll += e.value.y; break;
    case T::Close: quit = true; break;
    }
}

void InputQueue::push(InputEvent e) {
    e.time = std::max(e.time, m_last);
    m_last = e.time;
    m_frame.push_back(e);
    m_step.push_back(e);
}

void InputQueue::drain(std::deque<InputEvent>& q, double until, InputState& state, std::vector<InputEvent>* consumed) {
    while (!q.empty() && q.front().time <= until) {
        state.apply(q.front());
        if (consumed) consumed->push_back(q.front());
        q.pop_front();
    }
}

} // namespace ob::platform
