// Atomic writes under kill -9: a real `splinefig figures` killed with SIGKILL while it writes its
// PNG leaves no partial target (the previous output is intact, byte for byte), only a temporary
// file with an obvious name (".NAME.splinefig-PID-N.tmp"), which the next run that writes the
// same target removes.
//
// The child runs under ptrace, stopped at every system call of every thread; at each stop, while
// it cannot move, the test looks for the temporary file. The first stop at which it exists and
// holds bytes (the PNG written, not yet renamed into place) is where the child is killed: the
// same moment on any machine, however loaded, instead of a poll that has to be quick enough to
// see the file between its creation and its rename. A safety limit only reports a hang.
#include "hostile.hpp"
#include "skip.hpp"

#include <atomic>
#include <condition_variable>
#include <csignal>
#include <mutex>
#include <thread>
#include <sys/ptrace.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace splinefig::hostile;

namespace {

std::vector<fs::path> temporaries(const fs::path& dir, const std::string& target) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.rfind("." + target + ".splinefig-", 0) == 0 && n.size() > 4 && n.compare(n.size() - 4, 4, ".tmp") == 0)
      out.push_back(e.path());
  }
  return out;
}

bool temporary_with_bytes(const fs::path& dir, const std::string& target) {
  for (const fs::path& p : temporaries(dir, target)) {
    std::error_code ec;
    if (fs::file_size(p, ec) > 0 && !ec) return true;
  }
  return false;
}

enum class Traced { killed_at_temporary, finished, no_ptrace, hung };

// Runs `argv` in `dir` traced, and kills it at the first system-call stop at which a temporary
// file of `target` holds bytes.
Traced run_until_temporary(const fs::path& dir, const std::vector<std::string>& argv, const std::string& target) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    if (::ptrace(PTRACE_TRACEME, 0, nullptr, nullptr) != 0) ::_exit(126);
    ::raise(SIGSTOP);  // the tracer sets its options before the program starts
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  if (!WIFSTOPPED(status)) {
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 126);
    return Traced::no_ptrace;
  }
  const long options = PTRACE_O_TRACESYSGOOD | PTRACE_O_TRACECLONE | PTRACE_O_TRACEEXEC | PTRACE_O_EXITKILL;
  REQUIRE(::ptrace(PTRACE_SETOPTIONS, pid, nullptr, reinterpret_cast<void*>(options)) == 0);
  // The safety limit: a child that never gets there is killed and reported as a hang.
  std::mutex m;
  std::condition_variable cv;
  bool over = false;
  std::atomic<bool> hung{false};
  std::thread watchdog([&] {
    std::unique_lock<std::mutex> lock(m);
    if (!cv.wait_for(lock, std::chrono::seconds(5 * kTimeLimit), [&] { return over; })) {
      hung = true;
      ::kill(pid, SIGKILL);
    }
  });
  bool killed = false;
  REQUIRE(::ptrace(PTRACE_SYSCALL, pid, nullptr, nullptr) == 0);
  for (;;) {
    const pid_t tid = ::waitpid(-1, &status, __WALL);
    if (tid < 0) break;
    if (WIFEXITED(status) || WIFSIGNALED(status)) {
      if (tid == pid) break;
      continue;  // a thread of the child ended
    }
    if (!WIFSTOPPED(status)) continue;
    const int sig = WSTOPSIG(status);
    int deliver = 0;
    if (sig == (SIGTRAP | 0x80)) {  // a system-call stop: the thread is frozen in the call
      if (!killed && temporary_with_bytes(dir, target)) {
        ::kill(pid, SIGKILL);
        killed = true;
      }
    } else if (status >> 16 != 0) {  // a clone or exec event
    } else if (sig == SIGSTOP) {      // a new thread's first stop
    } else {
      deliver = sig;  // the child's own signal
    }
    ::ptrace(PTRACE_SYSCALL, tid, nullptr, reinterpret_cast<void*>(long(deliver)));
  }
  {
    std::lock_guard<std::mutex> lock(m);
    over = true;
  }
  cv.notify_one();
  watchdog.join();
  if (hung) return Traced::hung;
  return killed ? Traced::killed_at_temporary : Traced::finished;
}

}  // namespace

TEST_CASE("figures killed with SIGKILL mid-write leaves the previous output intact and a named temporary file") {
  const fs::path dir = scratch();
  const std::string specs_dir = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  REQUIRE(run_in(dir, {"figures", "--specs", specs_dir, "--out", ".", "--only", "bbasis"}).code == 0);
  const std::string good = splinefig::test::slurp(dir / "bbasis.png");
  REQUIRE(good.size() > 1000);

  const Traced t = run_until_temporary(
      dir, {SPLINEFIG_EXE, "figures", "--specs", specs_dir, "--out", ".", "--only", "bbasis", "--threads", "1"}, "bbasis.png");
  if (t == Traced::no_ptrace) {
    splinefig::testing_support::skip("ptrace is not permitted here: the child cannot be stopped at its write");
    fs::remove_all(dir);
    return;
  }
  INFO("0: killed at the temporary file, 1: finished without one, 3: hung (killed at the safety limit)");
  REQUIRE(int(t) == int(Traced::killed_at_temporary));
  // The target is the previous run's file, not a partial one.
  CHECK(splinefig::test::slurp(dir / "bbasis.png") == good);
  CHECK(temporaries(dir, "bbasis.png").size() == 1);
  // The next run over the same target removes the dead process's temporary file.
  REQUIRE(run_in(dir, {"figures", "--specs", specs_dir, "--out", ".", "--only", "bbasis"}).code == 0);
  CHECK(temporaries(dir, "bbasis.png").empty());
  CHECK(splinefig::test::slurp(dir / "bbasis.png") == good);
  fs::remove_all(dir);
}
