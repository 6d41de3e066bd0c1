// Scene: validation of every drawing call, then recording it. Bad input is rejected here with
// std::invalid_argument naming the argument, so rasterization never sees NaN or infinities.
#include "clip_region.hpp"
#include "stroke.hpp"

#include <splinefig/base/huge_pages.hpp>

#include <splinefig/renderer/text_outlines.hpp>

#include <cmath>
#include <numbers>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace splinefig::render {
namespace {

[[noreturn]] void bad(const std::string& what) { throw DrawError(what); }

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void check_finite(double v, const char* call, const char* name) {
  if (!std::isfinite(v)) bad(std::string(call) + ": " + name + " is not finite (" + num(v) + ")");
  if (std::abs(v) > kMaxCoordinate) bad(std::string(call) + ": " + name + " " + num(v) + " exceeds 1e15 in magnitude");
}

void check_points(std::span<const Vec2> pts, const char* call, const char* name) {
  // One pass without branches (|v| <= limit is false for NaN and infinities too); the point to
  // blame is looked for only when there is one.
  unsigned all_ok = 1;
  for (const Vec2& p : pts)
    all_ok &= unsigned(std::abs(p.x) <= kMaxCoordinate) & unsigned(std::abs(p.y) <= kMaxCoordinate);
  if (all_ok) return;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y))
      bad(std::string(call) + ": " + name + " point " + std::to_string(i) + " is not finite (" + num(pts[i].x) +
          ", " + num(pts[i].y) + ")");
    if (std::abs(pts[i].x) > kMaxCoordinate || std::abs(pts[i].y) > kMaxCoordinate)
      bad(std::string(call) + ": " + name + " point " + std::to_string(i) + " (" + num(pts[i].x) + ", " +
          num(pts[i].y) + ") exceeds 1e15 px in magnitude");
  }
}

void check_color(const Color& c, const char* call) {
  for (float v : {c.r, c.g, c.b, c.a})
    if (!std::isfinite(v)) bad(std::string(call) + ": colour component is not finite");
  if (c.a < 0 || c.a > 1) bad(std::string(call) + ": colour alpha " + num(c.a) + " is outside [0, 1]");
}

void check_style(const StrokeStyle& s, const char* call) {
  check_finite(s.width, call, "stroke width");
  if (s.width < 0) bad(std::string(call) + ": stroke width " + num(s.width) + " is negative");
  check_finite(s.miter_limit, call, "miter limit");
  if (s.miter_limit < 1) bad(std::string(call) + ": miter limit " + num(s.miter_limit) + " is below 1");
  check_finite(s.dash_offset, call, "dash offset");  // the pattern itself is valid by construction
}

// The box outline estimates are taken against: the canvas and more than any pixel filter's
// margin (the rasterizer clips to the canvas, or the filter grid's box around it).
detail::Box outline_box(int w, int h) { return {-16, -16, w + 16.0, h + 16.0}; }

}  // namespace

void Scene::count_outline(double vertices, const char* call) {
  if (clip_) vertices += clip_vertices_;
  const double total = outline_vertices_ + vertices;
  char buf[300];
  if (vertices > kMaxOutlineVertices) {
    std::snprintf(buf, sizeof buf,
                  "%s: its outline would have about %.3g vertices (joins, caps, dashes and arcs, estimated before "
                  "it is built), over the limit of 2^26 (about 1.3 GB)",
                  call, vertices);
    bad(buf);
  }
  if (total > kMaxOutlineVertices) {
    std::snprintf(buf, sizeof buf,
                  "%s: the scene's outlines would have about %.3g vertices with this item's %.3g (estimated before "
                  "they are built), over the limit of 2^26 (about 1.3 GB)",
                  call, total, vertices);
    bad(buf);
  }
  outline_vertices_ = total;
}

DashPattern::DashPattern(std::vector<double> lengths) : lengths_(std::move(lengths)) {
  if (lengths_.empty()) return;
  for (double d : lengths_) {
    if (!std::isfinite(d)) bad("dash length " + num(d) + " is not finite");
    if (d < 0) bad("dash length " + num(d) + " is negative");
    if (d > kMaxCoordinate) bad("dash length " + num(d) + " exceeds " + num(kMaxCoordinate) + " px");
    period_ += d;
  }
  if (!(period_ >= kMinDashPeriod))
    bad("dash pattern period " + num(period_) + " px is below " + num(kMinDashPeriod) + " px");
  if (lengths_.size() % 2) {  // SVG: an odd list repeats to make it even
    lengths_.reserve(2 * lengths_.size());
    lengths_.insert(lengths_.end(), lengths_.begin(), lengths_.end());
    period_ *= 2;
  }
}

DashPattern DashPattern::scaled(double s) const {
  std::vector<double> v(lengths_);
  for (double& d : v) d *= s;
  return DashPattern(std::move(v));
}

