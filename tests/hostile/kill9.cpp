// Atomic writes under kill -9: a real `splinefig figures --scale 4` killed with SIGKILL while it
// writes its PNG leaves no partial target (the previous output is intact, byte for byte), only
// a temporary file with an obvious name (".NAME.splinefig-PID-N.tmp"), which the next run that
// writes the same target removes.
#include "hostile.hpp"

#include <csignal>
#include <thread>
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

}  // namespace

TEST_CASE("figures killed with SIGKILL mid-write leaves the previous output intact and a named temporary file") {
  const fs::path dir = scratch();
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bbasis.toml";
  const std::string specs_dir = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";
  REQUIRE(run_in(dir, {"figures", "--specs", specs_dir, "--out", ".", "--only", "bbasis"}).code == 0);
  const std::string good = splinefig::test::slurp(dir / "bbasis.png");
  REQUIRE(good.size() > 1000);

  bool caught = false;
  for (int attempt = 0; attempt < 10 && !caught; ++attempt) {
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      if (::chdir(dir.c_str()) != 0) ::_exit(127);
      ::execl(SPLINEFIG_EXE, SPLINEFIG_EXE, "figures", "--specs", specs_dir.c_str(), "--out", ".", "--only", "bbasis",
              "--scale", "4", "--threads", "1", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    int status = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(kTimeLimit)) {
      if (!temporaries(dir, "bbasis.png").empty()) {
        ::kill(pid, SIGKILL);
        caught = true;
        break;
      }
      if (::waitpid(pid, &status, WNOHANG) == pid) break;  // finished before it was caught
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (!caught) ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  REQUIRE(caught);
  // The target is the previous run's file, not a partial one.
  CHECK(splinefig::test::slurp(dir / "bbasis.png") == good);
  CHECK(temporaries(dir, "bbasis.png").size() == 1);
  // The next run over the same target removes the dead process's temporary file.
  REQUIRE(run_in(dir, {"figures", "--specs", specs_dir, "--out", ".", "--only", "bbasis"}).code == 0);
  CHECK(temporaries(dir, "bbasis.png").empty());
  CHECK(splinefig::test::slurp(dir / "bbasis.png") == good);
  fs::remove_all(dir);
}
