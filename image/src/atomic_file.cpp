// Atomic file publication with signal-safe cleanup of temporary files (see atomic_file.hpp).
#include <splinefig/image/atomic_file.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <mutex>
#include <optional>

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace splinefig {
namespace {

namespace fs = std::filesystem;

// Temporary files being written, for the signal handler. A slot is free (0), being filled or
// emptied (1) or holds a file to remove (2); the handler only reads slots in state 2, and
// only async-signal-safe calls are made there.
struct Slot {
  std::atomic<int> state{0};
  int dirfd = -1;
  char name[256] = {};
};
constexpr int kSlots = 64;
Slot g_slots[kSlots];

// Every signal whose default action ends the process: the handler removes the temporaries, then
// the signal ends the process as it would have. That is the terminating signals another process
// or a limit sends (SIGINT ... SIGXFSZ, the real-time signals), and also the faults (SIGSEGV,
// SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS), which kill(1) can send as well and after
// which nothing of the file is worth keeping either. SIGXFSZ is here for programs that leave it
// at its default; the splinefig command ignores it, so that a write over the file-size limit
// fails with EFBIG and is reported like any failed write.
constexpr int kChained[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kFixed[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGVTALRM,
                          SIGPROF, SIGXCPU, SIGXFSZ, SIGPOLL, SIGSEGV, SIGBUS,  SIGFPE,  SIGILL,  SIGABRT,
                          SIGTRAP, SIGSYS,
#ifdef SIGSTKFLT
                          SIGSTKFLT,
#endif
#ifdef SIGPWR
                          SIGPWR,
#endif
#ifdef SIGEMT
                          SIGEMT,
#endif
#ifdef SIGLOST
                          SIGLOST,
#endif
};

// The signals above and the real-time signals, by number (SIGRTMIN is known only at run time).
struct SignalList {
  int count = 0;
  int numbers[NSIG] = {};
  sigset_t set;
  SignalList() {
    sigemptyset(&set);
    auto add = [this](int sig) {
      if (sig <= 0 || sig >= NSIG || sigismember(&set, sig) == 1) return;
      numbers[count++] = sig;
      sigaddset(&set, sig);
    };
    for (int sig : kFixed) add(sig);
#if defined(SIGRTMIN) && defined(SIGRTMAX)
    for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) add(sig);
#endif
  }
};
const SignalList& cleanup_signals() {
  static const SignalList list;
  return list;
}
struct sigaction g_previous[NSIG];  // by signal number, for the handler to restore

// Creating a temporary file and registering it is one step as far as the handler can see: a
// writer does both holding g_lock with the signals blocked in its own thread, and the handler
// (running on another thread) takes g_lock before it removes the registered files and sets
// g_dying first, so no writer creates a file after the handler has looked. The lock is held
// only for an openat and a copy of the name; spinning on it is async-signal-safe.
std::atomic_flag g_lock = ATOMIC_FLAG_INIT;
std::atomic<bool> g_dying{false};

void lock() {
  while (g_lock.test_and_set(std::memory_order_acquire)) {
  }
}
void unlock() { g_lock.clear(std::memory_order_release); }

// Blocks the cleanup signals in this thread for its lifetime, and holds g_lock.
class Critical {
 public:
  Critical() {
    ::pthread_sigmask(SIG_BLOCK, &cleanup_signals().set, &old_);
    lock();
  }
  ~Critical() {
    unlock();
    ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  Critical(const Critical&) = delete;
  Critical& operator=(const Critical&) = delete;

 private:
  sigset_t old_;
};

extern "C" void remove_temporaries_and_reraise(int sig) {
  const int saved = errno;
  g_dying.store(true, std::memory_order_seq_cst);
  lock();
  for (Slot& s : g_slots)
    if (s.state.load(std::memory_order_acquire) == 2) ::unlinkat(s.dirfd, s.name, 0);
  unlock();
  if (sig > 0 && sig < NSIG) ::sigaction(sig, &g_previous[sig], nullptr);
  errno = saved;
  ::raise(sig);  // delivered when this handler returns, to the previous action
}

void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    const SignalList& list = cleanup_signals();
    for (int i = 0; i < list.count; ++i) {
      const int sig = list.numbers[i];
      struct sigaction current {};
      if (::sigaction(sig, nullptr, &current) != 0) continue;
      if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN) continue;
      // SIGINT, SIGTERM and SIGHUP are chained to a handler the program has (Python's SIGINT);
      // the others are taken only at their default action, never from a profiler, a timer, a
      // debugger or a sanitizer's fault handler.
      const bool is_default = !(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_DFL;
      const bool chained = std::find(std::begin(kChained), std::end(kChained), sig) != std::end(kChained);
      if (!chained && !is_default) continue;
      g_previous[sig] = current;
      struct sigaction sa {};
      sa.sa_handler = remove_temporaries_and_reraise;
      sa.sa_mask = list.set;  // the other cleanup signals wait while the handler holds g_lock
      sa.sa_flags = 0;
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

// Registers a temporary file with the signal handler (the caller holds a Critical); a no-op
// when all slots are taken.
class Registration {
 public:
  Registration(int dirfd, const std::string& name) {
    if (name.size() >= sizeof(Slot::name)) return;
    for (Slot& s : g_slots) {
      int expected = 0;
      if (s.state.compare_exchange_strong(expected, 1, std::memory_order_acquire)) {
        s.dirfd = dirfd;
        std::memcpy(s.name, name.c_str(), name.size() + 1);
        s.state.store(2, std::memory_order_release);
        slot_ = &s;
        return;
      }
    }
  }
  ~Registration() {
    if (!slot_) return;
    const Critical c;
    slot_->state.store(1, std::memory_order_release);
    slot_->dirfd = -1;
    slot_->name[0] = 0;
    slot_->state.store(0, std::memory_order_release);
  }
  Registration(const Registration&) = delete;
  Registration& operator=(const Registration&) = delete;

 private:
  Slot* slot_ = nullptr;
};

std::string reason(int err) { return std::strerror(err); }

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Removes temporary files of `filename` left by processes that no longer exist (killed with
// SIGKILL, or a power cut). Files of live processes, and names this process did not make, stay.
void remove_stale_temporaries(int dirfd, const std::string& filename) {
  // '.', not ".": GCC 12 warns of a bogus overlap (-Wrestrict, GCC PR 105329) for a
  // one-character string literal + a temporary std::string; also in temporary_name.
  const std::string head = '.' + filename.substr(0, 200) + ".splinefig-";
  const int fd = ::dup(dirfd);
  if (fd < 0) return;
  DIR* d = ::fdopendir(fd);
  if (!d) {
    ::close(fd);
    return;
  }
  ::rewinddir(d);
  const long self = long(::getpid());
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name.size() <= head.size() + 4 || name.compare(0, head.size(), head) != 0 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      continue;
    const std::string rest = name.substr(head.size(), name.size() - head.size() - 4);  // "<pid>-<n>"
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || rest.find_first_not_of("0123456789-") != std::string::npos) continue;
    const long pid = std::strtol(rest.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == self) continue;
    if (::kill(pid_t(pid), 0) == -1 && errno == ESRCH) ::unlinkat(dirfd, name.c_str(), 0);
  }
  ::closedir(d);
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  const bool same = fs::equivalent(a, b, ec);
  return !ec && same;
}

std::string temporary_name(const std::string& filename, long pid, unsigned long n) {
  // 1 + 200 + ".splinefig-" (11) + pid (<= 20) + "-" + n (<= 20) + ".tmp" (4) < 256.
  std::string name = '.' + filename.substr(0, 200);
  name += ".splinefig-" + std::to_string(pid) + "-" + std::to_string(n) + ".tmp";
  return name;
}

void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes) {
  static std::atomic<unsigned long> counter{0};
  const fs::path target(path);
  const std::string filename = target.filename().string();
  if (filename.empty() || filename == "." || filename == "..")
    throw UnwritableFile(path + ": not a file name");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");

  install_handlers();
  Fd d;
  d.fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (d.fd < 0) throw UnwritableFile(path + ": cannot open its directory (" + reason(errno) + ")");

  std::string tmp;
  Fd f;
  std::optional<Registration> reg;
  {
    const Critical c;  // created and registered before any cleanup signal can look
    if (g_dying.load()) throw UnwritableFile(path + ": not written, the process is being stopped by a signal");
    for (int attempt = 0; attempt < 100 && f.fd < 0; ++attempt) {
      tmp = temporary_name(filename, long(::getpid()), counter++);
      f.fd = ::openat(d.fd, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (f.fd < 0 && errno != EEXIST)
        throw UnwritableFile(path + ": cannot create a file there (" + reason(errno) + ")");
    }
    if (f.fd < 0) throw UnwritableFile(path + ": cannot create a unique temporary file");
    reg.emplace(d.fd, tmp);
  }
  auto fail = [&](const std::string& what, int err) {
    ::close(f.fd);
    f.fd = -1;
    ::unlinkat(d.fd, tmp.c_str(), 0);
    throw UnwritableFile(path + ": " + what + " (" + reason(err) + ")");
  };
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(f.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed", errno);
    }
    if (n == 0) fail("write failed", EIO);
    done += std::size_t(n);
  }
  if (::fsync(f.fd) != 0) fail("write failed", errno);
  const int fd = f.fd;
  f.fd = -1;
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlinkat(d.fd, tmp.c_str(), 0);
    throw UnwritableFile(path + ": write failed (" + reason(err) + ")");
  }
  if (::renameat(d.fd, tmp.c_str(), d.fd, filename.c_str()) != 0) {
    const int err = errno;
    ::unlinkat(d.fd, tmp.c_str(), 0);
    throw UnwritableFile(path + ": cannot move the finished file into place (" + reason(err) + ")");
  }
  remove_stale_temporaries(d.fd, filename);
  // The rename itself reaches the disk with the directory; some file systems cannot sync one.
  if (::fsync(d.fd) != 0 && errno != EINVAL && errno != EROFS)
    throw UnwritableFile(path + ": written, but its directory could not be synced (" + reason(errno) + ")");
}

}  // namespace splinefig
