#include "splinefig/base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "splinefig/base/limits.hpp"

namespace splinefig {
namespace {

// The first failure of a loop, and a way to tell the other threads to stop taking items.
class Failure {
 public:
  void record() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!first_) first_ = std::current_exception();
  }
  void rethrow() {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
};

// Starts body(worker) on helpers 1 .. helpers, runs body(0) here, and joins them. A helper the
// system refuses is not started; the others (and this thread) take its items.
template <class Body>
void run_team(int helpers, Body&& body) {
  std::vector<std::thread> team;
  team.reserve(static_cast<std::size_t>(std::max(helpers, 0)));
  try {
    for (int w = 1; w <= helpers; ++w) team.emplace_back(body, w);
  } catch (const std::system_error&) {
  }
  body(0);
  for (auto& t : team) t.join();
}

}  // namespace

int worker_count(int threads) {
  if (threads > 0) return std::min(threads, kMaxThreads);
  const unsigned hw = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp(hw, 1u, static_cast<unsigned>(kMaxThreads)));
}

void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t, int)>& work) {
  if (n == 0) return;
  const int workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(worker_count(threads)), n));
  if (workers == 1) {
    for (std::size_t k = 0; k < n; ++k) work(k, 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  Failure failure;
  run_team(workers - 1, [&](int worker) {
    try {
      for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < n;) work(k, worker);
    } catch (...) {
      failure.record();
      next.store(n, std::memory_order_relaxed);  // no new items; those under way finish
    }
  });
  failure.rethrow();
}

std::size_t split_from_both_ends(std::size_t n, int threads, const std::function<void(std::size_t)>& mine,
                                 const std::function<void(std::size_t)>& theirs) {
  const int workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(worker_count(threads)), std::max<std::size_t>(n, 1)));
  std::mutex mutex;
  std::size_t lo = 0, hi = n;  // the items not yet taken
  Failure failure;
  // Takes the next item from the front (the caller) or the back (a helper), if any is left.
  auto take = [&](bool front, std::size_t& k) {
    std::lock_guard<std::mutex> lock(mutex);
    if (lo == hi) return false;
    k = front ? lo++ : --hi;
    return true;
  };
  run_team(workers - 1, [&](int worker) {
    try {
      for (std::size_t k; take(worker == 0, k);) (worker == 0 ? mine : theirs)(k);
    } catch (...) {
      failure.record();
      std::lock_guard<std::mutex> lock(mutex);
      hi = lo;
    }
  });
  failure.rethrow();
  return lo;
}

}  // namespace splinefig
