#pragma once
// The one way splinefig shares work between threads. Every parallel loop in the libraries goes
// through these two functions, so they share one rule for the thread count (worker_count), one
// fallback when the system refuses a thread, and one way of reporting a failure.
//
// Determinism: the functions decide only which thread runs an item, never what an item
// computes; callers partition their work into items that do not depend on the thread count, so
// the bytes they produce are the same for any `threads`.
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>

namespace splinefig {

// The number of threads a request for `threads` runs on: every core (at least 1) for 0 or less,
// otherwise `threads`, at most kMaxThreads (limits.hpp).
int worker_count(int threads);

// Runs work(k, worker) once for each k in [0, n), on the calling thread and on up to
// worker_count(threads) - 1 helpers started for the call (never more threads than items). Items
// are handed out in increasing order to whichever thread is free; `worker` in
// [0, worker_count(threads)) names the thread running the item (0 is the caller), for scratch
// kept per thread. Helpers the system refuses (RLIMIT_NPROC, memory) leave their share to the
// threads that started; with none, the caller runs every item. Under an address-space limit
// (RLIMIT_AS, RLIMIT_DATA) only the helpers whose stacks and malloc arenas fit in half of the
// space left are started, so that the thread count cannot take the memory the work needs. If an item throws, the items not
// yet started are skipped and the first exception is rethrown on the caller once every helper
// has stopped.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t k, int worker)>& work);

// Shares items [0, n) between the calling thread, which takes them from the front (mine(k) for
// k = 0, 1, ...), and up to worker_count(threads) - 1 helpers, which take them from the back
// (theirs(k, worker) for k = n - 1, n - 2, ..., with worker in [1, worker_count(threads)) naming
// the helper, for scratch kept per thread), each k once. Returns the m such that mine ran for
// [0, m) and theirs for [m, n): the caller's items are a prefix, which it may write straight
// into their final place while the helpers' items are kept aside. Refused helpers and
// exceptions as for parallel_for.
std::size_t split_from_both_ends(std::size_t n, int threads, const std::function<void(std::size_t)>& mine,
                                 const std::function<void(std::size_t, int)>& theirs);

// The bytes a process can still allocate: the least of what is left under RLIMIT_AS and
// RLIMIT_DATA, the memory the system calls available (MemAvailable) and what is left under the
// cgroup's memory.max; UINT64_MAX when none of them is known.
std::uint64_t memory_available();

// Bytes shared by workers that each hold a large buffer for a while (the figures batch's
// canvases), so that how much is held at once depends on the budget, not on the thread count.
// acquire(n) waits until n bytes fit beside those held, granting requests in the order they
// came; a request is granted at once when nothing is held, so one larger than the whole budget
// runs alone (and its allocation may still fail). The bytes are given back when the Grant goes.
class MemoryBudget {
 public:
  explicit MemoryBudget(std::uint64_t bytes) : budget_(bytes) {}
  MemoryBudget(const MemoryBudget&) = delete;
  MemoryBudget& operator=(const MemoryBudget&) = delete;

  class Grant {
   public:
    Grant(Grant&& g) noexcept : owner_(g.owner_), bytes_(g.bytes_) { g.owner_ = nullptr; }
    Grant(const Grant&) = delete;
    Grant& operator=(const Grant&) = delete;
    Grant& operator=(Grant&&) = delete;
    ~Grant() {
      if (owner_) owner_->release(bytes_);
    }

   private:
    friend class MemoryBudget;
    Grant(MemoryBudget* owner, std::uint64_t bytes) : owner_(owner), bytes_(bytes) {}
    MemoryBudget* owner_;
    std::uint64_t bytes_;
  };

  Grant acquire(std::uint64_t bytes);
  std::uint64_t budget() const { return budget_; }

 private:
  void release(std::uint64_t bytes);
  const std::uint64_t budget_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::uint64_t held_ = 0;
  std::uint64_t next_ticket_ = 0, serving_ = 0;  // requests are granted in ticket order
};

}  // namespace splinefig