void validate_pixel_filter(const Kernel& k) {
  if (!k.polynomial()) bad("pixel filter '" + k.name() + "': not a piecewise polynomial");
  if (k.pieces().size() > 8) bad("pixel filter '" + k.name() + "': support wider than 8 px");
  if (k.degree() > 7) bad("pixel filter '" + k.name() + "': a piece needs 1 to 8 coefficients");
  if (!(std::abs(k.integral()) > 1e-12)) bad("pixel filter '" + k.name() + "': its integral is zero");
}

Scene::Scene(int width, int height, Color background, Kernel filter)
    : width_(width), height_(height), background_(background), filter_(std::move(filter)) {
  if (width < 1 || height < 1) bad("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
  if (width > kMaxCanvasSide || height > kMaxCanvasSide)
    bad("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds " + std::to_string(kMaxCanvasSide) +
        " px a side");
  if (static_cast<long long>(width) * height > kMaxCanvasPixels)
    bad("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds 2^28 pixels");
  check_color(background, "Scene");
  validate_pixel_filter(filter_);
}

void Scene::set_max_crossings(double crossings) {
  if (!(crossings >= 0)) bad("Scene: the crossing limit must be >= 0 (infinity: no limit)");
  max_crossings_ = crossings;
}

void Scene::set_coverage_tolerance(double tolerance) {
  if (!(tolerance >= 0 && tolerance <= 1)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "Scene: coverage tolerance %g is not in [0, 1] (0: exact)", tolerance);
    bad(buf);
  }
  tolerance_ = tolerance;
}

// Appends with geometric growth into huge-page-advised storage (100k items are tens of MB): the
// new storage is advised before the items move into it, so that the move itself, which touches
// it first, takes huge pages rather than one fault per 4 KiB (reserve_huge advises only what it
// leaves untouched). The storage grows fourfold up to 2^20 items (128 MB), twofold beyond: each
// item then moves a third of a time on average instead of once, and the pages never touched
// past the last item cost address space only. 10^5 segments were recorded in about 7 ms instead of
// about 22 (most of it the moves and the first touches of each new storage). The item's clip is
// noted from the first clipped item on.
void Scene::record(DrawItem&& item) {
  if (items_.size() == items_.capacity()) {
    std::vector<DrawItem> grown;
    const std::size_t cap = items_.capacity();
    grown.reserve(std::max<std::size_t>(64, cap < (std::size_t{1} << 20) / 4 ? 4 * cap : 2 * cap));
    advise_huge_pages(grown.data(), grown.capacity() * sizeof(DrawItem));
    for (DrawItem& it : items_) grown.push_back(std::move(it));
    items_.swap(grown);
  }
  if (clip_ || !clips_.empty()) {
    clips_.resize(items_.size());
    clips_.push_back(clip_);
  }
  items_.push_back(std::move(item));
}

Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

void Scene::stroke_polyline(std::span<const Vec2> points, bool closed, const StrokeStyle& style, Color color) {
  stroke_polyline(std::vector<Vec2>(points.begin(), points.end()), closed, style, color);
}

void Scene::stroke_polyline(std::vector<Vec2>&& points, bool closed, const StrokeStyle& style, Color color) {
  check_points(points, "stroke_polyline", "polyline");
  check_style(style, "stroke_polyline");
  check_color(color, "stroke_polyline");
  const double work = detail::visible_dash_work(points, closed, style, {0, 0, double(width_), double(height_)});
  if (work > kMaxDashWork) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "stroke_polyline: the dash pattern is too fine for its length and width on this canvas "
                  "(%.3g dashes x overlap^2, limit 2^20)", work);
    bad(buf);
  }
  count_outline(detail::stroke_vertex_bound(points, closed, style, outline_box(width_, height_)), "stroke_polyline");
  record(StrokeItem{std::move(points), closed, style, color});
}

void Scene::fill_polygon(const std::vector<std::vector<Vec2>>& contours, FillRule rule, Color color) {
  for (const auto& c : contours) check_points(c, "fill_polygon", "contour");
  check_color(color, "fill_polygon");
  double vertices = 0;
  for (const auto& c : contours) vertices += static_cast<double>(c.size());
  count_outline(vertices, "fill_polygon");
  record(FillItem{contours, rule, color});
}

void Scene::fill_circle(Vec2 centre, double radius, Color color) {
  check_points({&centre, 1}, "fill_circle", "centre");
  check_finite(radius, "fill_circle", "radius");
  if (radius < 0) bad("fill_circle: radius " + num(radius) + " is negative");
  check_color(color, "fill_circle");
  count_outline(detail::arc_vertex_bound(centre, radius, 2 * std::numbers::pi, outline_box(width_, height_)) + 2, "fill_circle");
  record(DiskItem{centre, radius, color});
}

