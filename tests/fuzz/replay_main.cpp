// Replays a fuzz corpus through one harness's LLVMFuzzerTestOneInput without libFuzzer, so that
// the ordinary test build (GCC, ctest "fuzz-replay:<harness>") runs every corpus file on every
// change: `fuzz_replay_<harness> DIR_OR_FILE...`. Files are run in name order, each once. It
// fails (non-zero exit, naming the file) when the harness reports a finding (abort), crashes, or
// lets an exception escape, and when it was given no file at all (an empty or missing corpus
// would otherwise pass without running anything).
#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

char g_current[4096] = "";  // the file being replayed, for the signal handler

void say(const char* s) {
  if (::write(2, s, std::strlen(s)) < 0) return;
}

extern "C" void on_fatal_signal(int sig) {
  say("fuzz-replay: ");
  say(g_current);
  say(": ");
  say(sig == SIGABRT ? "the harness aborted (a finding)" : "the harness crashed");
  say(" (signal ");
  char num[16];
  int n = sig, i = 15;
  num[i] = '\0';
  do num[--i] = char('0' + n % 10), n /= 10;
  while (n > 0 && i > 0);
  say(num + i);
  say(")\n");
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

int main(int argc, char** argv) {
  for (int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_fatal_signal);
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p = argv[i];
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> in_dir;
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) in_dir.push_back(e.path());
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else if (fs::is_regular_file(p, ec)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "fuzz-replay: %s: neither a corpus directory nor a file\n", p.c_str());
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "fuzz-replay: no corpus file to replay\n");
    return 2;
  }
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof()) {
      std::fprintf(stderr, "fuzz-replay: %s: cannot be read\n", f.c_str());
      return 2;
    }
    std::snprintf(g_current, sizeof g_current, "%s", f.c_str());
    // libFuzzer hands the harness a buffer of exactly the input's size; an empty input is a
    // non-null pointer with size 0.
    std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
    data.reserve(1);
    try {
      (void)LLVMFuzzerTestOneInput(data.data(), data.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz-replay: %s: an exception escaped the harness: %s\n", f.c_str(), e.what());
      return 1;
    } catch (...) {
      std::fprintf(stderr, "fuzz-replay: %s: an exception of unknown type escaped the harness\n", f.c_str());
      return 1;
    }
  }
  std::printf("fuzz-replay: %zu corpus files, none a finding\n", files.size());
  return 0;
}
