// Persistent worker pool behind parallelFor. Workers sleep on a condition variable and claim
// chunks by compare-exchange on one word (generation | chunk count | next chunk), so a worker
// that wakes late never claims a chunk of another job; the caller claims chunks too.
#include "core/parallel.h"

#include "core/thread_cpu.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace ob {

namespace {

thread_local bool t_insideBody = false;

constexpr uint64_t MAX_CHUNKS = 0xFFFF;

constexpr uint64_t packWord(uint64_t gen, uint64_t chunks, uint64_t next) {
    return (gen << 32) | (chunks << 16) | next;
}

int defaultWorkers() {
    unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(std::min<unsigned>(hw, MAX_CHUNKS));
}

class Pool {
public:
    ~Pool() { stopThreads(); }

    void setWorkers(int n) {
        std::lock_guard lock(m_dispatch);
        stopThreads();
        m_workers = n <= 0 ? defaultWorkers() : int(std::min<uint64_t>(uint64_t(n), MAX_CHUNKS));
    }

    int workers() const { return m_workers; }

    void run(int begin, int end, int minChunk, RangeFn fn, void* ctx) {
        const int64_t range = int64_t(end) - begin;
        if (range <= 0) return;
        std::unique_lock dispatch(m_dispatch, std::defer_lock);
        const int64_t chunks = std::min<int64_t>(m_workers, range / std::max(minChunk, 1));
        if (chunks <= 1 || t_insideBody || !dispatch.try_lock()) {
            fn(ctx, begin, end);
            return;
        }
        if (int(m_threads.size()) != m_workers - 1) startThreads();

        // --- publish the job, wake the workers
        m_fn = fn;
        m_ctx = ctx;
        m_begin = begin;
        m_range = range;
        m_error = nullptr;
        m_pending.store(int(chunks), std::memory_order_relaxed);
        {
            std::lock_guard lock(m_mutex);
            const uint64_t gen = ((m_word.load(std::memory_order_relaxed) >> 32) + 1) & 0xFFFFFFFFu;
            m_word.store(packWord(gen, uint64_t(chunks), 0), std::memory_order_release);
            ++m_jobSeq;
        }
        m_wakeCv.notify_all();

        // --- take part, then wait for the chunks other workers claimed
        claimChunks(m_word.load(std::memory_order_acquire));
        for (int spin = 0; spin < 4096 && m_pending.load(std::memory_order_acquire) != 0; ++spin)
            std::this_thread::yield();
        if (m_pending.load(std::memory_order_acquire) != 0) {
            std::unique_lock lock(m_mutex);
            m_doneCv.wait(lock, [this] { return m_pending.load(std::memory_order_acquire) == 0; });
        }
        if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
    }

private:
    // Claims and runs chunks of the job published in word w until none is left.
    void claimChunks(uint64_t w) {
        for (;;) {
            const uint64_t next = w & 0xFFFF, chunks = (w >> 16) & 0xFFFF;
            if (next >= chunks) return;
            if (!m_word.compare_exchange_weak(w, w + 1, std::memory_order_acq_rel, std::memory_order_acquire))
                continue;
            // The claimed chunk keeps m_pending > 0, so the job fields stay valid until it is done.
            const int b = int(m_begin + m_range * int64_t(next) / int64_t(chunks));
            const int e = int(m_begin + m_range * int64_t(next + 1) / int64_t(chunks));
            t_insideBody = true;
            try {
                m_fn(m_ctx, b, e);
            } catch (...) {
                std::lock_guard lock(m_errorMutex);
                if (!m_error) m_error = std::current_exception();
            }
            t_insideBody = false;
            if (m_pending.fetch_sub(1, std::memory_order_acq_rel) == 1) {
                // Taking the mutex orders this wake-up after the caller's predicate check.
                std::lock_guard lock(m_mutex);
                m_doneCv.notify_one();
            }
            w = m_word.load(std::memory_order_acquire);
        }
    }

    void workerLoop() {
        uint64_t seen = 0;
        for (;;) {
            {
                std::unique_lock lock(m_mutex);
                m_wakeCv.wait(lock, [&] { return m_stop || m_jobSeq != seen; });
                if (m_stop) return;
                seen = m_jobSeq;
            }
            const WorkerCpuScope cpu;  // bench frame's workers row
            claimChunks(m_word.load(std::memory_order_acquire));
        }
    }

    void startThreads() {
        stopThreads();
        {
            std::lock_guard lock(m_mutex);
            m_stop = false;
        }
        for (int i = 1; i < m_workers; ++i) m_threads.emplace_back([this] { workerLoop(); });
    }

    void stopThreads() {
        if (m_threads.empty()) return;
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wakeCv.notify_all();
        for (auto& t : m_threads) t.join();
        m_threads.clear();
    }

    std::mutex m_dispatch;  // one job at a time; held by the dispatching caller
    std::vector<std::thread> m_threads;
    int m_workers = defaultWorkers();
    std::atomic<uint64_t> m_word{0};  // generation(32) | chunk count(16) | next chunk(16)
    std::atomic<int> m_pending{0};    // chunks of the current job not yet finished
    std::mutex m_mutex;               // guards m_jobSeq and m_stop; pairs with both condvars
    std::condition_variable m_wakeCv, m_doneCv;
    uint64_t m_jobSeq = 0;
    bool m_stop = false;
    RangeFn m_fn = nullptr;
    void* m_ctx = nullptr;
    int64_t m_begin = 0, m_range = 0;
    std::mutex m_errorMutex;
    std::exception_ptr m_error;
};

Pool& pool() {
    static Pool s_pool;
    return s_pool;
}

} // namespace

namespace detail {
void parallelForRaw(int begin, int end, int minChunk, RangeFn fn, void* ctx) {
    pool().run(begin, end, minChunk, fn, ctx);
}
} // namespace detail

void setWorkerCount(int n) { pool().setWorkers(n); }

int workerCount() { return pool().workers(); }

} // namespace ob
