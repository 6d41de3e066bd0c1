#pragma once
// Internal: text laid out as glyphs, each an outline in font units (cached per face and glyph)
// with its scale and pen position, in the text's own frame (pen origin at 0, y down).
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace splinefig::render::detail {

struct GlyphOutline {
  Path outline;                          // font units, y up, every contour closed
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;  // exact ink box (font units); empty: all 0
  bool empty = true;
};

struct PlacedGlyph {
  const GlyphOutline* glyph;  // owned by the font cache, never freed
  std::uint32_t id;           // glyph index in its face
  const void* face;           // identifies the face
  double x, y;                // pen position in pixels, text frame (y down)
  double scale;               // pixels per font unit
};

// A shaped glyph's place in the string: the byte where its cluster starts (HarfBuzz's cluster,
// in bytes of the whole text), its pen position and advance along the baseline, in pixels.
struct GlyphCluster {
  std::size_t byte;
  double x, advance;
};

struct TextLayout {
  std::vector<PlacedGlyph> glyphs;     // the inked glyphs
  std::vector<GlyphCluster> clusters;  // every shaped glyph, inked or not, in visual order
  double width = 0, ascent = 0, descent = 0;  // advance and ink extent, pixels
};

// Decodes, picks faces, shapes and places `text` at style.size (alignment and angle are not
// applied). Throws as text_path does.
TextLayout layout_text(std::string_view text, const TextStyle& style);

// Appends the layout's outlines to `out`, aligned about `anchor` and turned by style.angle.
void append_outlines(const TextLayout& layout, Vec2 anchor, const TextStyle& style, Path& out);

}  // namespace splinefig::render::detail
