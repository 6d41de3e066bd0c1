// Inputs that are not files of text: a directory given as a spec or CSV, /dev/zero, a FIFO
// nobody writes to. Each is a one-line error naming the path, exit 2, nothing written, and no
// hang (run() gives up after 300 s, which fails the test). A file that is missing or that the
// user may not read is said as such, with the system's reason, by every command that reads one.
#include "cli/run.hpp"

#include "skip.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::count_lines;
using splinefig::test::run;
using splinefig::test::shell_quote;
using splinefig::test::slurp;

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

namespace {

// Runs splinefig with `args` in `dir` as an unprivileged user: as is when not root, as user nobody
// (setpriv) when root, for whom no file is unreadable. Exit code and stderr.
splinefig::test::Run run_unprivileged(const std::vector<std::string>& args, const fs::path& dir) {
  // Built by appends (a literal plus a string is a -Wrestrict false positive of GCC 12 at -O3).
  std::string cmd = "cd ";
  cmd.append(shell_quote(dir.string())).append(" && ");
  if (::geteuid() == 0) cmd.append("setpriv --reuid=65534 --regid=65534 --clear-groups ");
  cmd.append("timeout 300 ").append(shell_quote(SPLINEFIG_EXE));
  for (const auto& a : args) cmd.append(" ").append(shell_quote(a));
  cmd.append(" < /dev/null > /dev/null 2> ").append(shell_quote((dir / "err").string()));
  const int status = std::system(cmd.c_str());
  splinefig::test::Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(dir / "err");
  fs::remove(dir / "err");
  return r;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Each command that reads a file, with FILE where the file goes.
const std::vector<std::vector<std::string>> kReaders = {
    {"render", "FILE", "-o", "out.png"},
    {"resample", "FILE", "-o", "out.png", "--scale", "2", "--filter", "bspline"},
    {"diff", "FILE", "FILE"},
    {"eval", "FILE", "--basis", "bspline"},
    {"kernel", "FILE", "--basis", "bspline"},
    {"interp", "FILE"},
};

std::vector<std::string> with_file(std::vector<std::string> args, const std::string& file) {
  std::replace(args.begin(), args.end(), std::string("FILE"), file);
  return args;
}

std::string input_for(const std::string& command) {
  return command == "render" ? "spec.toml" : command == "resample" || command == "diff" ? "image.png" : "points.csv";
}

}  // namespace

TEST_CASE("input files: a missing or unreadable input is said as such, with the reason, by every command") {
  const fs::path dir = scratch("access");
  fs::permissions(dir, fs::perms::all);  // searchable and writable by the unprivileged user
  fs::copy_file(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/bias.toml", dir / "spec.toml");
  fs::copy_file(std::string(SPLINEFIG_SOURCE_DIR) + "/tests/reference/renderer/fills.png", dir / "image.png");
  std::ofstream(dir / "points.csv") << "x,y\n0,0\n1,1\n2,0\n3,1\n";
  for (const auto& args : kReaders) {
    const std::string name = std::string("nosuch-").append(input_for(args[0]));
    const auto r = run(with_file(args, (dir / name).string()));
    const int code = args[0] == "diff" ? 4 : 2;  // diff: idiff's code for a file it could not read
    INFO("splinefig " << args[0] << " " << name << "\nstderr: " << r.err);
    CHECK(r.code == code);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::StartsWith(std::string("splinefig ").append(args[0]).append(": ")));
    CHECK_THAT(r.err, Catch::Contains((dir / name).string()));
    CHECK_THAT(lower(r.err), Catch::Contains("no such file"));
  }
  if (::geteuid() == 0 && std::system("command -v setpriv > /dev/null 2>&1") != 0) {
    splinefig::testing_support::skip("root without setpriv cannot make a file unreadable to itself");
  } else {
    for (const char* f : {"spec.toml", "image.png", "points.csv"}) fs::permissions(dir / f, fs::perms::none);
    for (const auto& args : kReaders) {
      const std::string name = input_for(args[0]);
      const auto r = run_unprivileged(with_file(args, name), dir);
      const int code = args[0] == "diff" ? 4 : 2;
      INFO("splinefig " << args[0] << " " << name << " (mode 000)\nstderr: " << r.err);
      CHECK(r.code == code);
      CHECK(count_lines(r.err) == 1);
      CHECK_THAT(r.err, Catch::StartsWith(std::string("splinefig ").append(args[0]).append(": ")));
      CHECK_THAT(r.err, Catch::Contains(name));
      CHECK_THAT(r.err, Catch::Contains("(Permission denied)"));
    }
    CHECK_FALSE(fs::exists(dir / "out.png"));
  }
  fs::remove_all(dir);
}
