// GPU time of a span of GL commands (GL_TIME_ELAPSED queries, read a few frames late so
// the CPU never waits for the GPU).
#pragma once
#include "gfx/handles.h"

#include <array>

namespace ob::gfx {

/// One timed span per frame; results arrive up to LATENCY frames later.
class GpuTimer {
public:
    explicit GpuTimer(const char* label);
    void begin();
    void end();
    /// The newest resolved measurement (ms), or a negative value when none is ready yet.
    double takeResultMs();

private:
    static constexpr int LATENCY = 4;
    std::array<Query, LATENCY> m_queries;
    std::array<bool, LATENCY> m_pending{};
    int m_next = 0;
    long m_resolved = 0;
};

} // namespace ob::gfx
