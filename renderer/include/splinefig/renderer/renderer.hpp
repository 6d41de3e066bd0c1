#pragma once
// splinefig's renderer: exact-area antialiased drawing into linear-light float images.
// No spline knowledge here. Geometry (paths, strokes, dashes) -> coverage -> pixels.
//
// Conventions (docs/conventions.md): (0,0) is the top-left corner of the top-left pixel, y down, pixel (i,j) has
// centre (i+0.5, j+0.5). Colours are linear-light RGBA with straight alpha at the API; the
// image (splinefig::Image, image/image.hpp) holds premultiplied linear RGBA float32,
// composited with Porter-Duff over. A stroke is the union of its pieces: one path never blends with itself.
#include <splinefig/base/error.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/image/image.hpp>
#include <splinefig/kernel/kernel.hpp>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace splinefig::render {

// Something the renderer is asked to draw that cannot be drawn: a bad size, radius, style, dash
// list, pixel filter or text (invalid UTF-8, a character no font has), or a flattening
// tolerance that is not positive. The message names the item and the value.
struct DrawError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

struct Vec2 {
  double x = 0, y = 0;
};

struct Color {  // linear light, straight alpha
  float r = 0, g = 0, b = 0, a = 1;
};
// "#rrggbb" or "#rrggbbaa" (sRGB) -> linear; nullopt if it is not such a string.
std::optional<Color> parse_hex_color(std::string_view hex);

// The values Porter-Duff over is computed in (compositor.hpp). Linear light is physically right
// and the default; sRGB blends the encoded values, as AGG, browsers and most 2-D libraries do, so
// that a PNG matches what they draw. rasterize() returns the canvas in its blend space's encoding
// (Image::encoding: linear, or srgb with associated alpha); to_linear() (image/srgb.hpp) gives the
// linear form.
enum class BlendSpace { linear, srgb };

enum class Join { Miter, Round, Bevel };
enum class Cap { Butt, Round, Square };
enum class FillRule { NonZero, EvenOdd };

// A dash pattern, checked and normalised once, where it is made: on/off lengths in pixels, each
// finite, >= 0 and at most kMaxCoordinate, with a period (their sum) of at least kMinDashPeriod;
// an odd list is repeated to an even one, as SVG does. Empty: a solid stroke. A bad list throws
// DrawError naming the length or the period, so a pattern that exists is valid.
class DashPattern {
 public:
  DashPattern() = default;
  DashPattern(std::initializer_list<double> lengths) : DashPattern(std::vector<double>(lengths)) {}
  explicit DashPattern(std::vector<double> lengths);

  bool empty() const { return lengths_.empty(); }
  std::size_t size() const { return lengths_.size(); }  // even
  double operator[](std::size_t i) const { return lengths_[i]; }
  const double* data() const { return lengths_.data(); }
  std::vector<double>::const_iterator begin() const { return lengths_.begin(); }
  std::vector<double>::const_iterator end() const { return lengths_.end(); }
  double period() const { return period_; }  // 0 when empty
  // Every length times s > 0 (the same pattern at another scale); throws as the constructor does.
  DashPattern scaled(double s) const;
  bool operator==(const DashPattern&) const = default;

 private:
  std::vector<double> lengths_;
  double period_ = 0;
};

// Pieces as in SVG 2: a round join is the circular sector between the outer corners.
struct StrokeStyle {
  double width = 1.0;
  Join join = Join::Miter;
  double miter_limit = 4.0;  // SVG semantics: miter length / width above this -> bevel
  Cap cap = Cap::Butt;
  DashPattern dashes;  // empty = solid
  double dash_offset = 0.0;
};

// The pixel filter is a separable k(x) k(y) with k a piecewise-polynomial Kernel
// (kernel/kernel.hpp; a spline basis function through spline/basis_kernel.hpp). The box (the
// default) is exact area coverage; otherwise a pixel's value is the shape convolved with k(x) k(y) at
// the pixel centre, divided by (integral of k)^2, computed exactly (see docs/renderer.md).
// Throws DrawError if `k` is not a usable pixel filter (not a polynomial, more than
// 8 pieces or coefficients per piece, a zero integral).
void validate_pixel_filter(const Kernel& k);

enum class Marker { Circle, Square, Diamond, Cross, Plus };
enum class HAlign { Left, Center, Right };
enum class VAlign { Baseline, Middle, Top, Bottom };

// Text is UTF-8, set in a DejaVu face (text_outlines.hpp: the faces, their lookup and
// fallback), shaped by HarfBuzz and drawn as glyph outlines by the same exact-area rasterizer as
// every shape.
enum class FontFamily { Sans, Serif, Mono };
enum class FontWeight { Normal, Bold };

