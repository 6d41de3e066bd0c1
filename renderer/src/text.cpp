#include "text.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace splinefig::render::detail {

std::string font_path(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  for (const char* dir : {"/usr/share/fonts/truetype/dejavu/", "/usr/share/fonts/TTF/", "/usr/share/fonts/dejavu/"}) {
    std::string p = std::string(dir) + name + ".ttf";
    if (std::filesystem::exists(p)) return p;
  }
  return name;  // let OpenImageIO search its font paths
}

namespace {
std::mutex& font_mutex() {  // FreeType state inside OpenImageIO is shared
  static std::mutex m;
  return m;
}
int pixel_size(double size) { return std::max(1, static_cast<int>(std::lround(size))); }
}  // namespace

TextMask text_mask(std::string_view text, Vec2 anchor, const TextStyle& style, int canvas_w, int canvas_h) {
  TextMask m;
  if (text.find_first_not_of(" \t\n") == std::string_view::npos) return m;  // no ink
  const int fs = pixel_size(style.size);
  const std::string font = font_path(style.font);
  std::lock_guard<std::mutex> lock(font_mutex());
  OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, fs, font);
  if (!r.defined()) throw std::runtime_error("text: font '" + style.font + "' could not be loaded");
  // Anchor alignment, from the ink box relative to the baseline origin.
  double ox = anchor.x, oy = anchor.y;
  const double w = r.xend - r.xbegin;
  if (style.halign == HAlign::Center) ox -= r.xbegin + 0.5 * w;
  else if (style.halign == HAlign::Right) ox -= r.xend;
  if (style.valign == VAlign::Top) oy -= r.ybegin;
  else if (style.valign == VAlign::Bottom) oy -= r.yend;
  else if (style.valign == VAlign::Middle) oy -= 0.5 * (r.ybegin + r.yend);
  const long x0 = std::lround(ox), y0 = std::lround(oy);
  // Mask over the ink box with one pixel of margin, clipped to the canvas.
  long bx0 = std::max<long>(0, x0 + r.xbegin - 1), by0 = std::max<long>(0, y0 + r.ybegin - 1);
  long bx1 = std::min<long>(canvas_w, x0 + r.xend + 1), by1 = std::min<long>(canvas_h, y0 + r.yend + 1);
  if (bx1 <= bx0 || by1 <= by0 || std::abs(x0) > (1L << 30) || std::abs(y0) > (1L << 30)) return m;
  OIIO::ImageSpec spec(static_cast<int>(bx1 - bx0), static_cast<int>(by1 - by0), 1, OIIO::TypeDesc::FLOAT);
  m.x = static_cast<int>(bx0);
  m.y = static_cast<int>(by0);
  m.width = spec.width;
  m.height = spec.height;
  m.coverage.assign(static_cast<std::size_t>(m.width) * m.height, 0.0f);
  // The glyphs are drawn straight into the zeroed mask, which the ImageBuf wraps.
  OIIO::ImageBuf buf(spec, m.coverage.data());
  const float white[1] = {1.0f};
  OIIO::ImageBufAlgo::render_text(buf, static_cast<int>(x0 - bx0), static_cast<int>(y0 - by0), text, fs, font, white);
  for (float& c : m.coverage) c = std::clamp(c, 0.0f, 1.0f);
  return m;
}

}  // namespace splinefig::render::detail

namespace splinefig::render {

TextExtent measure_text(std::string_view text, const TextStyle& style) {
  if (text.empty()) return TextExtent{};
  const std::string font = detail::font_path(style.font);
  std::lock_guard<std::mutex> lock(detail::font_mutex());
  OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, detail::pixel_size(style.size), font);
  if (!r.defined()) throw std::runtime_error("measure_text: font '" + style.font + "' could not be loaded");
  return TextExtent{static_cast<double>(r.xend - r.xbegin), static_cast<double>(-r.ybegin), static_cast<double>(r.yend)};
}

}  // namespace splinefig::render
