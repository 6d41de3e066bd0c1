#pragma once
// Writing a figure in the formats splinefig knows: PNG and EXR (the rasterized scene), SVG and
// PDF (the scene itself, vector/). One rule of size for all (docs/figures.md, "Print and web
// sizes"): `scale` is the number of output pixels per spec pixel, `dpi` the number of spec
// pixels per inch. So a raster file has scale * dpi pixels per inch (PNG pHYs, EXR
// XResolution), a PDF page is canvas * 72 / dpi points, an SVG canvas * 96 / dpi CSS px.
#include <splinefig/figures/figure.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace splinefig::figures {

// A dpi or scale of a figure file outside [kMinDpi, kMaxDpi] (base/limits.hpp), alone or as
// their product.
struct FileOptionsError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

// The formats a figure is written in. A name ("png", any case) or a path's extension is read
// into one once, where it is given (the command line); the writers take the value.
enum class Format { png, exr, svg, pdf };
std::optional<Format> format_named(std::string_view name);
std::optional<Format> format_of_path(const std::string& path);  // by the extension
const char* extension(Format format);                          // "png", "exr", "svg", "pdf"

struct FigureFileOptions {
  double scale = 1;      // the scene's output pixels per spec pixel
  double dpi = 0;        // spec pixels per inch; 0: none written (vector files: 96, the CSS pixel)
  int threads = 0;       // rasterizer threads
  std::string software;  // "splinefig 1.2.3"
  std::string title;     // image description, SVG title, PDF title
  long long date = -1;   // PDF creation date (seconds since 1970), none when negative
  // Filled in when the figure is rasterized (PNG, EXR): how each item was resolved (exactly,
  // or bands of rows from its pieces within the scene's coverage tolerance).
  render::RasterReport* report = nullptr;
};

// Writes `fig` to `path` as `format`. `raster` caches the rasterized scene between calls for
// the same figure (PNG and EXR share it). Throws UnwritableFile naming the path,
// FileOptionsError for a dpi outside [kMinDpi, kMaxDpi] (base/limits.hpp).
void write_figure_file(const FigureScene& fig, const std::string& path, Format format,
                       const FigureFileOptions& options, std::optional<Image>& raster);

// The figure as the SVG text write_figure_file writes for Format::svg (the same checks of dpi
// and scale, the same throws but UnwritableFile).
std::string figure_svg(const FigureScene& fig, const FigureFileOptions& options);

// The title a figure's files carry (PNG description, SVG <title>, PDF Title): the figure's title
// with its markup resolved to plain text ("$a$ = 0.5" is "a = 0.5"), as a viewer's title bar
// shows it (no file stem), or the spec's name when it has no title.
std::string file_title(const FigureSpec& spec);

// SOURCE_DATE_EPOCH as seconds, or -1 when it is unset or not a number.
long long source_date_epoch();

}  // namespace splinefig::figures
