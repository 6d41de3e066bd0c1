#include <splinefig/image/atomic_file.hpp>
#include <splinefig/vector/vector.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace splinefig::vector {
namespace {
std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}
}  // namespace

bool is_vector_file(const std::string& path) {
  const std::string e = lower_extension(path);
  return e == "svg" || e == "pdf";
}

void write_vector(const std::string& path, const render::Scene& scene, const Options& o) {
  if (o.dpi != 0 && !(o.dpi >= kMinDpi && o.dpi <= kMaxDpi))
    throw std::invalid_argument("dpi " + std::to_string(o.dpi) + " is outside [1, 10000]");
  const std::string e = lower_extension(path);
  if (e == "svg") {
    const std::string s = to_svg(scene, o);
    write_file_atomically(path, {reinterpret_cast<const unsigned char*>(s.data()), s.size()});
  } else if (e == "pdf") {
    const std::vector<unsigned char> b = to_pdf(scene, o);
    write_file_atomically(path, b);
  } else {
    throw UnwritableFile(path + ": not a vector format (the extension must be .svg or .pdf)");
  }
}

}  // namespace splinefig::vector
