#pragma once
// Internal: drawing one laid-out axes panel (layout/panel.hpp) into the painter's display list:
// its elements in plot_elements.cpp, its guides (grid, frame, ticks, labels, legend) in
// plot_guides.cpp, the occupancy grid and clipping in plot_geometry.cpp and clip_path.hpp.
// All coordinates here are layout units (1x pixels); the painter scales them.
#include "painter.hpp"
#include "../layout/panel.hpp"

#include <splinefig/figures/figure_info.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace splinefig::figures::detail {

// Where data has been drawn, on a 1-unit grid: labels and the legend go where it is empty.
// Which cells of the canvas data and labels already cover, for placing labels where they hide
// nothing: a mark covers a square of cells (mark_point), a polyline a square every 1.5 px along
// it, a rectangle its cells. Marks are kept as per-row spans (+1 where a span begins, -1 after
// it ends) and resolved into the grid when it is next read, so a mark costs its rows, not its
// cells: a series 300 px wide of 10^5 points 400 px long marked 2.4e12 cells one by one.
class Occupancy {
 public:
  Occupancy(int width, int height);
  void mark_polyline(const std::vector<Vec2>& pts, double radius);
  void mark_point(Vec2 p, double radius);
  void mark_rect(const Rect& r);
  long count(const Rect& r);  // covered cells inside r (cells off the canvas count 4)

 private:
  void span(int y, int x0, int x1);  // cells x0..x1 of row y (on the canvas, x0 <= x1)
  void resolve();
  int w_, h_;
  std::vector<std::uint8_t> covered_;  // w x h
  std::vector<std::int32_t> starts_;   // (w + 1) x h: spans beginning minus spans ended before each cell
  std::uint64_t pending_ = 0;          // spans not yet resolved
  int pending_y0_ = 1 << 30, pending_y1_ = -1;  // the rows they lie in
};

// A legend entry or an inline label's source: what to draw as the sample.
struct Entry {
  std::string label;
  Color color;
  render::StrokeStyle style;
  bool line = true, markers = false, patch = false;
  render::Marker marker = render::Marker::Circle;
  double marker_size = 6;
};

// Draws grid and zero lines (under the data).
void draw_under(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g);
// Draws the elements; returns the series for index.json and the legend entries.
void draw_elements(const PreparedAxes& ax, const Panel& panel, Painter& p, Occupancy& occ,
                   std::vector<SeriesInfo>& series, std::vector<Entry>& legend, std::vector<AxesInfo::DataInk>& ink,
                   const Guides& g);
// Frame, ticks, tick labels, axis labels, title (over the data), then the legend.
void draw_over(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g);
// Returns the legend's rectangle (none when nothing is drawn).
// The legend goes where it covers no data inside the box; when no spot is free and
// `require_free`, nothing is drawn and `*crowded` is set (the caller then puts it outside);
// otherwise the spot that covers least. Entries in the axes' legend_order, filled down columns.
std::optional<Rect> draw_legend(const AxesSpec& ax, const Panel& panel, const std::vector<Entry>& entries, Painter& p,
                                Occupancy& occ, const Guides& g, bool require_free = false, bool* crowded = nullptr);

// Marks the rectangles the axes' insets magnify as used (before the legend is placed).
void mark_inset_sources(const AxesSpec& ax, const Panel& panel, Occupancy& occ);
// Draws the axes' insets ([[axes.inset]], plot_inset.cpp): each where it covers no data (or at
// its `at`), the elements again at its ranges, its box, the rectangle it magnifies marked on
// the panel and the connectors between them; reports each in `out`.
void draw_insets(const PreparedAxes& prepared, const Panel& panel, Painter& p, Occupancy& occ, const Guides& g,
                 std::vector<AxesInfo::Inset>& out);
// Places text next to one of the candidate points (pixels, best first) where it covers the
// least drawn data and stays inside `box`; marks the chosen spot as used and returns the
// text's (left, baseline) anchor.
Vec2 place_label(const std::string& text, const Font& f, const std::vector<Vec2>& candidates, const Rect& box,
                 const Painter& p, Occupancy& occ, double distance = 7);

// Polyline clipping against a rectangle: the runs inside.
std::vector<std::vector<Vec2>> clip_polyline(const std::vector<Vec2>& pts, bool closed, const Rect& r);
std::vector<Vec2> clip_polygon(const std::vector<Vec2>& pts, const Rect& r);

}  // namespace splinefig::figures::detail
