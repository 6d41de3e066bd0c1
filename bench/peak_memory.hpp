#pragma once
// Peak memory a piece of work adds to a process, measured in a forked child so that it does
// not depend on what the benchmark process allocated before: the child resets its RSS high
// water mark (/proc/self/clear_refs, Linux >= 4.0), runs the work, and reports VmHWM minus the
// RSS it started from. Returns -1 when it cannot be measured (no /proc, fork failed).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>

namespace bench {

inline double proc_status_kb(const char* key) {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  double kb = -1;
  const std::size_t n = std::strlen(key);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, key, n) == 0 && line[n] == ':') kb = std::atof(line + n + 1);
  std::fclose(f);
  return kb;
}

// MB (2^20 bytes) that `work` adds to the RSS at its peak; `prepare` runs in the child before
// the high water mark is reset (to build the input without counting it).
inline double peak_added_mb(const std::function<void()>& prepare, const std::function<void()>& work) {
  int fd[2];
  if (pipe(fd) != 0) return -1;
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    close(fd[0]);
    double mb = -1;
    prepare();
    if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
      const bool reset = std::fputs("5", f) >= 0;
      if (std::fclose(f) == 0 && reset) {
        const double base = proc_status_kb("VmRSS");
        work();
        const double peak = proc_status_kb("VmHWM");
        if (base >= 0 && peak >= 0) mb = (peak - base) / 1024.0;
      }
    }
    ssize_t w = write(fd[1], &mb, sizeof mb);
    (void)w;
    _exit(0);
  }
  close(fd[1]);
  double mb = -1;
  if (read(fd[0], &mb, sizeof mb) != static_cast<ssize_t>(sizeof mb)) mb = -1;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return mb;
}

}  // namespace bench
