#pragma once
// OpenImageIO's error text can span lines; messages here are one line.
#include <string>

namespace splinefig::detail {

inline std::string one_line(std::string s) {
  for (auto& ch : s)
    if (ch == '\n' || ch == '\r' || ch == '\t') ch = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace splinefig::detail