struct TextStyle {
  double size = 14.0;  // font size (the em) in pixels
  Color color{0, 0, 0, 1};
  HAlign halign = HAlign::Left;      // by the advance width: Left puts the pen origin on the anchor
  VAlign valign = VAlign::Baseline;  // Top/Bottom/Middle: by the ink above and below the baseline
  FontFamily family = FontFamily::Sans;
  FontWeight weight = FontWeight::Normal;
  bool italic = false;  // the Oblique (Sans, Mono) or Italic (Serif) face
  double angle = 0;     // degrees, counter-clockwise as seen on the canvas, about the anchor
};

// The advance width of the shaped string and the ink above (ascent) and below (descent) the
// baseline, in pixels, unrotated. Throws DrawError for text that is not valid
// UTF-8 or a character no DejaVu face has.
struct TextExtent {
  double width = 0, ascent = 0, descent = 0;  // pixels
};
TextExtent measure_text(std::string_view text, const TextStyle& style);

class Path;  // path.hpp: lines and cubic Beziers

// The outline of a polygonal marker (square, diamond, plus, cross) of overall size `size`
// (side, or arm span; plus and cross arms are size/4 thick) centred at `centre`, as one closed
// contour. Circle markers are disks of diameter `size`: empty.
std::vector<Vec2> marker_polygon(Marker shape, Vec2 centre, double size);

// How a raster image item is sampled at canvas pixel centres.
enum class Sampling { Nearest, Bilinear };

// The drawing items: what a Scene records, one per drawing call, with that call's arguments
// (validated by the scene; Scene below says what each draws). A Scene exposes them in drawing
// order (Scene::items) for writers of other formats (vector/); a figure's display list records
// the same items in its own units before they are scaled into a scene.
struct StrokeItem {  // Scene::stroke_polyline
  std::vector<Vec2> points;
  bool closed = false;
  StrokeStyle style;
  Color color;
};
struct FillItem {  // Scene::fill_polygon
  std::vector<std::vector<Vec2>> contours;
  FillRule rule = FillRule::NonZero;
  Color color;
};
struct PathFillItem {  // Scene::fill_path
  std::shared_ptr<const Path> path;
  FillRule rule = FillRule::NonZero;
  Color color;
};
struct PathStrokeItem {  // Scene::stroke_path
  std::shared_ptr<const Path> path;
  StrokeStyle style;
  Color color;
};
struct DiskItem {  // Scene::fill_circle
  Vec2 centre;
  double radius = 0;
  Color color;
};
struct RingItem {  // Scene::stroke_circle
  Vec2 centre;
  double radius = 0;
  StrokeStyle style;
  Color color;
};
struct MarkerItem {  // Scene::marker
  Marker shape = Marker::Circle;
  Vec2 centre;
  double size = 0;
  Color color;
};
struct TextItem {  // Scene::text
  std::string text;
  Vec2 anchor;
  TextStyle style;
  // The glyph outlines the raster fills with the nonzero rule, in canvas pixels (text_path of
  // text, anchor and style), laid out by the scene when the item is recorded.
  std::shared_ptr<const Path> outline;
};
struct ImageItem {  // Scene::image: RGBA, associated alpha, as recorded
  std::shared_ptr<const Image> image;
  Vec2 p0, p1;  // the target rectangle's corners; p0 takes the image's top-left corner
  Sampling sampling = Sampling::Nearest;
};
using DrawItem = std::variant<StrokeItem, FillItem, PathFillItem, PathStrokeItem, DiskItem, RingItem, MarkerItem,
                              TextItem, ImageItem>;

// The coverage error a scene accepts by default where a stroke is resolved from its pieces
// (Scene::set_coverage_tolerance): 1/1024 of full coverage, a quarter of an 8-bit step.
inline constexpr double kDefaultCoverageTolerance = 1.0 / 1024;

// A drawing: a display list, rasterized at once (by tiles or bands, on any number of
// threads, with byte-identical results). Items are composited in the order added.
class Scene {
 public:
  Scene(int width, int height, Color background = {1, 1, 1, 1}, Kernel filter = Kernel::box());

  void stroke_polyline(std::span<const Vec2> points, bool closed, const StrokeStyle& style, Color color);
  // The same, taking the points over instead of copying them (a large polyline is not held twice).
  void stroke_polyline(std::vector<Vec2>&& points, bool closed, const StrokeStyle& style, Color color);
  void fill_polygon(const std::vector<std::vector<Vec2>>& contours, FillRule rule, Color color);
  void fill_circle(Vec2 centre, double radius, Color color);
  void stroke_circle(Vec2 centre, double radius, const StrokeStyle& style, Color color);
  void marker(Marker shape, Vec2 centre, double size, Color fill);
  // A path (path.hpp) filled, or stroked as the union of its pieces like a polyline. It is
  // flattened within the arc tolerance (1e-4 px) when the scene is rasterized, so a cubic
  // costs no more than the polyline it becomes, and a vector writer keeps its Beziers.
  void fill_path(const Path& path, FillRule rule, Color color);
  void stroke_path(const Path& path, const StrokeStyle& style, Color color);
  void text(std::string_view text, Vec2 anchor, const TextStyle& style);
  // A raster image (RGBA, associated alpha: the form rasterize returns, linear light or, with
  // Encoding::srgb, sRGB-encoded values) drawn into the rectangle with corners p0 and p1: each
  // canvas pixel whose centre lies inside samples the image at that centre, nearest or bilinear
  // (edge pixels repeated), and is composited over what is below. Not shaped by the pixel
  // filter: the image's own pixels are the samples.
  using Sampling = render::Sampling;
  void image(std::shared_ptr<const Image> image, Vec2 p0, Vec2 p1, Sampling sampling);

