#pragma once
// Internal: labels measured as the painter sets them (rich_text.hpp), for the layout, which
// places every text before anything is drawn.
#include <splinefig/figures/spec.hpp>

#include <map>
#include <string>
#include <tuple>

namespace splinefig::figures::detail {

// The renderer's style of plain text in font `f` at `size` (its family Sans when unset).
render::TextStyle plain_style(double size, const Font& f, bool italic);
// Plain-text extent at an output size, in output pixels. Shaping is cached by the renderer;
// figures repeat their labels, so extents are cached here too.
render::TextExtent measure_plain(const std::string& text, double size, const Font& f, bool italic);

class TextMeasure {
 public:
  explicit TextMeasure(double scale, render::FontFamily family = render::FontFamily::Sans)
      : scale_(scale), family_(family) {}
  double scale() const { return scale_; }

  // Extent of a label (rich_text.hpp markup) in layout units, measured at 1x.
  render::TextExtent measure(const std::string& s, const Font& f) const;
  // The font with the figure's family where it names none.
  Font resolved(const Font& f) const;

 private:
  double scale_;
  render::FontFamily family_;
  mutable std::map<std::tuple<std::string, double, bool, int>, render::TextExtent> cache_;
};

}  // namespace splinefig::figures::detail
