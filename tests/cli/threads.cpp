// --threads: a count beyond the documented maximum (256) is clamped, and threads the system
// refuses to create (RLIMIT_NPROC, set in a child process) leave the work to the threads that
// started: same bytes as one thread, exit 0, never std::terminate. The child runs as user
// nobody (RLIMIT_NPROC does not bind root); without root and setpriv the test is skipped.
#include "skip.hpp"
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::run;
using splinefig::test::shell_quote;
using splinefig::test::slurp;

namespace {

const std::string exe = SPLINEFIG_EXE;
const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bbasis.toml";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-threads-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::all);  // writable by the unprivileged user below
  return dir;
}

// Runs `command` (a shell command line) as user nobody with at most `nproc` processes and
// threads for that user; the exit code (-1 if killed after `seconds`: SIGKILL, since a process
// stuck loading OpenImageIO with its signals blocked by the atomic writer would not see SIGTERM).
// Waits (up to 10 s) until no process of user nobody is left: RLIMIT_NPROC counts all of the
// user's processes, and one killed by a probe's timeout counts until it is reaped.
void wait_until_nobody_runs() {
  for (int i = 0; i < 100; ++i) {
    bool found = false;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator("/proc", ec)) {
      std::ifstream status(e.path() / "status");
      for (std::string line; std::getline(status, line);)
        if (line.rfind("Uid:", 0) == 0) {
          std::istringstream uids(line.substr(4));
          int real = -1;
          uids >> real;
          found = found || real == 65534;
          break;
        }
      if (found) break;
    }
    if (!found) return;
    ::usleep(100000);
  }
}

int run_limited(const std::string& command, int nproc, int seconds = 300) {
  wait_until_nobody_runs();
  const std::string inner = "ulimit -u " + std::to_string(nproc) + " && exec " + command + " 2>/dev/null";
  const std::string cmd = "timeout -s KILL " + std::to_string(seconds) + " setpriv --reuid=65534 --regid=65534 --clear-groups bash -c " + shell_quote(inner);
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The smallest limit under which `command` runs with one thread of its own (the libraries
// start a few), or 0 if there is none up to 64. Below it, a library that OpenImageIO loads
// (log4cplus, whose static initializer starts a thread pool) can wait forever for a thread the
// system refused, so each probe is given a short time.
int baseline_nproc(const std::string& command) {
  for (int n = 2; n <= 64; ++n)
    if (run_limited(command, n, 8) == 0) return n;
  return 0;
}

bool can_limit_threads() {
  return ::geteuid() == 0 && std::system("command -v setpriv >/dev/null 2>&1 && command -v bash >/dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE("resample and render: --threads beyond 256 is clamped and gives the bytes of one thread") {
  const fs::path dir = scratch("clamp");
  const std::string png = (dir / "in.png").string();
  REQUIRE(run({"render", spec, "-o", png, "--threads", "1"}).code == 0);
  auto r = run({"resample", png, "-o", (dir / "one.png").string(), "--filter", "catmull-rom", "--scale", "0.5",
                "--threads", "1"});
  REQUIRE(r.code == 0);
  r = run({"resample", png, "-o", (dir / "many.png").string(), "--filter", "catmull-rom", "--scale", "0.5",
           "--threads", "536870912"});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK((slurp(dir / "many.png") == slurp(dir / "one.png")));
  r = run({"render", spec, "-o", (dir / "many-render.png").string(), "--threads", "2147483647"});
  CHECK(r.code == 0);
  CHECK((slurp(dir / "many-render.png") == slurp(png)));
  CHECK(run({"figures", "--threads", "-1"}).code == 2);
  fs::remove_all(dir);
}

TEST_CASE("threads the system refuses: render, resample and figures run with the threads that started") {
  if (!can_limit_threads()) {
    splinefig::testing_support::skip("needs root and setpriv to run a child as nobody under RLIMIT_NPROC");
    return;
  }
  const fs::path dir = scratch("nproc");
  const std::string png = (dir / "in.png").string();
  REQUIRE(run({"render", spec, "-o", png, "--threads", "1"}).code == 0);
  fs::permissions(png, fs::perms::all);
  const std::string q = shell_quote(exe);

  const std::string render1 = q + " render " + shell_quote(spec) + " -o " + shell_quote((dir / "r1.png").string());
  const int base = baseline_nproc(render1 + " --threads 1");
  REQUIRE(base > 0);
  // Two threads more than one thread needs: most of the 256 cannot start.
  CHECK(run_limited(q + " render " + shell_quote(spec) + " -o " + shell_quote((dir / "r.png").string()) +
                        " --threads 256", base + 2) == 0);
  CHECK((slurp(dir / "r.png") == slurp(png)));
  CHECK(run_limited(q + " render " + shell_quote(spec) + " -o " + shell_quote((dir / "r0.png").string()) +
                        " --threads 256", base) == 0);  // none of them
  CHECK((slurp(dir / "r0.png") == slurp(png)));

  const std::string resample = q + " resample " + shell_quote(png) + " --filter catmull-rom --scale 0.5 -o ";
  REQUIRE(run({"resample", png, "-o", (dir / "s1.png").string(), "--filter", "catmull-rom", "--scale", "0.5",
               "--threads", "1"}).code == 0);
  const int rbase = baseline_nproc(resample + shell_quote((dir / "s0.png").string()) + " --threads 1");
  REQUIRE(rbase > 0);
  CHECK(run_limited(resample + shell_quote((dir / "s.png").string()) + " --threads 256", rbase + 2) == 0);
  CHECK((slurp(dir / "s.png") == slurp(dir / "s1.png")));

  fs::create_directories(dir / "specs");
  for (const char* name : {"one", "two", "three", "four", "five"})
    std::ofstream(dir / "specs" / (std::string(name) + ".toml"))
        << "title = \"" << name << "\"\n[canvas]\nwidth = 64\nheight = 48\n[[polyline]]\npoints = [[4, 4], [60, 44]]\n";
  const std::string figures = q + " figures --specs " + shell_quote((dir / "specs").string()) + " --out ";
  fs::create_directories(dir / "f1");
  fs::create_directories(dir / "f");
  fs::permissions(dir / "f1", fs::perms::all);
  fs::permissions(dir / "f", fs::perms::all);
  const int fbase = baseline_nproc(figures + shell_quote((dir / "f1").string()) + " --threads 1 >/dev/null");
  REQUIRE(fbase > 0);
  // The workers that start render every figure: text is drawn by the library's own outlines
  // and OpenImageIO (with the thread its logging library starts) is loaded before the workers,
  // so no library needs a thread the system refuses once the run has begun.
  const int code = run_limited(figures + shell_quote((dir / "f").string()) + " --threads 256 >/dev/null", fbase + 1);
  CHECK(code == 0);
  for (const char* name : {"one", "two", "three", "four", "five"}) {
    INFO(name);
    CHECK((slurp(dir / "f" / (std::string(name) + ".png")) == slurp(dir / "f1" / (std::string(name) + ".png"))));
  }
  fs::remove_all(dir);
}
