#pragma once
// One scratch directory per test case (ctest runs them in parallel).
#include <filesystem>
#include <string>
#include <unistd.h>

inline std::filesystem::path scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / ("splinefig-image-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
