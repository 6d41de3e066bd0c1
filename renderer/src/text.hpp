#pragma once
// Text through OpenImageIO's render_text (FreeType) with DejaVu Sans: glyph coverage masks at
// integer pixel positions, composited like any other item.
#include <splinefig/renderer/renderer.hpp>

#include <vector>

namespace splinefig::render::detail {

struct TextMask {
  int x = 0, y = 0, width = 0, height = 0;  // canvas position of the mask's top-left pixel
  std::vector<float> coverage;              // row-major, in [0, 1]
};

// The font file for a font name: a path is used as given; "DejaVuSans" and other DejaVu names
// resolve to fonts-dejavu-core's files.
std::string font_path(const std::string& name);

TextMask text_mask(std::string_view text, Vec2 anchor, const TextStyle& style, int canvas_w, int canvas_h);

}  // namespace splinefig::render::detail
