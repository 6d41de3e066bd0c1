#pragma once
// A file name's extension as the format choosers read it: lower-cased, without the dot, "" for
// none ("A.SVG" -> "svg", "dir.d/file" -> "", ".png" -> "": a hidden file, as std::filesystem).
#include <filesystem>
#include <string>

namespace splinefig {

inline std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  if (!e.empty()) e.erase(0, 1);
  for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e;
}

}  // namespace splinefig