  // Every shape and text item recorded from now on is drawn intersected with the region the
  // path encloses under `rule`, exactly (one sweep resolves shape and clip together), until
  // clear_clip() or the next set_clip. An image cannot be recorded while a clip is set, and SVG
  // and PDF writers refuse a scene with clipped items (clipped()).
  void set_clip(const Path& path, FillRule rule = FillRule::NonZero);
  void clear_clip();

  int width() const { return width_; }
  int height() const { return height_; }
  Color background() const { return background_; }
  const Kernel& filter() const { return filter_; }
  BlendSpace blend_space() const { return blend_; }
  void set_blend_space(BlendSpace space) { blend_ = space; }
  // The work the exact union may take, in crossings of one item's outline with itself on the
  // canvas (kMaxSweepCrossings by default): rasterize refuses an item past it with
  // std::length_error, from a lower bound on its crossings found before it is swept, or, where
  // the bound sees too few, once the sweep's own count of its events passes it (infinity: no
  // limit).
  double max_crossings() const { return max_crossings_; }
  void set_max_crossings(double crossings);
  // The coverage error accepted in any pixel, as a fraction of full coverage, in [0, 1]
  // (kDefaultCoverageTolerance unless set). 0: every item is resolved by the exact sweep of its
  // outline and refused past max_crossings. Above 0, a solid stroke (no dashes, no clip, box
  // filter) whose outline, in some band of rows, crosses itself far more often than it has
  // edges is resolved in that band from its pieces instead (docs/renderer.md): pixels the
  // pieces certainly fill are 1, the others are swept exactly from the pieces that meet them.
  // That method's error is at most 1e-9 per pixel beyond the arc flattening both share, within
  // every tolerance above 0; the work limit still holds, counted in the same units.
  double coverage_tolerance() const { return tolerance_; }
  void set_coverage_tolerance(double tolerance);

  // Every recorded item, in drawing order, as the call that recorded it (for writers of
  // other formats: vector/).
  std::span<const DrawItem> items() const { return items_; }
  // Whether some item was recorded under a clip path (set_clip), which only the rasterizer draws.
  bool clipped() const { return !clips_.empty(); }

  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  ~Scene();

 private:
  int width_, height_;
  Color background_;
  Kernel filter_;
  BlendSpace blend_ = BlendSpace::linear;
  double max_crossings_ = kMaxSweepCrossings;
  double outline_vertices_ = 0;  // the recorded items' outline vertices, estimated from above
  double clip_vertices_ = 0;     // the clip path's, added to each clipped item's
  // Adds an item's estimate to the scene's; std::invalid_argument naming `call` past the limit.
  void count_outline(double vertices, const char* call);
  double tolerance_ = kDefaultCoverageTolerance;
  std::shared_ptr<const struct ClipRegion> clip_;  // clip_region.hpp
  std::vector<DrawItem> items_;
  // Each item's clip (null: none), index by index, once an item has been clipped; empty before.
  std::vector<std::shared_ptr<const ClipRegion>> clips_;
  void record(DrawItem&& item);
  const ClipRegion* clip_of(std::size_t item) const { return item < clips_.size() ? clips_[item].get() : nullptr; }
  friend Image rasterize(const Scene&, int threads, struct RasterReport* report);
};

// How rasterize resolved each item, for callers that report it (`render -v`): the items with
// bands of rows resolved from their pieces under the coverage tolerance (Scene above).
struct RasterReport {
  struct Item {
    std::size_t index = 0;   // in drawing order, from 0
    int bands = 0;           // bands of rows the item touches
    int piece_bands = 0;     // of those, resolved from its pieces
  };
  std::vector<Item> items;   // only items with piece_bands > 0, by index
  double tolerance = 0;      // the scene's coverage tolerance
  int band_rows = 0;         // rows of a band
};

// The picture as an RGBA image (associated alpha, channels R, G, B, A) in the scene's blend
// space: linear light by default (Encoding::linear), sRGB-encoded for BlendSpace::srgb.
// threads <= 0: all hardware threads. `report`, if given, is filled in.
Image rasterize(const Scene& scene, int threads = 0, RasterReport* report = nullptr);

}  // namespace splinefig::render
