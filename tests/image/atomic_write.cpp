// Atomic publication of image files: unique temporary names that fit NAME_MAX, concurrent
// writers, a full disk (a file-size limit: writes fail with EFBIG as they do with ENOSPC),
// and real signals to real processes.
#include <splinefig/image/io.hpp>

#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace splinefig;
namespace fs = std::filesystem;

namespace {

// Noise does not compress: the file is about as large as its pixels.
Image noise(int w, int h, unsigned seed) {
  Image im(w, h, 4);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (std::size_t p = 0; p < im.pixel_count(); ++p) {
    const float a = u(rng);
    for (int c = 0; c < 3; ++c) im.pixels[p * 4 + std::size_t(c)] = u(rng) * a;
    im.pixels[p * 4 + 3] = a;
  }
  return im;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Starts the hidden test case `name` of this executable in a new process, given `dir` in
// SPLINEFIG_CHILD_DIR (and `extra_env`); in_fresh_process waits for it and returns its wait
// status (the code child_main's body returned). A fresh
// exec, not a bare fork: when this process has already written an EXR (another test case, run
// in the same process by `test_image` without a filter), OpenEXR's thread pool is running, and a
// forked copy that writes an EXR waits forever for workers it does not have.
pid_t spawn_fresh_process(const std::string& name, const fs::path& dir, const std::vector<std::string>& extra_env = {}) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("SPLINEFIG_CHILD_", 0) != 0) env.emplace_back(*e);
  env.push_back("SPLINEFIG_CHILD_DIR=" + dir.string());
  env.insert(env.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> envp, argv{const_cast<char*>("test_image"), const_cast<char*>(name.c_str()), nullptr};
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::execve("/proc/self/exe", argv.data(), envp.data());
    ::_exit(97);
  }
  return pid;
}

int in_fresh_process(const std::string& name, const fs::path& dir) {
  const pid_t pid = spawn_fresh_process(name, dir);
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  return status;
}

// The body of a hidden test case run by in_fresh_process: `body(dir)`'s return value is the
// process's exit code (98: it threw). Run any other way (no SPLINEFIG_CHILD_DIR), it does nothing.
template <class F>
void child_main(F body) {
  const char* dir = std::getenv("SPLINEFIG_CHILD_DIR");
  if (!dir) return;
  int code = 99;
  try {
    code = body(fs::path(dir));
  } catch (...) {
    code = 98;
  }
  std::fflush(nullptr);
  ::_exit(code);
}

}  // namespace

TEST_CASE("atomic write: temporary names are unique and fit NAME_MAX for any valid target name") {
  for (std::size_t len : {5u, 100u, 200u, 246u, 251u, 255u}) {
    const std::string name = std::string(len - 4, 'n') + ".png";
    const std::string tmp = temporary_name(name, 4194304, 18446744073709551615ul);
    CHECK(tmp.size() <= 255);
    CHECK(tmp.front() == '.');
  }
  CHECK(temporary_name("a.png", 1, 2) != temporary_name("a.png", 1, 3));
  CHECK(temporary_name("a.png", 1, 2) != temporary_name("a.png", 2, 2));

  const auto dir = scratch_dir("long-names");
  const Image im = noise(4, 4, 1);
  for (std::size_t len : {246u, 251u, 255u}) {
    const std::string name = std::string(len - 4, 'x') + ".png";
    write_image((dir / name).string(), im);
    CHECK(fs::exists(dir / name));
    fs::remove(dir / name);
  }
  CHECK(names_in(dir).empty());
}

TEST_CASE("atomic write: threads writing the same and different files leave only complete files") {
  const auto dir = scratch_dir("threads");
  const Image a = noise(64, 64, 2), b = noise(64, 64, 3);
  std::atomic<int> failures{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < 8; ++t)
    pool.emplace_back([&, t] {
      try {
        for (int i = 0; i < 10; ++i) {
          write_image((dir / "shared.png").string(), (t + i) % 2 ? a : b);
          write_image((dir / ("own" + std::to_string(t) + ".exr")).string(), a);
        }
      } catch (...) {
        ++failures;
      }
    });
  for (auto& th : pool) th.join();
  CHECK(failures == 0);
  const auto names = names_in(dir);
  CHECK(names.size() == 9);
  for (const auto& n : names) {
    INFO(n);
    CHECK(n.find(".tmp") == std::string::npos);
    CHECK_NOTHROW(read_image((dir / n).string()));
  }
}

