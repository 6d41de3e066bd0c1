// A figure's files: rasterized once for PNG and EXR, written as vectors for SVG and PDF.
#include <splinefig/figures/output.hpp>

#include "text/rich_text.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/vector/vector.hpp>

#include <splinefig/base/extension.hpp>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace splinefig::figures {

std::optional<Format> format_named(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  for (Format f : {Format::png, Format::exr, Format::svg, Format::pdf})
    if (n == extension(f)) return f;
  return std::nullopt;
}

std::optional<Format> format_of_path(const std::string& path) {
  const std::string e = lower_extension(path);
  return e.empty() ? std::nullopt : format_named(e);
}

const char* extension(Format format) {
  switch (format) {
    case Format::png: return "png";
    case Format::exr: return "exr";
    case Format::svg: return "svg";
    case Format::pdf: return "pdf";
  }
  return "";
}

namespace {

// The dpi and scale checks of write_figure_file.
void check_dpi(Format format, const FigureFileOptions& o) {
  if (o.dpi != 0 && !(o.dpi >= kMinDpi && o.dpi <= kMaxDpi)) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "dpi %g is outside [%g, %g]", o.dpi, kMinDpi, kMaxDpi);
    throw FileOptionsError(buf);
  }
  // The file holds dpi x scale (the figure keeps its printed size at any scale): that is what
  // the limit bounds, for rasters and vectors alike (a vector without --dpi takes 96).
  const double file_dpi = (o.dpi > 0 ? o.dpi : (format == Format::svg || format == Format::pdf ? 96.0 : 0.0)) * o.scale;
  if (file_dpi != 0 && !(file_dpi >= kMinDpi && file_dpi <= kMaxDpi)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "dpi %g at scale %g is %g dots per inch in the file, outside [%g, %g]",
                  o.dpi > 0 ? o.dpi : 96.0, o.scale, file_dpi, kMinDpi, kMaxDpi);
    throw FileOptionsError(buf);
  }
}

vector::Options vector_options(const FigureFileOptions& o) {
  vector::Options v;
  v.dpi = (o.dpi > 0 ? o.dpi : 96.0) * o.scale;
  v.title = o.title;
  v.creator = o.software;
  v.date = o.date;
  return v;
}

}  // namespace

std::string figure_svg(const FigureScene& fig, const FigureFileOptions& o) {
  check_dpi(Format::svg, o);
  return vector::to_svg(fig.scene, vector_options(o));
}

// Plain text: the title's markup resolved ("$a$ = 0.5" is "a = 0.5"), as index.json has it. A
// reader sees it (a viewer's title bar, a browser's tab), so the file stem is no part of it.
std::string file_title(const FigureSpec& spec) {
  return spec.title.empty() ? spec.name : detail::plain_text(spec.title);
}

void write_figure_file(const FigureScene& fig, const std::string& path, Format format, const FigureFileOptions& o,
                       std::optional<Image>& raster) {
  check_dpi(format, o);
  if (format == Format::svg || format == Format::pdf) {
    const vector::Options v = vector_options(o);
    vector::write_vector(path, fig.scene, format == Format::svg ? vector::VectorFormat::svg : vector::VectorFormat::pdf, v);
    return;
  }
  if (!raster) raster = render::rasterize(fig.raster, o.threads, o.report);
  WriteOptions w;
  w.software = o.software;
  w.description = o.title;
  w.dpi = o.dpi > 0 ? o.dpi * o.scale : 0;
  w.date = o.date;
  write_image(path, *raster, format == Format::png ? ImageFormat::png : ImageFormat::exr, w);
}

long long source_date_epoch() {
  const char* s = std::getenv("SOURCE_DATE_EPOCH");
  if (!s || !*s) return -1;
  char* end = nullptr;
  const long long v = std::strtoll(s, &end, 10);
  return (*end == '\0' && v >= 0) ? v : -1;
}

}  // namespace splinefig::figures
