// Thread counts chosen by measurement, once per machine and kernel size, the way FFTW chooses
// its plans, and kept in the cache beside the FFTW wisdom.
#pragma once
#include <functional>
#include <string>

namespace ob {

/// Threads for the kernel named `key` (its size in it, e.g. "ocean 256² ×1 cascades"): 1 or
/// `threads`. The choice kept in the cache file ($XDG_CACHE_HOME/oceanbox/thread_choices, else
/// ~/.cache/oceanbox/thread_choices) for key and `threads`, else measured now and kept there
/// (under a file lock, so processes starting together measure one at a time): `run(n)` runs
/// the kernel once on n threads, alternately for 1 and `threads`, in MEASURE_PAIRS pairs
/// (repeated within a sample up to about 1 ms), and `threads` is chosen only when its median is
/// below SPEED_UP_NEEDED × the one-thread median: a kernel is never slower than on one thread
/// as measured. threads <= 1 returns 1 without measuring; with measuring off (below) returns
/// `threads`. Without a writable cache the choice is measured once per process.
int measuredThreads(const std::string& key, int threads, const std::function<void(int threads)>& run);

/// Which of two ways to run the kernel named `key` (its size in it): true for the second, chosen
/// only when its median is below SPEED_UP_NEEDED × the first's, measured and kept in the same
/// cache as measuredThreads (`run(second)` runs it once either way); with measuring off, `fallback`.
bool measuredChoice(const std::string& key, bool fallback, const std::function<void(bool second)>& run);

/// Alternating pairs measured by measuredThreads.
constexpr int MEASURE_PAIRS = 5;
/// measuredThreads picks more than one thread only below this fraction of the one-thread time.
constexpr double SPEED_UP_NEEDED = 0.9;

/// Off: measuredThreads returns the most threads it is offered, without measuring or reading
/// the cache (tests that check the bits of every split; sanitizer runs). On by default;
/// OCEANBOX_MEASURE_THREADS=0 in the environment starts a process with it off.
void setThreadMeasuring(bool on);
/// Whether measuring is on (setThreadMeasuring).
bool threadMeasuring();

} // namespace ob
