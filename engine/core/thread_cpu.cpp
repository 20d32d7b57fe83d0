// Thread CPU clocks and the workers' sum.
#include "core/thread_cpu.h"

#include <atomic>
#include <ctime>

namespace ob {

namespace {

// The workers' CPU time, ns: one counter for the process, as the pool is one.
std::atomic<int64_t>& workerNanos() {
    static std::atomic<int64_t> s_nanos{0};
    return s_nanos;
}

} // namespace

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double workerCpuSeconds() { return 1e-9 * double(workerNanos().load(std::memory_order_relaxed)); }

void addWorkerCpu(double seconds) { workerNanos().fetch_add(int64_t(seconds * 1e9), std::memory_order_relaxed); }

} // namespace ob
