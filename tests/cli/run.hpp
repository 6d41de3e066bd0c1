#pragma once
// Runs the splinefig executable (SPLINEFIG_EXE) as a user would: arguments, text on stdin;
// captures exit code, stdout and stderr through temporary files. Each run is limited to 300 s.
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>
#include <sys/wait.h>

namespace splinefig::test {

struct Run {
  int code = -1;
  std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// `stdout_path` replaces the captured stdout (e.g. "/dev/full" to make writing fail);
// `stdin_path` replaces `input` as stdin (e.g. "/dev/zero").
inline Run run(const std::vector<std::string>& args, const std::string& input = "",
               const std::string& stdout_path = "", const std::string& stdin_path = "") {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("splinefig-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "in", std::ios::binary) << input; }
  // A command that hangs fails its test (exit 124) instead of stalling the suite.
  std::string cmd = "timeout 300 " + shell_quote(SPLINEFIG_EXE);
  const std::string out = stdout_path.empty() ? (dir / "out").string() : stdout_path;
  for (const auto& a : args) cmd.append(" ").append(shell_quote(a));
  cmd.append(" < ").append(shell_quote(stdin_path.empty() ? (dir / "in").string() : stdin_path));
  cmd.append(" > ").append(shell_quote(out));
  cmd.append(" 2> ").append(shell_quote((dir / "err").string()));
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (stdout_path.empty()) r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

inline size_t count_lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace splinefig::test
