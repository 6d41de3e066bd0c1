// Guides of an axes panel: grid, zero lines, frame, ticks and their labels, axis labels,
// the panel title, inline label placement and the legend.
#include "draw.hpp"

#include <algorithm>
#include <cmath>

namespace splinefig::figures::detail {
namespace {

render::StrokeStyle hairline(double width = 1) {
  render::StrokeStyle s;
  s.width = width;
  s.cap = render::Cap::Butt;
  s.join = render::Join::Miter;
  return s;
}

}  // namespace

void draw_under(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g) {
  const Rect& b = panel.box;
  if (ax.grid) {
    for (const auto& t : panel.x_ticks) {
      double x = tick_pixel(panel.map.x, t.value);
      p.hairline({{x, b.top}, {x, b.bottom}}, false, hairline(), g.grid);
    }
    for (const auto& t : panel.y_ticks) {
      double y = tick_pixel(panel.map.y, t.value);
      p.hairline({{b.left, y}, {b.right, y}}, false, hairline(), g.grid);
    }
  }
  if (ax.zero_line) {
    if (ax.y.scale == Scale::Linear) {
      double y = panel.map.y.to_pixel(0);
      if (y > b.top + 0.5 && y < b.bottom - 0.5) p.hairline({{b.left, y}, {b.right, y}}, false, hairline(), g.zero);
    }
    if (ax.x.scale == Scale::Linear) {
      double x = panel.map.x.to_pixel(0);
      if (x > b.left + 0.5 && x < b.right - 0.5) p.hairline({{x, b.top}, {x, b.bottom}}, false, hairline(), g.zero);
    }
  }
}

void draw_over(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g) {
  const Rect& b = panel.box;
  if (ax.frame != Frame::None) {
    // Spines lie just outside the box, on whole pixels at 1x: crisp at any integer scale.
    const double l = b.left - 0.5, r = b.right + 0.5, t = b.top - 0.5, bo = b.bottom + 0.5;
    if (ax.frame == Frame::Box) {
      p.hairline({{l, t}, {r, t}, {r, bo}, {l, bo}}, true, hairline(), g.axis);
    } else {
      p.hairline({{l, t}, {l, bo}, {r, bo}}, false, hairline(), g.axis);
    }
    // Each tick, then its label where the layout placed it (plot_layout.cpp).
    auto label = [&](const PlacedText& t) { p.text(t.text, t.at, t.font, t.anchor, t.angle); };
    for (size_t i = 0; i < panel.x_ticks.size(); ++i) {
      double x = tick_pixel(panel.map.x, panel.x_ticks[i].value);
      p.hairline({{x, b.bottom + 1}, {x, b.bottom + 1 + g.tick_length}}, false, hairline(), g.axis);
      label(panel.x_tick_labels.at(i));
    }
    for (size_t i = 0; i < panel.y_ticks.size(); ++i) {
      double y = tick_pixel(panel.map.y, panel.y_ticks[i].value);
      p.hairline({{b.left - 1, y}, {b.left - 1 - g.tick_length, y}}, false, hairline(), g.axis);
      label(panel.y_tick_labels.at(i));
    }
    // Minor ticks: three fifths as long, no label.
    const double minor = 0.6 * g.tick_length;
    for (double v : panel.x_minor) {
      const double x = panel.map.x.to_pixel(v);
      p.hairline({{x, b.bottom + 1}, {x, b.bottom + 1 + minor}}, false, hairline(), g.axis);
    }
    for (double v : panel.y_minor) {
      const double y = panel.map.y.to_pixel(v);
      p.hairline({{b.left - 1, y}, {b.left - 1 - minor, y}}, false, hairline(), g.axis);
    }
    for (double m : ax.x.marks) {
      double x = panel.map.x.to_pixel(m);
      if (x < b.left - 0.5 || x > b.right + 0.5) continue;
      double y = b.bottom + 1;
      p.fill({{{x, y - 6}, {x - 4, y}, {x + 4, y}}}, render::FillRule::NonZero, g.axis);
    }
  }
  // The axis labels and the title, where the layout placed them.
  for (const PlacedText& t : panel.labels) p.text(t.text, t.at, t.font, t.anchor, t.angle);
}

Vec2 place_label(const std::string& text, const Font& f, const std::vector<Vec2>& candidates, const Rect& box,
                 const Painter& p, Occupancy& occ, double d) {
  const render::TextExtent e = p.measure(text, f);
  const double w = e.width, h = e.ascent + e.descent;
  // Directions, best first: above, below, the four diagonals, then the sides.
  const double dirs[8][2] = {{0, -1}, {0, 1}, {1, -1}, {-1, -1}, {1, 1}, {-1, 1}, {1, 0}, {-1, 0}};
  const Rect inside = box.inflated(-2);
  double best = 1e300;
  Rect best_rect{};
  for (size_t ci = 0; ci < candidates.size(); ++ci) {
    Vec2 c = candidates[ci];
    for (int di = 0; di < 8; ++di) {
      double dx = dirs[di][0], dy = dirs[di][1];
      double diag = (dx != 0 && dy != 0) ? 0.75 : 1.0;
      double cx = c.x + dx * (d * diag + 0.5 * w), cy = c.y + dy * (d * diag + 0.5 * h);
      Rect r{cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h};
      double score = 10.0 * occ.count(r.inflated(2)) + 1.5 * static_cast<double>(ci) + 2.0 * di;
      if (r.left < inside.left || r.right > inside.right || r.top < inside.top || r.bottom > inside.bottom) score += 1e6;
      if (score < best) best = score, best_rect = r;
    }
  }
  // No spot next to the data inside the box: the best one moved into it, if the text fits.
  if (best >= 1e6 && w <= inside.width() && h <= inside.height()) {
    const double dx = std::max(0.0, inside.left - best_rect.left) - std::max(0.0, best_rect.right - inside.right);
    const double dy = std::max(0.0, inside.top - best_rect.top) - std::max(0.0, best_rect.bottom - inside.bottom);
    best_rect = {best_rect.left + dx, best_rect.top + dy, best_rect.right + dx, best_rect.bottom + dy};
  }
  occ.mark_rect(best_rect.inflated(1));
  return {best_rect.left, best_rect.top + e.ascent};
}

namespace {
constexpr double kPad = kLegendPad, kSample = kLegendSample, kGap = kLegendGap,
                 kColumnGap = kLegendColumnGap;
}  // namespace

std::optional<Rect> draw_legend(const AxesSpec& ax, const Panel& panel, const std::vector<Entry>& drawn, Painter& p,
                                Occupancy& occ, const Guides& g, bool require_free, bool* crowded) {
  if (drawn.empty() || ax.legend == LegendPlace::None) return std::nullopt;
  // The entries in legend_order, the rest after them as drawn.
  std::vector<Entry> entries;
  for (const std::string& label : ax.legend_order) {
    const auto it = std::find_if(drawn.begin(), drawn.end(), [&](const Entry& e) { return e.label == label; });
    if (it == drawn.end())
      throw SpecFileError(ax.where.with_key("axes.legend_order"), "\"" + label + "\" is no label in the legend");
    if (std::none_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.label == label; })) entries.push_back(*it);
  }
  for (const Entry& e : drawn)
    if (std::none_of(entries.begin(), entries.end(), [&](const Entry& x) { return x.label == e.label; })) entries.push_back(e);
  const Font& f = g.legend_font;
  const double pad = kPad, sample = kSample, gap = kGap, row = legend_row(g);
  Font tf = f;
  tf.bold = true;
  std::vector<std::string> labels;
  for (const auto& e : entries) labels.push_back(e.label);
  const auto [w, h] = legend_size(ax, labels, p, g);
  double text_w = 0;
  for (const auto& e : entries) text_w = std::max(text_w, p.measure(e.label, f).width);
  if (!ax.legend_title.empty()) text_w = std::max(text_w, p.measure(ax.legend_title, tf).width - sample - gap);
  const int rows = legend_rows(ax.legend_columns, entries.size());
  const double col_w = sample + gap + text_w + kColumnGap;
  const Rect& b = panel.box;
  const double inset = kLegendInset;
  struct Spot {
    LegendPlace place;
    double x, y;
  };
  const double xl = b.left + inset, xr = b.right - inset - w, xc = std::round(0.5 * (b.left + b.right - w));
  const double yt = b.top + inset, yb = b.bottom - inset - h, yc = std::round(0.5 * (b.top + b.bottom - h));
  // Inside the box, in the order of preference (a place the spec names first); the legend goes
  // to the first spot that covers no data (none of the occupancy grid's cells: the data's
  // strokes widened by a pixel, its markers, the inline labels), as matplotlib's "best" does.
  std::vector<Spot> spots = {{LegendPlace::UpperRight, xr, yt}, {LegendPlace::UpperLeft, xl, yt},
                             {LegendPlace::LowerRight, xr, yb}, {LegendPlace::LowerLeft, xl, yb},
                             {LegendPlace::UpperCenter, xc, yt}, {LegendPlace::LowerCenter, xc, yb},
                             {LegendPlace::Auto, xr, yc},        {LegendPlace::Auto, xl, yc}};
  if (ax.legend != LegendPlace::Auto && ax.legend != LegendPlace::OutsideRight)
    std::stable_partition(spots.begin(), spots.end(), [&](const Spot& s) { return s.place == ax.legend; });
  Spot chosen{LegendPlace::OutsideRight, b.right + kLegendOutsideGap, b.top};
  if (ax.legend != LegendPlace::OutsideRight) {
    long best = -1;
    for (const auto& s : spots) {
      const long n = occ.count(Rect{std::round(s.x), std::round(s.y), std::round(s.x) + w, std::round(s.y) + h}.inflated(1));
      if (best < 0 || n < best) best = n, chosen = s;
      if (n == 0) break;
    }
    // Every spot inside covers data: the caller lays the panel out again with the legend
    // outside the box, when it may.
    if (best > 0 && require_free) {
      if (crowded) *crowded = true;
      return std::nullopt;
    }
  }
  double x = std::round(chosen.x), y = std::round(chosen.y);
  occ.mark_rect({x, y, x + w, y + h});
  Color bg{1, 1, 1, 0.92f};
  p.fill({{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}}, render::FillRule::NonZero, bg);
  p.stroke({{x + 0.5, y + 0.5}, {x + w - 0.5, y + 0.5}, {x + w - 0.5, y + h - 0.5}, {x + 0.5, y + h - 0.5}}, true,
           hairline(), *render::parse_hex_color("#cccccc"));
  double cy = y + pad;
  if (!ax.legend_title.empty()) {
    p.text(ax.legend_title, {x + pad, cy + 0.5 * row}, tf, {render::HAlign::Left, render::VAlign::Middle});
    cy += row;
  }
  for (size_t i = 0; i < entries.size(); ++i) {
    const Entry& e = entries[i];
    const int r = static_cast<int>(i) % rows, c = static_cast<int>(i) / rows;  // down each column
    double my = cy + row * r + 0.5 * row - 2;
    double sx0 = x + pad + c * col_w, sx1 = sx0 + sample;
    if (e.patch) {
      p.fill({{{sx0, my - 6}, {sx1, my - 6}, {sx1, my + 6}, {sx0, my + 6}}}, render::FillRule::NonZero, e.color);
    }
    if (e.line) {
      render::StrokeStyle st = e.style;
      st.cap = st.dashes.empty() ? render::Cap::Round : render::Cap::Butt;
      double inset_x = st.dashes.empty() ? st.width / 2 : 0;
      p.stroke({{sx0 + inset_x, my}, {sx1 - inset_x, my}}, false, st, e.color);
    }
    if (e.markers) p.marker(e.marker, {0.5 * (sx0 + sx1), my}, e.marker_size, e.color);
    p.text(e.label, {sx1 + gap, my}, f, {render::HAlign::Left, render::VAlign::Middle});
  }
  return Rect{x, y, x + w, y + h};
}

}  // namespace splinefig::figures::detail
