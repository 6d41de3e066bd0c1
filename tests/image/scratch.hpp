#pragma once
// One scratch directory per test case (ctest runs them in parallel), removed when the test
// process exits.
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>
#include <unistd.h>

inline std::filesystem::path scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  struct Made {
    std::vector<fs::path> dirs;
    ~Made() {
      std::error_code ec;
      for (const fs::path& d : dirs) fs::remove_all(d, ec);
    }
  };
  static Made made;
  const fs::path d = fs::temp_directory_path() / ("splinefig-image-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  made.dirs.push_back(d);
  return d;
}
