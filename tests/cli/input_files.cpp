// Inputs that are not files of text: a directory given as a spec or CSV, /dev/zero, a FIFO
// nobody writes to. Each is a one-line error naming the path, exit 2, nothing written, and no
// hang (run() gives up after 300 s, which fails the test).
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::count_lines;
using splinefig::test::run;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-inputs-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void check_fails(const std::vector<std::string>& args, const std::string& says, const std::string& stdin_path = "") {
  const auto r = run(args, "0,0\n1,1\n2,0\n3,1\n", "", stdin_path);
  INFO("splinefig " << args[0] << " " << args[1] << " (stdin " << stdin_path << ")\nstderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(says));
}

}  // namespace

TEST_CASE("render: a directory, /dev/zero or a FIFO as the spec is an error naming it") {
  const fs::path dir = scratch("render");
  const std::string out = (dir / "x.png").string();
  fs::create_directories(dir / "specs.toml");
  check_fails({"render", (dir / "specs.toml").string(), "-o", out}, (dir / "specs.toml").string() + ": is a directory");
  check_fails({"render", "/dev/zero", "-o", out}, "/dev/zero: not a regular file");
  const std::string fifo = (dir / "fifo.toml").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  check_fails({"render", fifo, "-o", out}, fifo + ": not a regular file");
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("eval and interp: /dev/zero or a directory on stdin, or as --betas, is an error") {
  const fs::path dir = scratch("csv");
  check_fails({"eval", "--basis", "bspline"}, "stdin line 1: a NUL byte: the input is not text", "/dev/zero");
  check_fails({"interp", "--output", "bspline"}, "stdin line 1: a NUL byte: the input is not text", "/dev/zero");
  check_fails({"eval", "--basis", "bspline"}, "cannot read stdin", dir.string());
  check_fails({"interp", "--output", "bspline"}, "cannot read stdin", dir.string());
  check_fails({"eval", "--basis", "beta", "--betas", "/dev/zero"}, "--betas /dev/zero: not a regular file");
  check_fails({"eval", "--basis", "beta", "--betas", dir.string()}, "--betas " + dir.string() + ": is a directory");
  const std::string fifo = (dir / "betas.csv").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  check_fails({"eval", "--basis", "beta", "--betas", fifo}, "--betas " + fifo + ": not a regular file");
  // A line of a megabyte and more without a newline is not CSV; it is refused, not buffered on.
  check_fails({"eval", "--basis", "bspline"}, "stdin line 1: longer than 1 MiB without a newline",
              [&] {
                const std::string big = (dir / "big").string();
                std::ofstream(big) << std::string((1 << 20) + 10, '1');
                return big;
              }());
  fs::remove_all(dir);
}
