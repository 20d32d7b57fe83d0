// Measured thread counts kept in the cache folder: one "key of N = n" line per kernel.
#include "core/thread_choice.h"

#include "core/cache_file.h"
#include "core/log.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>
#include <unistd.h>

namespace ob {

namespace {

// OCEANBOX_MEASURE_THREADS=0 in the environment starts with measuring off.
std::atomic<bool> s_measuring{[] {
    const char* env = std::getenv("OCEANBOX_MEASURE_THREADS");
    return !(env && std::string(env) == "0");
}()};

// "key of N = n" lines; anything else is skipped (a file from another version re-measures).
std::map<std::string, int> readChoices(const std::string& path) {
    std::map<std::string, int> out;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        const size_t eq = line.rfind(" = ");
        if (eq == std::string::npos) continue;
        const int n = std::atoi(line.c_str() + eq + 3);
        if (n >= 1) out[line.substr(0, eq)] = n;
    }
    return out;
}

bool writeChoices(const std::string& path, const std::map<std::string, int>& choices) {
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp);
        for (const auto& [key, n] : choices) out << key << " = " << n << "\n";
        if (!out) return false;
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) std::filesystem::remove(tmp, ec);
    return !ec;
}

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// MEASURE_PAIRS alternating samples of run(1) and run(threads), each sample the mean of `reps`
// runs with reps chosen so a sample lasts about 1 ms; the lower median wins, more threads
// only by SPEED_UP_NEEDED.
int measure(int threads, const std::function<void(int)>& run) {
    using Clock = std::chrono::steady_clock;
    const auto timeRuns = [&](int n, int reps) {
        const auto t0 = Clock::now();
        for (int r = 0; r < reps; ++r) run(n);
        return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / reps;
    };
    timeRuns(1, 1);  // warm-up: caches, pages, the worker threads
    timeRuns(threads, 1);
    const double once = timeRuns(1, 1);
    const int reps = std::clamp(int(std::ceil(1.0 / std::max(once, 1e-3))), 1, 64);
    std::vector<double> one, many;
    for (int p = 0; p < MEASURE_PAIRS; ++p) {
        one.push_back(timeRuns(1, reps));
        many.push_back(timeRuns(threads, reps));
    }
    return medianOf(many) < SPEED_UP_NEEDED * medianOf(one) ? threads : 1;
}

} // namespace

void setThreadMeasuring(bool on) { s_measuring = on; }

bool threadMeasuring() { return s_measuring; }

int measuredThreads(const std::string& key, int threads, const std::function<void(int threads)>& run) {
    if (threads <= 1) return 1;
    if (!s_measuring) return threads;
    static std::mutex mutex;             // one measurement at a time in the process
    static std::map<std::string, int> known;  // this process's choices (the file's, or measured)
    std::lock_guard<std::mutex> lock(mutex);
    const std::string full = key + " of " + std::to_string(threads);
    if (const auto it = known.find(full); it != known.end()) return it->second;
    const std::string path = cachePath("thread_choices");  // beside the FFTW wisdom
    FileLock fileLock(path);
    std::map<std::string, int> choices;
    if (fileLock.held()) {
        choices = readChoices(path);
        if (const auto it = choices.find(full); it != choices.end()) {
            const int n = std::clamp(it->second, 1, threads);
            known[full] = n;
            return n;
        }
    }
    const int n = measure(threads, run);
    known[full] = n;
    choices[full] = n;
    if (!fileLock.held() || !writeChoices(path, choices)) {
        static bool warned = false;
        if (!warned) {
            warned = true;
            logWarn("the thread-count cache %s cannot be written: thread counts are measured again in every run",
                    path.empty() ? "(no HOME or XDG_CACHE_HOME)" : path.c_str());
        }
    }
    return n;
}

bool measuredChoice(const std::string& key, bool fallback, const std::function<void(bool second)>& run) {
    if (!s_measuring) return fallback;
    // Two "threads": the second way (the cache's line reads "key of 2 = 2" when it won).
    return measuredThreads(key, 2, [&run](int n) { run(n == 2); }) == 2;
}

} // namespace ob
