#pragma once
// Internal: a display list in layout units (1x pixels) that is scaled to the output size
// when it becomes one renderer scene; raster images are scene items like the rest. It
// measures labels as it sets them (text/measure.hpp).
#include "../naming.hpp"
#include "../text/measure.hpp"

#include <splinefig/figures/spec.hpp>
#include <splinefig/renderer/path.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace splinefig::figures::detail {

// A label (rich_text.hpp markup): set as runs when the list is scaled, at the output size.
struct TextOp {
  std::string text;
  Vec2 at;
  Font font;  // its family resolved
  TextAnchor anchor;
  double angle;  // degrees, counter-clockwise, about `at`
};
// A raster of the spec: read when the list is scaled (it becomes a render::ImageItem).
struct ImageOp {
  Raster raster;
  double x0, y0, x1, y1;  // target rectangle in layout units
};
// What the painter records: the renderer's drawing items (renderer.hpp) in layout units, and
// the figure's labels and rasters.
using Op = std::variant<render::StrokeItem, render::PathStrokeItem, render::FillItem, render::DiskItem, render::RingItem,
                        render::MarkerItem, TextOp, ImageOp>;

class Painter : public TextMeasure {
 public:
  explicit Painter(double scale, render::FontFamily family = render::FontFamily::Sans) : TextMeasure(scale, family) {}

  void stroke(std::vector<Vec2> pts, bool closed, const render::StrokeStyle& s, Color c);
  void stroke(render::Path path, const render::StrokeStyle& s, Color c);
  // A guide's line of horizontal and vertical segments (a spine, a tick, a grid line): in raster
  // output each segment's centre line moves onto the pixel grid (pixel centres for an odd width
  // in output pixels, pixel edges for an even one) and its ends onto pixel edges; vector output
  // keeps the exact positions.
  void hairline(std::vector<Vec2> pts, bool closed, const render::StrokeStyle& s, Color c);
  void fill(std::vector<std::vector<Vec2>> contours, render::FillRule rule, Color c);
  void circle(Vec2 centre, double r, std::optional<Color> fill, std::optional<Pen> stroke);
  void marker(render::Marker shape, Vec2 centre, double size, Color c);
  // A label (rich_text.hpp markup), aligned about `at` as a whole, then turned by `angle`
  // degrees counter-clockwise about `at` (90: reads upwards).
  void text(std::string s, Vec2 at, const Font& f, TextAnchor a, double angle = 0);
  void image(Raster r, double x0, double y0, double x1, double y1);

  const std::vector<Op>& ops() const { return ops_; }
  // Drops the ops from `n` on (a panel drawn again).
  void truncate(std::size_t n) {
    if (n < ops_.size()) ops_.resize(n), notes_.resize(n);
  }

  // "FILE:LINE: KEY" of the spec table whose drawing follows; every op records it, so that an
  // error found when the op is painted names that table.
  void set_origin(const SpecLocation& origin);
  const SpecLocation& origin_of(std::size_t op) const;
  // Whether the op is a hairline (snapped to the pixel grid in raster output).
  bool hairline_at(std::size_t op) const { return notes_[op].hairline; }

 private:
  void add(Op op, bool hairline = false);

  std::vector<Op> ops_;
  std::vector<SpecLocation> origins_{SpecLocation()};
  struct Note {
    std::uint32_t origin;  // index into origins_
    bool hairline;
  };
  std::vector<Note> notes_;  // per op
};

// Width and height of a raster in its own pixels (reads the file header if needed).
Vec2 raster_size(const Raster& r);


// The display list at the painter's scale as a scene of the given size (pixels).
// `snap`: the hairlines on the pixel grid (raster output).
render::Scene scene_of(const Painter& p, int width, int height, Color background, const Kernel& filter,
                       render::BlendSpace blend, double coverage_tolerance, bool snap = false);

}  // namespace splinefig::figures::detail