TEST_CASE("atomic write child - full disk", "[.child]") {
  child_main([](const fs::path& dir) {
    const fs::path out = dir / "out", keep = dir / "keep";
    const fs::path png = out / "figure.png", exr = out / "figure.exr";
    write_image(png.string(), noise(8, 8, 4));
    write_image(exr.string(), noise(8, 8, 4));
    fs::copy_file(png, keep / "figure.png");
    fs::copy_file(exr, keep / "figure.exr");
    std::signal(SIGXFSZ, SIG_IGN);  // writes past the limit fail with EFBIG instead
    struct rlimit lim {
      16384, 16384
    };
    if (::setrlimit(RLIMIT_FSIZE, &lim) != 0) return 10;
    int code = 0;
    for (const fs::path& p : {png, exr}) {
      try {
        write_image(p.string(), noise(256, 256, 5));  // about 1 MB
        code |= 1;  // reported success
      } catch (const UnwritableImage& e) {
        const std::string what = e.what();
        if (what.rfind(p.string() + ": ", 0) != 0 || what.find('\n') != std::string::npos) code |= 2;
      }
    }
    return code;
  });
}

TEST_CASE("atomic write: a full disk is an error, the old file stays and no temporary is left") {
  // The file-size limit and everything that touches OpenImageIO are in a fresh process.
  const auto dir = scratch_dir("full-disk");
  const fs::path out = dir / "out", keep = dir / "keep";
  fs::create_directories(out);
  fs::create_directories(keep);
  const fs::path png = out / "figure.png", exr = out / "figure.exr";
  const int status = in_fresh_process("atomic write child - full disk", dir);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(names_in(out) == std::vector<std::string>{"figure.exr", "figure.png"});
  CHECK(bytes_of(png) == bytes_of(keep / "figure.png"));
  CHECK(bytes_of(exr) == bytes_of(keep / "figure.exr"));
}

// Threads writing PNGs in a fresh process (no cleanup handler inherited: a forked copy of a
// process that has written an image already would inherit this one's, which the reset to the
// default action below would then remove), at the signal's default action until the signal.
TEST_CASE("atomic write child - writers until a signal", "[.child]") {
  child_main([](const fs::path& dir) {
    const int sig = std::atoi(std::getenv("SPLINEFIG_CHILD_SIGNAL")), threads = std::atoi(std::getenv("SPLINEFIG_CHILD_THREADS"));
    std::signal(sig, SIG_DFL);  // as in a plain process (the test runner catches some)
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);  // SIGQUIT, SIGXCPU, SIGXFSZ and the faults would dump core
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        const Image im = noise(512, 512, unsigned(t));
        try {
          for (int i = 0;; ++i) write_image((dir / ('w' + std::to_string(t) + "-" + std::to_string(i % 3) + ".png")).string(), im);
        } catch (const UnwritableImage&) {
          // Once the handler runs, a write another thread starts is refused ("the process is
          // being stopped by a signal"); this thread then waits for the signal to end the process
          // (an uncaught exception would end it first, by SIGABRT).
          for (;;) ::pause();
        }
      });
    for (auto& th : pool) th.join();
    return 0;
  });
}