void Scene::stroke_circle(Vec2 centre, double radius, const StrokeStyle& style, Color color) {
  check_points({&centre, 1}, "stroke_circle", "centre");
  check_finite(radius, "stroke_circle", "radius");
  if (radius < 0) bad("stroke_circle: radius " + num(radius) + " is negative");
  check_style(style, "stroke_circle");
  check_color(color, "stroke_circle");
  {
    // As prepare_item draws it: an annulus, or a dashed stroke of the circle's polygon (made
    // here, once its own size is known to be within the limit).
    const detail::Box near = outline_box(width_, height_);
    const double h = 0.5 * style.width, full = 2 * std::numbers::pi;
    const double polygon = detail::arc_vertex_bound(centre, radius, full, near) + 2;
    if (style.dashes.empty() || radius == 0 || h == 0) {
      count_outline(detail::arc_vertex_bound(centre, radius + h, full, near) +
                        (radius > h ? detail::arc_vertex_bound(centre, radius - h, full, near) : 0) + 4,
                    "stroke_circle");
    } else if (polygon > kMaxOutlineVertices) {
      count_outline(polygon, "stroke_circle");
    } else {
      std::vector<Vec2> pts{Vec2{centre.x + radius, centre.y}};
      detail::arc_interior(centre, radius, 0.0, full, near, [&](Vec2 q) { pts.push_back(q); });
      count_outline(detail::stroke_vertex_bound(pts, true, style, near), "stroke_circle");
    }
  }
  record(RingItem{centre, radius, style, color});
}

void Scene::marker(Marker shape, Vec2 centre, double size, Color fill) {
  check_points({&centre, 1}, "marker", "centre");
  check_finite(size, "marker", "size");
  if (size < 0) bad("marker: size " + num(size) + " is negative");
  check_color(fill, "marker");
  count_outline(shape == Marker::Circle
                    ? detail::arc_vertex_bound(centre, 0.5 * size, 2 * std::numbers::pi, outline_box(width_, height_)) + 2
                    : 16,
                "marker");
  record(MarkerItem{shape, centre, size, fill});
}

void Scene::set_clip(const Path& path, FillRule rule) {
  check_points(path.points(), "set_clip", "path");
  clip_vertices_ = static_cast<double>(path.flattened_size(detail::kArcTolerance));
  clip_ = std::make_shared<const ClipRegion>(ClipRegion{path, rule});
}

void Scene::clear_clip() { clip_.reset(); }

void Scene::image(std::shared_ptr<const Image> image, Vec2 p0, Vec2 p1, Sampling sampling) {
  if (!image) bad("image: no image");
  if (clip_) bad("image: images are not clipped; clear_clip() first");
  if (image->channels != 4 || image->width < 1 || image->height < 1 ||
      image->pixels.size() != image->pixel_count() * 4)
    bad("image: the image must be RGBA with pixels (" + std::to_string(image->width) + " x " +
        std::to_string(image->height) + " x " + std::to_string(image->channels) + ")");
  for (float v : image->pixels)
    if (!std::isfinite(v)) bad("image: a pixel value is not finite");
  const Vec2 corners[2] = {p0, p1};
  check_points(corners, "image", "corner");
  record(ImageItem{std::move(image), p0, p1, sampling});
}

void Scene::fill_path(const Path& path, FillRule rule, Color color) {
  check_points(path.points(), "fill_path", "path");
  check_color(color, "fill_path");
  count_outline(static_cast<double>(path.flattened_size(detail::kArcTolerance)), "fill_path");
  record(PathFillItem{std::make_shared<const Path>(path), rule, color});
}

void Scene::stroke_path(const Path& path, const StrokeStyle& style, Color color) {
  check_points(path.points(), "stroke_path", "path");
  check_style(style, "stroke_path");
  check_color(color, "stroke_path");
  {
    // Flattened as prepare_item flattens it, once the flat points are known to be within the limit.
    const double flat_points = static_cast<double>(path.flattened_size(detail::kArcTolerance));
    if (flat_points > kMaxOutlineVertices) {
      count_outline(flat_points, "stroke_path");
    } else {
      const Path::Flat flat = path.flatten(detail::kArcTolerance);
      double vertices = 0;
      for (std::size_t i = 0; i < flat.contours.size(); ++i)
        vertices += detail::stroke_vertex_bound(flat.contours[i], flat.closed[i], style, outline_box(width_, height_));
      count_outline(vertices, "stroke_path");
    }
  }
  record(PathStrokeItem{std::make_shared<const Path>(path), style, color});
}

void Scene::text(std::string_view text, Vec2 anchor, const TextStyle& style) {
  check_points({&anchor, 1}, "text", "anchor");
  check_finite(style.size, "text", "font size");
  if (style.size <= 0 || style.size > kMaxFontSize)
    bad("text: font size " + num(style.size) + " is outside (0, " + num(kMaxFontSize) + "]");
  check_color(style.color, "text");
  check_finite(style.angle, "text", "angle");
  // Laid out now: bad UTF-8 and missing characters are errors of this call.
  auto outline = std::make_shared<const Path>(text_path(text, anchor, style));
  count_outline(static_cast<double>(outline->flattened_size(detail::kArcTolerance)), "text");
  record(TextItem{std::string(text), anchor, style, std::move(outline)});
}

}  // namespace splinefig::render
