#pragma once
// The one way splinefig shares work between threads. Every parallel loop in the libraries goes
// through these two functions, so they share one rule for the thread count (worker_count), one
// fallback when the system refuses a thread, and one way of reporting a failure.
//
// Determinism: the functions decide only which thread runs an item, never what an item
// computes; callers partition their work into items that do not depend on the thread count, so
// the bytes they produce are the same for any `threads`.
#include <cstddef>
#include <functional>

namespace splinefig {

// The number of threads a request for `threads` runs on: every core (at least 1) for 0 or less,
// otherwise `threads`, at most kMaxThreads (limits.hpp).
int worker_count(int threads);

// Runs work(k, worker) once for each k in [0, n), on the calling thread and on up to
// worker_count(threads) - 1 helpers started for the call (never more threads than items). Items
// are handed out in increasing order to whichever thread is free; `worker` in
// [0, worker_count(threads)) names the thread running the item (0 is the caller), for scratch
// kept per thread. Helpers the system refuses (RLIMIT_NPROC, memory) leave their share to the
// threads that started; with none, the caller runs every item. If an item throws, the items not
// yet started are skipped and the first exception is rethrown on the caller once every helper
// has stopped.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t k, int worker)>& work);

// Shares items [0, n) between the calling thread, which takes them from the front (mine(k) for
// k = 0, 1, ...), and up to worker_count(threads) - 1 helpers, which take them from the back
// (theirs(k) for k = n - 1, n - 2, ...), each k once. Returns the m such that mine ran for
// [0, m) and theirs for [m, n): the caller's items are a prefix, which it may write straight
// into their final place while the helpers' items are kept aside. Refused helpers and
// exceptions as for parallel_for.
std::size_t split_from_both_ends(std::size_t n, int threads, const std::function<void(std::size_t)>& mine,
                                 const std::function<void(std::size_t)>& theirs);

}  // namespace splinefig
