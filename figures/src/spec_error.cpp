// Where a spec says something, and the error naming it (spec.hpp).
#include <splinefig/figures/spec.hpp>

namespace splinefig::figures {

std::string SpecLocation::str() const {
  std::string s = file;
  if (line != 0) {
    s += ':';
    s += std::to_string(line);
  }
  if (!key.empty()) {
    s += ": ";
    s += key;
  }
  return s;
}

SpecFileError::SpecFileError(const std::string& message) : ErrorOf([&] {
  static constexpr char hex[] = "0123456789abcdef";
  std::string line;
  line.reserve(message.size());
  for (const char ch : message) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      line += "\\x";
      line += hex[c >> 4];
      line += hex[c & 15];
    } else {
      line += ch;
    }
  }
  return line;
}()) {}

}  // namespace splinefig::figures
