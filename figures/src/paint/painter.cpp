// The figure display list and its rendering (see painter.hpp).
#include "painter.hpp"

#include "../text/rich_text.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <algorithm>
#include <numbers>
#include <cmath>
#include <stdexcept>

namespace splinefig::figures::detail {

void Painter::set_origin(const SpecLocation& origin) {
  if (origins_.back() != origin) origins_.push_back(origin);
}
const SpecLocation& Painter::origin_of(std::size_t op) const { return origins_[notes_[op].origin]; }
void Painter::add(Op op, bool hairline) {
  ops_.push_back(std::move(op));
  notes_.push_back({static_cast<std::uint32_t>(origins_.size() - 1), hairline});
}

void Painter::stroke(std::vector<Vec2> pts, bool closed, const render::StrokeStyle& s, Color c) {
  if (pts.empty() || !(s.width > 0) || c.a <= 0) return;
  add(render::StrokeItem{std::move(pts), closed, s, c});
}
void Painter::hairline(std::vector<Vec2> pts, bool closed, const render::StrokeStyle& s, Color c) {
  if (pts.empty() || !(s.width > 0) || c.a <= 0) return;
  add(render::StrokeItem{std::move(pts), closed, s, c}, true);
}
void Painter::stroke(render::Path path, const render::StrokeStyle& s, Color c) {
  if (path.empty() || !(s.width > 0) || c.a <= 0) return;
  add(render::PathStrokeItem{std::make_shared<const render::Path>(std::move(path)), s, c});
}
void Painter::fill(std::vector<std::vector<Vec2>> contours, render::FillRule rule, Color c) {
  if (c.a <= 0) return;
  add(render::FillItem{std::move(contours), rule, c});
}
void Painter::circle(Vec2 centre, double r, std::optional<Color> fill, std::optional<Pen> stroke) {
  if (fill) add(render::DiskItem{centre, r, *fill});
  if (stroke) add(render::RingItem{centre, r, stroke->style, stroke->color});
}
void Painter::marker(render::Marker shape, Vec2 centre, double size, Color c) {
  add(render::MarkerItem{shape, centre, size, c});
}
void Painter::text(std::string s, Vec2 at, const Font& f, TextAnchor a, double angle) {
  if (s.empty()) return;
  add(TextOp{std::move(s), at, resolved(f), a, angle});
}
void Painter::image(Raster r, double x0, double y0, double x1, double y1) {
  add(ImageOp{std::move(r), x0, y0, x1, y1});
}

Vec2 raster_size(const Raster& r) {
  if (r.file.empty()) return {static_cast<double>(r.width), static_cast<double>(r.height)};
  const Image im = read_image(r.file, ReadMode::linear);
  return {static_cast<double>(im.width), static_cast<double>(im.height)};
}

namespace {

// The raster as linear-light RGBA with associated alpha (the renderer's form): a file is
// read decoded (io.hpp), inline data is grey, opaque.
Image load(const Raster& r) {
  if (!r.file.empty()) {
    const Image src = read_image(r.file, ReadMode::linear);
    Image px(src.width, src.height, 4);
    const int nc = src.channels, a = src.alpha_channel;
    int colour[3], k = 0;  // the first three channels that are not alpha
    for (int c = 0; c < nc && k < 3; ++c)
      if (c != a) colour[k++] = c;
    for (std::size_t i = 0; i < src.pixel_count(); ++i) {
      const float* s = &src.pixels[i * std::size_t(nc)];
      float* d = &px.pixels[i * 4];
      for (int c = 0; c < 3; ++c) d[c] = k == 3 ? s[colour[c]] : (k > 0 ? s[colour[0]] : 0.0f);
      d[3] = a >= 0 ? s[a] : 1.0f;
    }
    return px;
  }
  Image px(r.width, r.height, 4);
  for (std::size_t i = 0; i < px.pixel_count(); ++i) {
    float v = r.data[i * r.channels];
    if (r.srgb_data) v = srgb_to_linear(v);
    for (int k = 0; k < 3; ++k) px.pixels[i * 4 + k] = v;
    px.pixels[i * 4 + 3] = 1;
  }
  return px;
}

std::vector<Vec2> scaled(const std::vector<Vec2>& pts, double s) {
  std::vector<Vec2> out(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) out[i] = {pts[i].x * s, pts[i].y * s};
  return out;
}

// A hairline's points (output pixels) on the pixel grid: across each horizontal or vertical
// segment, its centre onto a pixel centre (odd width, rounded, at least 1) or a pixel edge
// (even width); a coordinate along the segments only, onto a pixel edge. A point where a
// horizontal and a vertical segment meet is snapped across both.
std::vector<Vec2> snapped(std::vector<Vec2> pts, bool closed, double width) {
  const long n = std::max(1L, std::lround(width));
  auto across = [&](double c) { return n % 2 ? std::floor(c) + 0.5 : std::round(c); };
  const std::size_t m = pts.size();
  std::vector<char> vertical(m, 0), horizontal(m, 0);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = i + 1 < m ? i + 1 : (closed && m > 2 ? 0 : m);
    if (j == m) continue;
    if (pts[i].x == pts[j].x) vertical[i] = vertical[j] = 1;
    if (pts[i].y == pts[j].y) horizontal[i] = horizontal[j] = 1;
  }
  for (std::size_t i = 0; i < m; ++i) {
    pts[i].x = vertical[i] ? across(pts[i].x) : std::round(pts[i].x);
    pts[i].y = horizontal[i] ? across(pts[i].y) : std::round(pts[i].y);
  }
  return pts;
}

render::StrokeStyle scaled(render::StrokeStyle st, double s) {
  st.width *= s;
  st.dashes = st.dashes.scaled(s);
  st.dash_offset *= s;
  return st;
}

// A label set as runs (rich_text.hpp), aligned as a whole, each run on the baseline, the whole
// turned about the anchor.
void draw_text(render::Scene& scene, const TextOp& op, double s) {
  RichText rt = set_text(op.text, op.font.size * s,
                         [&](const std::string& t, double size, bool italic) { return measure_plain(t, size, op.font, italic); });
  double ox = 0, oy = 0;  // the label's pen origin relative to the anchor, in the label's frame
  if (op.anchor.halign == render::HAlign::Center) ox = -0.5 * rt.width;
  else if (op.anchor.halign == render::HAlign::Right) ox = -rt.width;
  if (op.anchor.valign == render::VAlign::Top) oy = rt.ascent;
  else if (op.anchor.valign == render::VAlign::Middle) oy = 0.5 * (rt.ascent - rt.descent);
  else if (op.anchor.valign == render::VAlign::Bottom) oy = -rt.descent;
  const bool upright = op.angle == 0;
  const double a = op.angle * std::numbers::pi / 180;
  // Exact for the quarter turns axis labels use.
  const double c = op.angle == 90 ? 0.0 : std::cos(a), sn = op.angle == 90 ? 1.0 : std::sin(a);
  const Vec2 at{op.at.x * s, op.at.y * s};
  for (const Run& run : rt.runs) {
    render::TextStyle style = plain_style(run.size, op.font, run.italic);
    style.angle = op.angle;
    const double u = ox + run.dx, v = oy + run.dy;
    const Vec2 p = upright ? Vec2{at.x + u, at.y + v} : Vec2{at.x + c * u + sn * v, at.y - sn * u + c * v};
    scene.text(run.text, p, style);
  }
}

}  // namespace

