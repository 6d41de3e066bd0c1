#pragma once
// Sharing a row of work items [0, n) between the calling thread and helpers it starts for the
// purpose: the caller takes them from the front, the helpers from the back, until they meet.
// The caller's items are then a prefix [0, m), which it may have written straight into their
// final place (a long stroke's outline pieces, appended in order), while the helpers' items
// are kept aside until they can be placed after the caller's.
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace splinefig::render::detail {

// Runs mine(k) for k = 0, 1, ... on this thread and theirs(k) for k = n - 1, n - 2, ... on up to
// threads - 1 helpers, each k once; returns the m such that mine ran for [0, m) and theirs for
// [m, n). Rethrows the first exception either threw once every helper has stopped (the items
// not yet started are then skipped). The system may refuse helpers: this thread then takes
// the items they would have.
template <class Mine, class Theirs>
std::size_t split_from_both_ends(int threads, std::size_t n, Mine&& mine, Theirs&& theirs) {
  std::mutex mutex;
  std::size_t lo = 0, hi = n;  // the items not yet taken
  std::exception_ptr failure;
  auto fail = [&]() {
    std::lock_guard<std::mutex> lock(mutex);
    if (!failure) failure = std::current_exception();
    hi = lo;
  };
  auto helper = [&]() {
    try {
      for (;;) {
        std::size_t k;
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (lo == hi) return;
          k = --hi;
        }
        theirs(k);
      }
    } catch (...) {
      fail();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads > 1 ? threads - 1 : 0));
  try {
    for (int t = 1; t < threads && static_cast<std::size_t>(t) < n; ++t) pool.emplace_back(helper);
  } catch (const std::system_error&) {
  }
  try {
    for (;;) {
      std::size_t k;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (lo == hi) break;
        k = lo++;
      }
      mine(k);
    }
  } catch (...) {
    fail();
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return lo;
}

}  // namespace splinefig::render::detail
