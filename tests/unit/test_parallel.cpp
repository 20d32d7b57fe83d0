// The worker pool under load: many short jobs back to back, so a worker that wakes late
// meets the next job (the race the generation word guards against); each index is run
// exactly once by one job. Under ThreadSanitizer this is the pool's stress test.
#include "core/parallel.h"

#include <atomic>
#include <catch2/catch.hpp>
#include <vector>

TEST_CASE("parallelFor: 3000 back-to-back jobs of varying size run every index once, on 2, 3 and 8 workers", "[parallel]") {
    for (int workers : {2, 3, 8}) {
        ob::setWorkerCount(workers);
        std::vector<int> hits(4096);
        long long wrong = 0;
        for (int job = 0; job < 3000; ++job) {
            const int n = 1 + (job * 37) % 4096;
            ob::parallelFor(0, n, 1 + job % 64, [&](int b, int e) {
                for (int i = b; i < e; ++i) hits[size_t(i)] += 1;  // chunks are disjoint: no atomics needed
            });
            for (int i = 0; i < n; ++i) {
                wrong += hits[size_t(i)] != 1;
                hits[size_t(i)] = 0;
            }
        }
        CHECK(wrong == 0);
    }
    ob::setWorkerCount(0);
}

TEST_CASE("parallelFor: a job whose chunks throw leaves the pool ready for the next, on 8 workers", "[parallel]") {
    ob::setWorkerCount(8);
    for (int job = 0; job < 200; ++job) {
        CHECK_THROWS(ob::parallelFor(0, 800, 1, [&](int b, int) {
            if (b % 3 == 0) throw std::runtime_error("chunk");
        }));
        std::atomic<int> total{0};
        ob::parallelFor(0, 800, 1, [&](int b, int e) { total += e - b; });
        CHECK(total == 800);
    }
    ob::setWorkerCount(0);
}