render::Scene scene_of(const Painter& p, int width, int height, Color background, const Kernel& filter,
                       render::BlendSpace blend, double coverage_tolerance, bool snap) {
  const double s = p.scale();
  render::Scene scene(width, height, background, filter);
  scene.set_blend_space(blend);
  scene.set_coverage_tolerance(coverage_tolerance);
  for (std::size_t i = 0; i < p.ops().size(); ++i) {
    const Op& op = p.ops()[i];
    naming_origin(p.origin_of(i), [&] { std::visit(
        [&](const auto& o) {
          using T = std::decay_t<decltype(o)>;
          if constexpr (std::is_same_v<T, render::StrokeItem>) {
            if (snap && p.hairline_at(i)) scene.stroke_polyline(snapped(scaled(o.points, s), o.closed, o.style.width * s), o.closed, scaled(o.style, s), o.color);
            else scene.stroke_polyline(scaled(o.points, s), o.closed, scaled(o.style, s), o.color);
          } else if constexpr (std::is_same_v<T, render::PathStrokeItem>) {
            scene.stroke_path(o.path->transformed(s, 0, 0, s, 0, 0), scaled(o.style, s), o.color);
          } else if constexpr (std::is_same_v<T, render::FillItem>) {
            std::vector<std::vector<Vec2>> c;
            for (const auto& contour : o.contours) c.push_back(scaled(contour, s));
            scene.fill_polygon(c, o.rule, o.color);
          } else if constexpr (std::is_same_v<T, render::DiskItem>) {
            scene.fill_circle({o.centre.x * s, o.centre.y * s}, o.radius * s, o.color);
          } else if constexpr (std::is_same_v<T, render::RingItem>) {
            scene.stroke_circle({o.centre.x * s, o.centre.y * s}, o.radius * s, scaled(o.style, s), o.color);
          } else if constexpr (std::is_same_v<T, render::MarkerItem>) {
            scene.marker(o.shape, {o.centre.x * s, o.centre.y * s}, o.size * s, o.color);
          } else if constexpr (std::is_same_v<T, TextOp>) {
            draw_text(scene, o, s);
          } else if constexpr (std::is_same_v<T, ImageOp>) {
            scene.image(std::make_shared<const Image>(load(o.raster)), {o.x0 * s, o.y0 * s}, {o.x1 * s, o.y1 * s},
                        o.raster.nearest ? render::Scene::Sampling::Nearest : render::Scene::Sampling::Bilinear);
          }
        },
        op); });
  }
  return scene;
}

}  // namespace splinefig::figures::detail
