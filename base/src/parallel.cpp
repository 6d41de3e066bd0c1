#include "splinefig/base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <fstream>
#include <limits>
#include <string>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "splinefig/base/limits.hpp"

#include <sys/resource.h>
#include <unistd.h>

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

int helpers_that_fit(int helpers);

// Starts body(worker) on helpers 1 .. helpers, runs body(0) here, and joins them. A helper the
// system refuses, or one the address space left cannot hold (helpers_that_fit), is not started;
// the others (and this thread) take its items.
template <class Body>
void run_team(int helpers, Body&& body) {
  helpers = helpers_that_fit(helpers);
  std::vector<std::thread> team;
  team.reserve(static_cast<std::size_t>(std::max(helpers, 0)));
  try {
    for (int w = 1; w <= helpers; ++w) team.emplace_back(body, w);
  } catch (const std::system_error&) {
  }
  body(0);
  for (auto& t : team) t.join();
}

constexpr std::uint64_t kUnknown = std::numeric_limits<std::uint64_t>::max();

// What is left under a resource limit, given the bytes already counted against it.
std::uint64_t left_under(int resource, std::uint64_t used) {
  rlimit r{};
  if (::getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return kUnknown;
  const auto limit = static_cast<std::uint64_t>(r.rlim_cur);
  return limit > used ? limit - used : 0;
}

bool limited(int resource) {
  rlimit r{};
  return ::getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY;
}

// The address space left under RLIMIT_AS and RLIMIT_DATA, the less of the two (kUnknown for
// no limit), from the process's size in /proc/self/statm (total pages, ..., data + stack pages).
std::uint64_t address_space_left() {
  if (!limited(RLIMIT_AS) && !limited(RLIMIT_DATA)) return kUnknown;
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  unsigned long long size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%llu %llu %llu %llu %llu %llu", &size, &resident, &shared, &text, &lib, &data) != 6) size = data = 0;
    std::fclose(f);
  }
  return std::min(left_under(RLIMIT_AS, size * page), left_under(RLIMIT_DATA, data * page));
}

// Under an address-space limit, each helper takes its thread stack (RLIMIT_STACK, 8 MiB when
// unlimited) and, once it allocates, a malloc arena that reserves 64 MiB: the helpers started are
// those whose reservations fit in half of the space left, the other half kept for the work, so
// that --threads 256 under `ulimit -v` does not take the space the canvas needs.
int helpers_that_fit(int helpers) {
  if (helpers <= 0) return 0;
  const std::uint64_t left = address_space_left();
  if (left == kUnknown) return helpers;
  rlimit r{};
  const std::uint64_t stack =
      ::getrlimit(RLIMIT_STACK, &r) == 0 && r.rlim_cur != RLIM_INFINITY ? static_cast<std::uint64_t>(r.rlim_cur) : std::uint64_t(8) << 20;
  const std::uint64_t each = stack + (std::uint64_t(64) << 20);
  return static_cast<int>(std::min<std::uint64_t>(static_cast<std::uint64_t>(helpers), left / 2 / each));
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
                                 const std::function<void(std::size_t, int)>& theirs) {
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
      for (std::size_t k; take(worker == 0, k);) {
        if (worker == 0) mine(k);
        else theirs(k, worker);
      }
    } catch (...) {
      failure.record();
      std::lock_guard<std::mutex> lock(mutex);
      hi = lo;
    }
  });
  failure.rethrow();
  return lo;
}

namespace {

// A number read from the start of a one-line file ("max" or nothing: unknown).
std::uint64_t number_in(const char* path) {
  std::ifstream in(path);
  unsigned long long v = 0;
  return in >> v ? v : kUnknown;
}

}  // namespace

std::uint64_t memory_available() {
  std::uint64_t best = address_space_left();
  {
    std::ifstream in("/proc/meminfo");
    std::string key;
    unsigned long long kib = 0;
    std::string unit;
    while (in >> key >> kib >> unit)
      if (key == "MemAvailable:") {
        best = std::min<std::uint64_t>(best, kib * 1024);
        break;
      }
  }
  const std::uint64_t cgroup_max = number_in("/sys/fs/cgroup/memory.max");
  if (cgroup_max != kUnknown) {
    const std::uint64_t current = number_in("/sys/fs/cgroup/memory.current");
    if (current != kUnknown) best = std::min(best, cgroup_max > current ? cgroup_max - current : 0);
  }
  return best;
}

MemoryBudget::Grant MemoryBudget::acquire(std::uint64_t bytes) {
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t ticket = next_ticket_++;
  changed_.wait(lock, [&] { return serving_ == ticket && (held_ == 0 || bytes <= budget_ - std::min(held_, budget_)); });
  ++serving_;
  held_ += bytes;
  lock.unlock();
  changed_.notify_all();  // the next ticket may fit too
  return Grant(this, bytes);
}

void MemoryBudget::release(std::uint64_t bytes) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    held_ -= bytes;
  }
  changed_.notify_all();
}

}  // namespace splinefig
