// Persistent worker pool: splits an index range into contiguous chunks over the cores.
// Threads are created once and reused; a call allocates nothing and runs inline when small.
#pragma once
#include <memory>
#include <type_traits>

namespace ob {

/// Type-erased body: runs indices [begin, end) with ctx pointing at the caller's callable.
using RangeFn = void (*)(void* ctx, int begin, int end);

namespace detail {
/// Untyped entry point behind parallelFor (see there).
void parallelForRaw(int begin, int end, int minChunk, RangeFn fn, void* ctx);
} // namespace detail

/// Splits [begin, end) into at most workerCount() contiguous chunks of at least minChunk
/// indices (chunk i = [begin + r·i/c, begin + r·(i+1)/c)) and calls body(chunkBegin,
/// chunkEnd) for each, the calling thread taking part; returns when all are done.
/// Runs body(begin, end) inline when the range holds fewer than 2·minChunk indices, when
/// one worker is set, when called from inside a body, or while another thread dispatches.
/// The first exception thrown by a body is rethrown here. Body must be callable as
/// body(int, int); chunks run concurrently, so they must touch disjoint data.
template <class F>
void parallelFor(int begin, int end, int minChunk, F&& body) {
    using Fn = std::remove_reference_t<F>;
    detail::parallelForRaw(
        begin, end, minChunk,
        [](void* ctx, int b, int e) { (*static_cast<Fn*>(ctx))(b, e); },
        const_cast<void*>(static_cast<const void*>(std::addressof(body))));
}

/// Sets the number of workers (calling thread included) for later parallelFor calls;
/// n <= 0 restores the default, std::thread::hardware_concurrency() (at least 1).
/// Must not be called while a parallelFor is running.
void setWorkerCount(int n);

/// Number of workers parallelFor splits over (calling thread included), >= 1.
int workerCount();

} // namespace ob
