#include <splinefig/base/extension.hpp>
#include <splinefig/image/atomic_file.hpp>
#include <splinefig/vector/vector.hpp>

#include <cstdio>

namespace splinefig::vector {

std::optional<VectorFormat> vector_format_of(const std::string& path) {
  const std::string e = lower_extension(path);
  if (e == "svg") return VectorFormat::svg;
  if (e == "pdf") return VectorFormat::pdf;
  return std::nullopt;
}

void write_vector(const std::string& path, const render::Scene& scene, VectorFormat format, const Options& o) {
  if (o.dpi != 0 && !(o.dpi >= kMinDpi && o.dpi <= kMaxDpi)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "dpi %g is outside [%g, %g]", o.dpi, kMinDpi, kMaxDpi);
    throw VectorError(buf);
  }
  if (format == VectorFormat::svg) {
    const std::string s = to_svg(scene, o);
    write_file_atomically(path, {reinterpret_cast<const unsigned char*>(s.data()), s.size()});
  } else {
    const std::vector<unsigned char> b = to_pdf(scene, o);
    write_file_atomically(path, b);
  }
}

void write_vector(const std::string& path, const render::Scene& scene, const Options& o) {
  const auto format = vector_format_of(path);
  if (!format) throw UnwritableFile(path + ": not a vector format (the extension must be .svg or .pdf)");
  write_vector(path, scene, *format, o);
}

}  // namespace splinefig::vector
