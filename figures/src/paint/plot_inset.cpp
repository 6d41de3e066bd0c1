// Insets of an axes panel ([[axes.inset]], docs/spec.md): a region of the plot box showing the
// panel's elements again at the inset's own ranges, the rectangle it magnifies marked on the
// panel and joined to it by connector lines (as matplotlib's indicate_inset_zoom).
#include "draw.hpp"

#include <algorithm>
#include <cmath>

namespace splinefig::figures::detail {
namespace {

render::StrokeStyle thin(double width) {
  render::StrokeStyle s;
  s.width = width;
  s.cap = render::Cap::Butt;
  s.join = render::Join::Miter;
  return s;
}

// The panel's map of the inset's ranges (the axes' orientation kept: a flipped axis stays flipped).
std::array<double, 2> oriented(const std::array<double, 2>& r, const std::array<double, 2>& parent) {
  return parent[1] < parent[0] ? std::array<double, 2>{r[1], r[0]} : r;
}

// The inset's box at its `at` (whole pixels at 1x), or its size when it is placed automatically.
Rect box_at(const std::array<double, 4>& a, const Rect& b) {
  return {std::round(b.left + a[0] * b.width()), std::round(b.bottom - (a[1] + a[3]) * b.height()),
          std::round(b.left + (a[0] + a[2]) * b.width()), std::round(b.bottom - a[1] * b.height())};
}
std::array<double, 2> inset_size(const InsetSpec& in, const Rect& b) {
  if (in.at) {
    const Rect r = box_at(*in.at, b);
    return {r.width(), r.height()};
  }
  return {std::round(in.size[0] * b.width()), std::round(in.size[1] * b.height())};
}

// The inset's ranges: as given, or for an axes of equal aspect the shorter one widened about its
// centre so that the inset keeps it.
struct Ranges {
  std::array<double, 2> x, y;
};
Ranges inset_ranges(const InsetSpec& in, const AxesSpec& ax, const Rect& b) {
  Ranges r{in.x_range, in.y_range};
  if (!ax.equal_aspect) return r;
  const auto [w, h] = inset_size(in, b);
  const double sx = std::max(1.0, w) / (r.x[1] - r.x[0]), sy = std::max(1.0, h) / (r.y[1] - r.y[0]);
  if (sx > sy) {
    const double half = 0.5 * std::max(1.0, w) / sy, mid = 0.5 * (r.x[0] + r.x[1]);
    r.x = {mid - half, mid + half};
  } else {
    const double half = 0.5 * std::max(1.0, h) / sx, mid = 0.5 * (r.y[0] + r.y[1]);
    r.y = {mid - half, mid + half};
  }
  return r;
}

// The rectangle of data the inset magnifies, where the panel draws it.
Rect marked_rect(const Ranges& rg, const Panel& panel) {
  const double x0 = panel.map.x.to_pixel(rg.x[0]), x1 = panel.map.x.to_pixel(rg.x[1]);
  const double y0 = tick_pixel(panel.map.y, rg.y[0]), y1 = tick_pixel(panel.map.y, rg.y[1]);
  return {std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)};
}

// Where the inset goes: at its `at`, else at the first spot (the legend's, in the legend's order)
// that covers nothing drawn yet, else the one that covers least. Whole pixels at 1x.
Rect inset_box(const InsetSpec& in, const Rect& b, Occupancy& occ) {
  if (in.at) return box_at(*in.at, b);
  const auto [w, h] = inset_size(in, b);
  const double inset = std::min({kLegendInset, 0.5 * (b.width() - w), 0.5 * (b.height() - h)});
  const double xl = b.left + inset, xr = b.right - inset - w, xc = 0.5 * (b.left + b.right - w);
  const double yt = b.top + inset, yb = b.bottom - inset - h, yc = 0.5 * (b.top + b.bottom - h);
  const double spots[8][2] = {{xr, yt}, {xl, yt}, {xr, yb}, {xl, yb}, {xc, yt}, {xc, yb}, {xr, yc}, {xl, yc}};
  long best = -1;
  Rect chosen{};
  for (const auto& s : spots) {
    const Rect r{std::round(s[0]), std::round(s[1]), std::round(s[0]) + w, std::round(s[1]) + h};
    const long n = occ.count(r.inflated(2));
    if (best < 0 || n < best) best = n, chosen = r;
    if (n == 0) break;
  }
  return chosen;
}

// Whether the segment a-b runs through the inside of r (its ends may lie on r's edge).
bool crosses(Vec2 a, Vec2 b, const Rect& r) {
  const Rect in = r.inflated(-0.75);
  for (int i = 1; i < 256; ++i) {
    const double t = i / 256.0;
    if (in.contains({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)})) return true;
  }
  return false;
}

