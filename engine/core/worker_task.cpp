// WorkerTask's wait, out of line.
#include "core/worker_task.h"

namespace ob {

void WorkerTask::wait() const {
    std::lock_guard lock(m_join);
    if (m_task.valid()) m_task.get();
    m_busy.store(false, std::memory_order_release);
}

} // namespace ob
