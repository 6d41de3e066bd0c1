#pragma once
// A renderer Scene as a vector file: SVG (written directly) or PDF (Cairo's PDF surface), with
// the same size, colours (sRGB), z-order and geometry as the raster picture. Paths keep their
// cubic Beziers, so exact spline pieces stay exact; strokes use the format's own width, joins,
// caps, miter limit and dashes (both formats paint a stroke as one shape, the union of its
// pieces, as the rasterizer does); circles are circles; raster items are embedded as PNG at
// their own pixel size. See docs/vector.md.
#include <splinefig/base/error.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig::vector {

// A scene or option the vector writers cannot write: a dpi outside [kMinDpi, kMaxDpi], a raster
// item Cairo cannot hold as an image, or Cairo's own failure to make the PDF. The message names
// the value. (A scene item the renderer refuses stays its render::DrawError; a file that cannot
// be written is UnwritableFile.)
struct VectorError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

struct Options {
  // Pixels per inch of the scene's pixels (kMinDpi to kMaxDpi): the physical size is width/dpi inches. 0: the CSS
  // pixel (96 per inch). An SVG is width * 96 / dpi CSS px wide (its viewBox is the scene's
  // pixels), a PDF page width * 72 / dpi points.
  double dpi = 0;
  std::string title;    // SVG <title>, PDF Title
  std::string creator;  // PDF Creator ("splinefig 1.2.3")
  // PDF CreationDate as seconds since 1970 (SOURCE_DATE_EPOCH), or none when 0 or negative (never
  // the clock, never 1970): the same scene gives the same bytes.
  long long date = -1;
};

std::string to_svg(const render::Scene& scene, const Options& options = {});
std::vector<unsigned char> to_pdf(const render::Scene& scene, const Options& options = {});

enum class VectorFormat { svg, pdf };
// The format a path's extension names (.svg or .pdf, any case), if any.
std::optional<VectorFormat> vector_format_of(const std::string& path);
// True for a path ending in .svg or .pdf (any case).
inline bool is_vector_file(const std::string& path) { return vector_format_of(path).has_value(); }

// Text as XML character data or a quoted attribute value (&, <, >, " escaped; C0 controls but
// tab, newline and CR, and U+FFFE and U+FFFF, which XML 1.0 has no way to hold, as U+FFFD): for
// SVG, and for the HTML that shows it.
std::string xml_escape(std::string_view text);

// Writes to_svg or to_pdf, atomically (image/atomic_file.hpp). Throws UnwritableFile naming the
// path, VectorError for a dpi outside [kMinDpi, kMaxDpi] (base/limits.hpp).
void write_vector(const std::string& path, const render::Scene& scene, VectorFormat format, const Options& options = {});
// As above, in the format the extension names; UnwritableFile for another extension.
void write_vector(const std::string& path, const render::Scene& scene, const Options& options = {});

}  // namespace splinefig::vector
