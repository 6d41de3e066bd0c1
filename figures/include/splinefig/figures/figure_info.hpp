#pragma once
// What a laid-out figure tells besides its pixels (docs/figures.md): where each axes' plot box
// is in output pixels, its data ranges and ticks, the colour and look of every labelled series
// and the boxes of its texts, for image-based tests and index.json.
#include <splinefig/figures/axes.hpp>

#include <array>
#include <string>
#include <vector>

namespace splinefig::figures {

struct SeriesInfo {
  std::string label;
  std::string color;  // "#rrggbb"
  std::string kind;   // curve, kernel, series, polygon, fill, rule
  // How else it is drawn, so a reader can tell it from the others without colour: its dash
  // pattern (on/off lengths in pixels at 1x; empty: solid, or no line), whether it is drawn as
  // a line, and its marker ("circle", "square", ...; empty: none).
  std::vector<double> dash = {};
  bool line = true;
  std::string marker = {};
  bool piece = false;  // a labelled piece of a kernel drawn in several colours
};

// A text the layout placed (or a legend, as one box): what it is and the rectangle it covers
// (left, top, right, bottom in output pixels: its advance width, its ink's height).
struct TextBox {
  std::string what;  // "title", "x label", "y label", "x tick label", "y tick label", "legend", "text"
  std::array<double, 4> box{};
};

struct AxesInfo {
  std::array<double, 4> pixel_box{};  // left, top, right, bottom in output pixels
  std::array<double, 2> x_range{}, y_range{};
  Scale x_scale = Scale::Linear, y_scale = Scale::Linear;
  std::vector<SeriesInfo> series;
  std::vector<double> x_ticks, y_ticks;
  // Every text box of the panel: the guides' texts, the legend, the elements' texts (inline
  // labels, [[axes.text]], annotations); the layout keeps the guides' and the legend apart
  // and inside the canvas.
  std::vector<TextBox> text_boxes;
  // The data as drawn, for checks (not written to index.json): each stroked polyline of the
  // elements (a curve as sampled for drawing) and each marker as one point, in output pixels,
  // with the distance from them that its ink reaches (half the stroke's width, half the
  // marker's size).
  struct DataInk {
    std::vector<std::array<double, 2>> points;
    double radius = 0;
  };
  std::vector<DataInk> data_ink;
  // Each inset ([[axes.inset]]) as drawn (not written to index.json): its box and the
  // rectangle it magnifies as marked on the panel, in output pixels (left, top, right, bottom,
  // the exact places before the marks' lines are put on the pixel grid), and its ranges.
  struct Inset {
    std::array<double, 4> pixel_box{}, marked_box{};
    std::array<double, 2> x_range{}, y_range{};
  };
  std::vector<Inset> insets;

  AxisMap x_map() const;  // data -> output pixels, as docs/conventions.md states
  AxisMap y_map() const;
};

// The animated WebP written beside a figure with [animation] (docs/figures.md).
struct AnimationInfo {
  std::string file;           // empty: none written
  int width = 0, height = 0;  // output pixels
  int frames = 0;
  std::string alt;            // the gallery's alt text
};

struct FigureInfo {
  std::string name, title, caption;
  std::string source;  // the source figure it reproduces (the spec's `source`), plain text
  int width = 0, height = 0;  // output pixels
  bool pixel_exact = false;   // the spec's [gallery] pixel_exact: shown at its pixel size
  std::vector<AxesInfo> axes;
  std::vector<std::string> files;  // filled in by whoever writes the files
  AnimationInfo animation;         // likewise
};

}  // namespace splinefig::figures