// The axes' elements as the inset draws them: without labels and texts (the panel has them).
PreparedAxes unlabelled(const PreparedAxes& prepared) {
  PreparedAxes copy = prepared;
  for (PlotElement& e : copy.axes.elements)
    std::visit(
        [](auto& el) {
          if constexpr (requires { el.label.label; }) el.label = Labelling{};
          if constexpr (requires { el.look.label.label; }) el.look.label = Labelling{};
          if constexpr (requires { el.piece_labels; }) el.piece_labels.clear();
          if constexpr (std::is_same_v<std::decay_t<decltype(el)>, TextElement> ||
                        std::is_same_v<std::decay_t<decltype(el)>, AnnotationElement>)
            el.text.clear();
        },
        e);
  return copy;
}

}  // namespace

void mark_inset_sources(const AxesSpec& ax, const Panel& panel, Occupancy& occ) {
  for (const InsetSpec& in : ax.insets) occ.mark_rect(marked_rect(inset_ranges(in, ax, panel.box), panel).inflated(1));
}

void draw_insets(const PreparedAxes& prepared, const Panel& panel, Painter& p, Occupancy& occ, const Guides& g,
                 std::vector<AxesInfo::Inset>& out) {
  const AxesSpec& ax = prepared.axes;
  if (ax.insets.empty()) return;
  const double scale = p.scale();
  for (const InsetSpec& in : ax.insets) {
    p.set_origin(in.where);
    const Ranges rg = inset_ranges(in, ax, panel.box);
    const Rect z = marked_rect(rg, panel);
    const Rect b = inset_box(in, panel.box, occ);
    occ.mark_rect(b.inflated(1));
    // The inset: an opaque panel with the elements at its ranges, clipped to it, and a box.
    Panel inset;
    inset.box = b;
    inset.x_range = oriented(rg.x, panel.x_range);
    inset.y_range = oriented(rg.y, panel.y_range);
    inset.map.x = {ax.x.scale, inset.x_range[0], inset.x_range[1], b.left, b.right, 'x'};
    inset.map.y = {ax.y.scale, inset.y_range[0], inset.y_range[1], b.bottom, b.top, 'y'};
    p.fill({{{b.left, b.top}, {b.right, b.top}, {b.right, b.bottom}, {b.left, b.bottom}}}, render::FillRule::NonZero,
           Color{1, 1, 1, 1});
    PreparedAxes copy = unlabelled(prepared);
    sample_paths(copy, inset.map, 0.05 / scale);
    Occupancy scratch = occ;
    std::vector<SeriesInfo> series;
    std::vector<Entry> entries;
    std::vector<AxesInfo::DataInk> ink;
    draw_elements(copy, inset, p, scratch, series, entries, ink, g);
    p.set_origin(in.where);
    const double l = b.left - 0.5, r = b.right + 0.5, t = b.top - 0.5, bo = b.bottom + 0.5;
    p.hairline({{l, t}, {r, t}, {r, bo}, {l, bo}}, true, thin(1), g.axis);
    // The magnified rectangle on the panel, its 1-px lines on pixel centres (where the raster's
    // hairlines go, so that SVG and PDF draw it where the PNG does), and the connectors from its
    // corners to the inset's that run outside both.
    auto centre = [](double v) { return std::floor(v) + 0.5; };
    const Rect zs{centre(z.left), centre(z.top), centre(z.right), centre(z.bottom)};
    p.hairline({{zs.left, zs.top}, {zs.right, zs.top}, {zs.right, zs.bottom}, {zs.left, zs.bottom}}, true, thin(1),
               g.axis);
    const Vec2 zc[4] = {{zs.left, zs.top}, {zs.right, zs.top}, {zs.right, zs.bottom}, {zs.left, zs.bottom}};
    const Vec2 bc[4] = {{l, t}, {r, t}, {r, bo}, {l, bo}};
    for (int k = 0; k < 4; ++k) {
      if (crosses(zc[k], bc[k], z) || crosses(zc[k], bc[k], b)) continue;
      p.stroke({zc[k], bc[k]}, false, thin(0.75), g.axis);
      occ.mark_polyline({zc[k], bc[k]}, 1);
    }
    out.push_back({{b.left * scale, b.top * scale, b.right * scale, b.bottom * scale},
                   {z.left * scale, z.top * scale, z.right * scale, z.bottom * scale},
                   rg.x,
                   rg.y});
  }
}

}  // namespace splinefig::figures::detail
