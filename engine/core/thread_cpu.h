// CPU time of threads, for the frame's budget (bench frame's main_cpu and workers rows): the
// calling thread's own, and what the simulation's workers (the parallelFor pool, the pipelined
// steps) spent, summed over them.
#pragma once
#include <cstdint>

namespace ob {

/// The calling thread's CPU time so far, s (CLOCK_THREAD_CPUTIME_ID: running, not waiting).
double threadCpuSeconds();

/// The CPU time the simulation's worker threads spent in their work so far, s (the pool's
/// workers in their chunks, the calling thread's share excluded; the pipelined steps' threads).
double workerCpuSeconds();

/// Adds `seconds` of a worker thread's CPU time to workerCpuSeconds (a worker outside the pool).
void addWorkerCpu(double seconds);

/// Adds the thread CPU time from construction to destruction to workerCpuSeconds: one per
/// task a simulation worker runs.
class WorkerCpuScope {
public:
    WorkerCpuScope() : m_start(threadCpuSeconds()) {}
    ~WorkerCpuScope() { addWorkerCpu(threadCpuSeconds() - m_start); }
    WorkerCpuScope(const WorkerCpuScope&) = delete;
    WorkerCpuScope& operator=(const WorkerCpuScope&) = delete;

private:
    double m_start;
};

} // namespace ob
