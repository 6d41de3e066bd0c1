#pragma once
// The hostile-input suite's helpers: every case runs the splinefig executable in a scratch
// directory under a hard time limit (SIGKILL), so that a hang fails its test instead of
// stalling the suite. Spec files are written there under their own name, so that messages
// read "NAME.toml:LINE: KEY: ...".
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace splinefig::hostile {

namespace fs = std::filesystem;

// Generous: each case takes well under a second in a Release build; sanitizer builds are
// about ten times slower. A case that runs into the limit is a hang.
inline constexpr int kTimeLimit = 60;

struct Outcome {
  int code = -1;
  bool killed = false;  // ran into the time limit
  double seconds = 0;
  std::string out, err;
};

inline fs::path scratch() {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() /
                       ("splinefig-hostile-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

// Runs `splinefig ARGS` in `dir` with stdin from `stdin_path` (default: empty).
inline Outcome run_in(const fs::path& dir, const std::vector<std::string>& args, int limit = kTimeLimit,
                      const std::string& stdin_path = "/dev/null") {
  using test::shell_quote;
  std::string cmd = "cd " + shell_quote(dir.string()) + " && timeout -s KILL " + std::to_string(limit) + " " +
                    shell_quote(SPLINEFIG_EXE);
  for (const auto& a : args) cmd += ' ' + shell_quote(a);
  cmd += " < " + shell_quote(stdin_path) + " > " + shell_quote((dir / ".out").string()) + " 2> " +
         shell_quote((dir / ".err").string());
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  Outcome o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.killed = o.code == 137 || o.code == 124;
  o.out = test::slurp(dir / ".out");
  o.err = test::slurp(dir / ".err");
  return o;
}

// Renders spec `text` as NAME.toml; the outcome, with the PNG's existence checked by callers.
inline Outcome render_spec(const fs::path& dir, const std::string& name, const std::string& text,
                           const std::vector<std::string>& extra = {}) {
  write_file(dir / (name + ".toml"), text);
  std::vector<std::string> args{"render", name + ".toml", "-o", name + ".png"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_in(dir, args);
}

// The spec is refused in time: exit 2, one line on stderr that starts "splinefig render: " and
// contains `says` (its "NAME.toml:LINE: KEY" part included), and no image written.
inline void check_refused(const std::string& name, const std::string& text, const std::string& says,
                          const std::vector<std::string>& extra = {}) {
  const fs::path dir = scratch();
  const Outcome o = render_spec(dir, name, text, extra);
  INFO(name << ".toml (" << o.seconds << " s): " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 2);
  CHECK(test::count_lines(o.err) == 1);
  CHECK_THAT(o.err, Catch::StartsWith("splinefig render: ") && Catch::Contains(says));
  CHECK_FALSE(fs::exists(dir / (name + ".png")));
  fs::remove_all(dir);
}

// The spec renders in time, with nothing on stderr.
inline void check_renders(const std::string& name, const std::string& text, const std::vector<std::string>& extra = {}) {
  const fs::path dir = scratch();
  const Outcome o = render_spec(dir, name, text, extra);
  INFO(name << ".toml (" << o.seconds << " s): " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 0);
  CHECK(o.err.empty());
  CHECK(fs::exists(dir / (name + ".png")));
  fs::remove_all(dir);
}

}  // namespace splinefig::hostile