namespace {

// That child, sent `sig` `delay_ms` after the first file of its appeared in its directory: it
// ends by that signal and leaves only complete files.
void check_signal_leaves_no_temporary(int sig, int threads, int delay_ms, const std::string& tag) {
  const auto dir = scratch_dir(tag);
  const pid_t pid = spawn_fresh_process("atomic write child - writers until a signal", dir,
                                        {"SPLINEFIG_CHILD_SIGNAL=" + std::to_string(sig), "SPLINEFIG_CHILD_THREADS=" + std::to_string(threads)});
  // The child has started writing: its first (temporary) file exists. The safety limit only
  // reports a child that never writes.
  const auto t0 = std::chrono::steady_clock::now();
  while (fs::is_empty(dir) && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const bool started = !fs::is_empty(dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
  ::kill(pid, sig);
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  INFO(tag);
  REQUIRE(started);
  CHECK(WIFSIGNALED(status));
  if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == sig);
  for (const auto& n : names_in(dir)) {
    INFO(n);
    CHECK(n.find(".tmp") == std::string::npos);
    // Complete PNG structure, every CRC and the whole zlib stream (read here byte by byte).
    CHECK_NOTHROW(check_png_structure((dir / n).string()));
  }
  fs::remove_all(dir);
}

}  // namespace

TEST_CASE("atomic write: SIGTERM during parallel writes leaves no temporary file") {
  for (int round = 0; round < 8; ++round)
    check_signal_leaves_no_temporary(SIGTERM, 4, 37 * round, "sigterm-" + std::to_string(round));
}

TEST_CASE("atomic write: every signal that ends the process by default leaves no temporary file") {
  // SIGINT and SIGHUP as SIGTERM; those a limit or a timer sends; the faults, as kill(1) sends
  // them; the Linux ones (SIGSTKFLT, SIGPWR) and the real-time signals at both ends and between.
  std::vector<int> signals{SIGINT,  SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGVTALRM, SIGPROF, SIGXCPU,
                           SIGXFSZ, SIGPOLL, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};
#ifdef SIGSTKFLT
  signals.push_back(SIGSTKFLT);
#endif
#ifdef SIGPWR
  signals.push_back(SIGPWR);
#endif
  for (int sig : {SIGRTMIN, SIGRTMIN + 1, (SIGRTMIN + SIGRTMAX) / 2, SIGRTMAX}) signals.push_back(sig);
  for (int sig : signals) check_signal_leaves_no_temporary(sig, 2, 20, "signal-" + std::to_string(sig));
}

TEST_CASE("atomic write child - inherited SIG_IGN", "[.child]") {
  child_main([](const fs::path& dir) {
    std::signal(SIGINT, SIG_IGN);
    write_image((dir / "a.png").string(), noise(4, 4, 6));  // installs the cleanup handlers
    ::raise(SIGINT);
    write_image((dir / "b.png").string(), noise(4, 4, 7));
    ::raise(SIGINT);
    return 7;
  });
}

TEST_CASE("atomic write: an inherited SIG_IGN stays ignored") {
  const auto dir = scratch_dir("sig-ign");
  const int status = in_fresh_process("atomic write child - inherited SIG_IGN", dir);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 7);
  CHECK(names_in(dir) == std::vector<std::string>{"a.png", "b.png"});
}

TEST_CASE("atomic write child - write fig.png", "[.child]") {
  child_main([](const fs::path& dir) {
    write_image((dir / "fig.png").string(), noise(4, 4, 9));
    return 0;
  });
}

TEST_CASE("atomic write: temporaries left by killed processes are removed, those of live ones kept") {
  const auto dir = scratch_dir("stale");
  const pid_t dead = ::fork();
  REQUIRE(dead >= 0);
  if (dead == 0) ::_exit(0);
  REQUIRE(::waitpid(dead, nullptr, 0) == dead);  // a pid that no longer exists
  const std::string stale = temporary_name("fig.png", long(dead), 3);
  const std::string live = temporary_name("fig.png", long(::getppid()), 4);
  const std::string other = temporary_name("other.png", long(dead), 5);
  for (const auto& n : {stale, live, other}) std::ofstream(dir / n) << "partial";
  const int status = in_fresh_process("atomic write child - write fig.png", dir);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK_FALSE(fs::exists(dir / stale));
  CHECK(fs::exists(dir / live));
  CHECK(fs::exists(dir / other));  // another target's: left to that target's next write
  CHECK(fs::exists(dir / "fig.png"));
}

TEST_CASE("atomic write: a failed write names the path, in one line, and leaves nothing") {
  const auto dir = scratch_dir("failures");
  const Image im = noise(4, 4, 8);
  CHECK_THROWS_WITH(write_image((dir / "no" / "such" / "dir.png").string(), im),
                    Catch::StartsWith((dir / "no" / "such" / "dir.png").string() + ": "));
  CHECK_THROWS_WITH(write_image((dir / "x.bmp").string(), im), Catch::Contains("unsupported image format '.bmp'"));
  Image five(2, 2, 5);
  CHECK_THROWS_WITH(write_image((dir / "five.png").string(), five), Catch::Contains("1 to 4 channels"));
  Image wrong(2, 2, 4);
  wrong.pixels.resize(3);
  CHECK_THROWS_WITH(write_image((dir / "wrong.png").string(), wrong), Catch::Contains("wrong buffer size"));
  fs::create_directories(dir / "taken.png");  // the target is a directory: the rename fails
  CHECK_THROWS_WITH(write_image((dir / "taken.png").string(), im), Catch::Contains("taken.png"));
  CHECK(names_in(dir) == std::vector<std::string>{"taken.png"});
}
