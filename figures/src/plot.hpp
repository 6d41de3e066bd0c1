#pragma once
// Internal: drawing one axes panel. Layout (ranges, box, ticks) in plot_layout.cpp, plot
// elements in plot_elements.cpp, guides (frame, ticks, labels, legend) in plot_guides.cpp.
// All coordinates here are layout units (1x pixels); the painter scales them.
#include "generated.hpp"
#include "painter.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/sampling.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace splinefig::figures::detail {

struct Rect {
  double left = 0, top = 0, right = 0, bottom = 0;
  double width() const { return right - left; }
  double height() const { return bottom - top; }
  bool contains(Vec2 p) const { return p.x >= left && p.x <= right && p.y >= top && p.y <= bottom; }
  Rect inflated(double d) const { return {left - d, top - d, right + d, bottom + d}; }
};

// Where data has been drawn, on a 1-unit grid: labels and the legend go where it is empty.
class Occupancy {
 public:
  Occupancy(int width, int height);
  void mark_polyline(const std::vector<Vec2>& pts, double radius);
  void mark_point(Vec2 p, double radius);
  void mark_rect(const Rect& r, int weight = 1);
  long count(const Rect& r) const;  // marked cells inside r

 private:
  int w_, h_;
  std::vector<std::uint16_t> cells_;
};

// The look of the guides (docs/figures.md, house style).
struct Guides {
  Color axis = *render::parse_hex_color("#333333");
  Color grid = *render::parse_hex_color("#e6e6e6");
  Color zero = *render::parse_hex_color("#b3b3b3");
  Font tick_font{12, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  Font label_font{13, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  Font title_font{14, *render::parse_hex_color("#1a1a1a"), true, std::nullopt};
  Font legend_font{12, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  double tick_length = 5;
};

// A text the layout placed, with the rectangle it covers (layout units: its advance width
// and its ink's ascent and descent, turned with it).
struct PlacedText {
  std::string what;  // "title", "x label", "y label", "x tick label", "y tick label"
  std::string text;
  Vec2 at;
  Font font;
  TextAnchor anchor;
  double angle = 0;
  Rect rect;
};

// The rectangle covered by a text of extent `e` anchored at `at` and turned by `angle` degrees
// counter-clockwise about it, as the painter draws it.
Rect text_rect(const render::TextExtent& e, Vec2 at, TextAnchor a, double angle = 0);
// Whether two rectangles overlap or come closer than `gap`.
bool rects_meet(const Rect& a, const Rect& b, double gap = 0);

struct Panel {
  Rect box;
  // The guides' texts: a label per tick (in the ticks' order, maybe empty), then the axis
  // labels and the title.
  std::vector<PlacedText> x_tick_labels, y_tick_labels, labels;
  std::optional<Rect> legend;     // where a legend outside the box goes
  PixelMap map;
  std::vector<Tick> x_ticks, y_ticks;
  std::vector<double> x_minor, y_minor;  // unlabelled: 2..9 times each decade of a log axis
  std::array<double, 2> x_range{}, y_range{};
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

// An axes ready to be laid out and drawn: its generated elements replaced by what they
// generate (generated.hpp) and each spline curve built once.
struct PreparedAxes {
  AxesSpec axes;
  std::map<size_t, Curve> curves;              // per CurveElement, by element index
  std::vector<std::pair<size_t, Path>> paths;  // series whose points are sampled from a path
  std::vector<std::pair<size_t, std::string>> generated;  // series of generated elements, with where
};
// Traced series get rough points (enough for the data range) until sample_paths().
PreparedAxes prepare_axes(const AxesSpec& ax);
// Also checks that generated series stay where log axes can show them (throws SpecFileError).
void sample_paths(PreparedAxes& prepared, const PixelMap& map, double tolerance);

// Pixel position of a tick (db axes: the tick value is in dB already).
double tick_pixel(const AxisMap& m, double value);

// Data bounds of the elements (for axes without a range).
void data_bounds(const PreparedAxes& ax, std::array<double, 2>& xb, std::array<double, 2>& yb, bool& has_x, bool& has_y);

// The layout's refusal: the canvas leaves too small a plot box for the panel's texts.
struct LayoutRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Lays the panel out inside `cell` on a canvas of `canvas_w` x `canvas_h` layout units: every
// text box measured, ticks thinned where their labels would meet, the box shrunk to leave room
// for the texts; throws LayoutRefused when the texts cannot all be placed apart from each
// other and inside the canvas.
Panel layout_panel(const PreparedAxes& prepared, const Rect& cell, double canvas_w, double canvas_h, const Painter& p,
                   const Guides& g);
// The smallest plot box a panel can have (each way).
inline constexpr double kMinPlotBox = 24;
// The least gap between neighbouring tick labels, and between other text boxes.
inline constexpr double kTickLabelGap = 4, kTextGap = 2;

// Draws grid and zero lines (under the data).
void draw_under(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g);
// Draws the elements; returns the series for index.json and the legend entries.
void draw_elements(const PreparedAxes& ax, const Panel& panel, Painter& p, Occupancy& occ,
                   std::vector<SeriesInfo>& series, std::vector<Entry>& legend);
// Frame, ticks, tick labels, axis labels, title (over the data), then the legend.
void draw_over(const AxesSpec& ax, const Panel& panel, Painter& p, const Guides& g);
// Returns the legend's rectangle (none when nothing is drawn).
std::optional<Rect> draw_legend(const AxesSpec& ax, const Panel& panel, const std::vector<Entry>& entries, Painter& p,
                                Occupancy& occ, const Guides& g);
// The inset of a legend inside the plot box.
inline constexpr double kLegendInset = 10;
// The legend's width and height for entries with these labels.
std::array<double, 2> legend_size(const AxesSpec& ax, const std::vector<std::string>& labels, const Painter& p,
                                  const Guides& g);
// The labels of the elements that go to the legend (what draw_elements() will make entries of).
std::vector<std::string> legend_labels(const AxesSpec& ax);
// The gap between the plot box and a legend outside it.
inline constexpr double kLegendOutsideGap = 12;

// Places text next to one of the candidate points (pixels, best first) where it covers the
// least drawn data and stays inside `box`; marks the chosen spot as used and returns the
// text's (left, baseline) anchor.
Vec2 place_label(const std::string& text, const Font& f, const std::vector<Vec2>& candidates, const Rect& box,
                 const Painter& p, Occupancy& occ, double distance = 7);

// The pixel outline of a fill with `under` (plot_fill.cpp): the element's samples, closed by the
// baseline or by the `to` element's samples reversed.
std::vector<Vec2> fill_under_polygon(const PreparedAxes& prepared, const FillElement& f, const PixelMap& map,
                                     double tol);

// Polyline clipping against a rectangle: the runs inside.
std::vector<std::vector<Vec2>> clip_polyline(const std::vector<Vec2>& pts, bool closed, const Rect& r);
std::vector<Vec2> clip_polygon(const std::vector<Vec2>& pts, const Rect& r);

}  // namespace splinefig::figures::detail
