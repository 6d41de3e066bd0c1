// A figure's files: rasterized once for PNG and EXR, written as vectors for SVG and PDF.
#include <splinefig/figures/output.hpp>

#include <splinefig/image/io.hpp>
#include <splinefig/vector/vector.hpp>

#include <cstdlib>
#include <stdexcept>

namespace splinefig::figures {

bool is_figure_format(const std::string& ext) { return ext == "png" || ext == "exr" || ext == "svg" || ext == "pdf"; }

void write_figure_file(const FigureScene& fig, const std::string& path, const std::string& format,
                       const FigureFileOptions& o, std::optional<Image>& raster) {
  if (o.dpi != 0 && !(o.dpi >= kMinDpi && o.dpi <= kMaxDpi))
    throw std::invalid_argument("dpi " + std::to_string(o.dpi) + " is outside [1, 10000]");
  if (format == "svg" || format == "pdf") {
    vector::Options v;
    v.dpi = (o.dpi > 0 ? o.dpi : 96.0) * o.scale;
    v.title = o.title;
    v.creator = o.software;
    v.date = o.date;
    vector::write_vector(path, fig.scene, v);
    return;
  }
  if (format != "png" && format != "exr") throw UnwritableFile(path + ": unknown format '" + format + "'");
  if (!raster) raster = render::rasterize(fig.scene, o.threads);
  WriteOptions w;
  w.software = o.software;
  w.description = o.title;
  w.dpi = o.dpi > 0 ? o.dpi * o.scale : 0;
  w.date = o.date;
  write_image(path, *raster, w);
}

long long source_date_epoch() {
  const char* s = std::getenv("SOURCE_DATE_EPOCH");
  if (!s || !*s) return -1;
  char* end = nullptr;
  const long long v = std::strtoll(s, &end, 10);
  return (*end == '\0' && v >= 0) ? v : -1;
}

}  // namespace splinefig::figures
