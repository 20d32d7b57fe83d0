// GPU timer queries in a ring.
#include "gfx/gpu_timer.h"

#include <string>

namespace ob::gfx {

GpuTimer::GpuTimer(const char* label) {
    for (int i = 0; i < LATENCY; ++i) {
        GLuint id;
        glCreateQueries(GL_TIME_ELAPSED, 1, &id);
        glObjectLabel(GL_QUERY, id, -1, (std::string(label) + "[" + std::to_string(i) + "]").c_str());
        m_queries[size_t(i)] = Query(id);
    }
}

void GpuTimer::begin() {
    // The slot about to be reused: drop its old result if it never resolved.
    m_pending[size_t(m_next)] = false;
    glBeginQuery(GL_TIME_ELAPSED, m_queries[size_t(m_next)].id());
}

void GpuTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    m_pending[size_t(m_next)] = true;
    m_next = (m_next + 1) % LATENCY;
}

double GpuTimer::takeResultMs() {
    double result = -1.0;
    // Oldest first: the slot after the newest.
    for (int i = 0; i < LATENCY; ++i) {
        int slot = (m_next + i) % LATENCY;
        if (!m_pending[size_t(slot)]) continue;
        GLint available = 0;
        glGetQueryObjectiv(m_queries[size_t(slot)].id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) break;
        GLuint64 ns = 0;
        glGetQueryObjectui64v(m_queries[size_t(slot)].id(), GL_QUERY_RESULT, &ns);
        m_pending[size_t(slot)] = false;
        // The first query of a context can report an absolute timestamp on llvmpipe: skip it.
        if (m_resolved++ > 0) result = double(ns) * 1e-6;
    }
    return result;
}

} // namespace ob::gfx
