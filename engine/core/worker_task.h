// One piece of a step run on a worker thread while the main thread goes on ([sim] pipelined):
// whatever reads or writes its results next joins it first. Joining is cheap when nothing runs
// (one atomic load) and safe from any thread (queries may come from several at once).
#pragma once
#include "core/thread_cpu.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <mutex>
#include <utility>

namespace ob {

class WorkerTask {
public:
    WorkerTask() = default;
    ~WorkerTask() { join(); }
    WorkerTask(const WorkerTask&) = delete;
    WorkerTask& operator=(const WorkerTask&) = delete;

    /// Joins the task before, then runs `work` on a thread of its own (bench frame's workers row
    /// counts its CPU). What `work` touches must stay untouched by others until join().
    template <class F>
    void start(F&& work) {
        join();
        m_task = std::async(std::launch::async, [work = std::forward<F>(work)]() mutable {
            const WorkerCpuScope cpu;
            work();
        });
        m_busy.store(true, std::memory_order_release);
        ++m_started;
    }

    /// Waits for the task started last, if it has not been waited for (rethrows what it threw).
    /// Inline only the check: queries call it per point.
    void join() const {
        if (m_busy.load(std::memory_order_acquire)) wait();
    }

    /// Whether a task was started and has not finished yet.
    bool running() const {
        return m_busy.load(std::memory_order_acquire) && m_task.wait_for(std::chrono::seconds(0)) != std::future_status::ready;
    }

    /// Tasks started so far.
    uint64_t started() const { return m_started; }

private:
    void wait() const;  // out of line (worker_task.cpp): the callers' hot loops stay small

    uint64_t m_started = 0;
    mutable std::future<void> m_task;
    mutable std::atomic<bool> m_busy{false};  // m_task not yet waited for
    mutable std::mutex m_join;                // one waiter at a time
};

} // namespace ob
