#pragma once
// Internal: one axes panel laid out: its generated elements computed and its curves built
// (plot_prepare.cpp), its ranges, plot box, ticks and the guides' texts placed (plot_layout.cpp),
// the outline of a fill under an element (plot_fill.cpp). Drawing it is paint/draw.hpp's.
// All coordinates here are layout units (1x pixels); the painter scales them.
#include "generated.hpp"
#include "../naming.hpp"
#include "../text/measure.hpp"

#include <splinefig/figures/sampling.hpp>

#include <array>
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

// The look of the guides (docs/figures.md, house style), their fonts of the figure's text
// sizes (pixels at 1x; the defaults those of a spec without a print width).
struct Guides {
  static Color ink() { return *render::parse_hex_color("#1a1a1a"); }
  Guides() = default;
  explicit Guides(const TextSizes& s)
      : tick_font{s.tick, ink(), false, std::nullopt},
        label_font{s.label, ink(), false, std::nullopt},
        title_font{s.panel_title, ink(), true, std::nullopt},
        legend_font{s.legend, ink(), false, std::nullopt},
        inline_font{s.inline_label, {}, false, std::nullopt} {}
  Color axis = *render::parse_hex_color("#333333");
  Color grid = *render::parse_hex_color("#e6e6e6");
  Color zero = *render::parse_hex_color("#b3b3b3");
  Font tick_font{12, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  Font label_font{13, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  Font title_font{14, *render::parse_hex_color("#1a1a1a"), true, std::nullopt};
  Font legend_font{12, *render::parse_hex_color("#1a1a1a"), false, std::nullopt};
  Font inline_font{15, {}, false, std::nullopt};  // labels set beside the data, in their element's colour
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

// An axes ready to be laid out and drawn: its generated elements replaced by what they
// generate (generated.hpp) and each spline curve built once.
struct PreparedAxes {
  AxesSpec axes;
  std::map<size_t, Curve> curves;              // per CurveElement, by element index
  std::vector<std::pair<size_t, Path>> paths;  // series whose points are sampled from a path
  std::vector<std::pair<size_t, SpecLocation>> generated;  // series of generated elements, with where
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
struct LayoutRefused : ErrorOf<std::runtime_error, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

// Lays the panel out inside `cell` on a canvas of `canvas_w` x `canvas_h` layout units: every
// text box measured, ticks thinned where their labels would meet, the box shrunk to leave room
// for the texts; throws LayoutRefused when the texts cannot all be placed apart from each
// other and inside the canvas.
Panel layout_panel(const PreparedAxes& prepared, const Rect& cell, double canvas_w, double canvas_h, const TextMeasure& p,
                   const Guides& g);
// The smallest plot box a panel can have (each way).
inline constexpr double kMinPlotBox = 24;
// The least gap between neighbouring tick labels, and between other text boxes.
inline constexpr double kTickLabelGap = 4, kTextGap = 2;

// The inset of a legend inside the plot box; its padding, a sample's width, the gap after it,
// a row's height and the gap between columns.
inline constexpr double kLegendInset = 10;
inline constexpr double kLegendPad = 8, kLegendSample = 28, kLegendGap = 8, kLegendRow = 19, kLegendColumnGap = 16;
// A legend row's height for the guides' legend font: kLegendRow for the 12 px font, in proportion.
inline double legend_row(const Guides& g) { return kLegendRow * g.legend_font.size / 12; }
// A legend of `entries` asked for `columns` columns is filled column by column (down the first
// column, then the next): its rows, and the columns that takes (fewer when the last would be
// empty, 6 entries in 5 columns take 3 of 2 rows).
int legend_rows(int columns, std::size_t entries);
int legend_columns_used(int columns, std::size_t entries);
// The legend's width and height for entries with these labels.
std::array<double, 2> legend_size(const AxesSpec& ax, const std::vector<std::string>& labels, const TextMeasure& p,
                                  const Guides& g);
// The labels of the elements that go to the legend (what draw_elements() will make entries of).
std::vector<std::string> legend_labels(const AxesSpec& ax);
// The gap between the plot box and a legend outside it.
inline constexpr double kLegendOutsideGap = 12;

// The pixel outline of a fill with `under` (plot_fill.cpp): the element's samples, closed by the
// baseline or by the `to` element's samples reversed.
std::vector<Vec2> fill_under_polygon(const PreparedAxes& prepared, const FillElement& f, const PixelMap& map,
                                     double tol);

}  // namespace splinefig::figures::detail
