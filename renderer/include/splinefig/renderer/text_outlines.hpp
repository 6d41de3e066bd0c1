#pragma once
// Text as glyph outlines: the exact geometry that Scene::text rasterizes, for writers that keep
// text as paths (SVG, PDF).
//
// A string is decoded from UTF-8, each character is given the first face of the fallback chain
// that has it (font_fallback below), runs of one face are shaped by HarfBuzz (kerning,
// ligatures, marks) in font units, and the glyphs' FreeType outlines (quadratic and cubic
// Beziers, unhinted) are scaled to the style's size and placed at the shaped positions with no
// rounding: the pen origin is wherever the anchor and alignment put it, to any fraction of a
// pixel. The outline is filled with the nonzero rule.
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace splinefig::render {

// The glyph outlines of `text` in canvas pixels (y down), placed as Scene::text draws them:
// aligned about `anchor` by style.halign/valign, then turned by style.angle about the anchor.
// Throws DrawError for invalid UTF-8 ("text: invalid UTF-8 at byte N") or a
// character that no DejaVu face has ("text: no DejaVu font has U+XXXX"), and
// std::runtime_error if the style's own font file is not installed.
Path text_path(std::string_view text, Vec2 anchor, const TextStyle& style);

// Where text_path puts each character, for writers that lay the string itself over the
// outlines (SVG's and PDF's invisible text layer, which makes labels searchable and
// selectable): the pen origin, the start of the baseline after alignment and turning, and each
// character's (code point's) place along the turned baseline. A character's place is its
// HarfBuzz cluster's pen position and advance; the characters of one cluster (a ligature, a
// base and its marks) share it in equal parts. Throws as text_path does.
struct PlacedChar {
  char32_t code;            // the code point
  std::size_t byte, bytes;  // where it is in the text (UTF-8)
  double x, advance;        // pen offset from the origin along the baseline, and advance (pixels)
};
struct TextPlacement {
  Vec2 origin;                           // canvas pixels
  double width = 0;                      // the shaped advance (measure_text's width)
  double ascent = 0, descent = 0;        // measure_text's ink extent
  std::vector<PlacedChar> chars;         // in the text's order
};
TextPlacement text_placement(std::string_view text, Vec2 anchor, const TextStyle& style);

// The DejaVu file name of a style's face, e.g. "DejaVuSerif-BoldItalic.ttf".
std::string font_file_name(FontFamily family, FontWeight weight, bool italic);

// The directories searched for font files, in order: share/splinefig/fonts next to the running
// program's bin/ (an installed or relocated tree), then /usr/share/fonts/truetype/dejavu.
std::vector<std::string> font_dirs();

// The full path of a font file name, or empty if no font directory has it.
std::string find_font(const std::string& file_name);

// The faces tried in order for a character: the style's own face, the same family without
// the italic, then without the bold, then DejaVu Sans, Serif, Sans Mono (each in the style's
// weight and slant first) and DejaVu Math TeX Gyre. Only installed files are listed.
std::vector<std::string> font_fallback(const TextStyle& style);

}  // namespace splinefig::render
