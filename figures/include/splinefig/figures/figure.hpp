#pragma once
// Figures: a spec laid out and drawn. render_figure() turns a FigureSpec into an image
// plus the facts that image-based tests and index.json need (docs/figures.md): where each
// axes' plot box is in pixels, its data ranges, and the colour of every labelled series.
#include <splinefig/figures/axes.hpp>
#include <splinefig/figures/spec.hpp>

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

  AxisMap x_map() const;  // data -> output pixels, as docs/conventions.md states
  AxisMap y_map() const;
};

struct FigureInfo {
  std::string name, title, caption;
  int width = 0, height = 0;  // output pixels
  std::vector<AxesInfo> axes;
  std::vector<std::string> files;  // filled in by whoever writes the files
};

struct RenderOptions {
  double scale = 1;  // output pixels per spec pixel
  int threads = 0;   // <= 0: all hardware threads
};

struct RenderedFigure {
  Image image;
  FigureInfo info;
};

// Throws SpecFileError if the scaled canvas is too large, std::runtime_error if an image
// element cannot be read.
RenderedFigure render_figure(const FigureSpec& spec, const RenderOptions& options = {});

// The figure as a renderer scene (what render_figure rasterizes, and what vector/ writes as
// SVG or PDF), at `scale` output pixels per spec pixel.
struct FigureScene {
  render::Scene scene;
  FigureInfo info;
};
FigureScene figure_scene(const FigureSpec& spec, double scale = 1);

// The figure of the spec file at `path`, rendered: load_spec() then render_figure(), for tests
// that check a spec against a reference in one line,
//   CHECK_THAT(render_spec_to_image("fig.toml"), MatchesReference("fig.png"));
// Throws SpecFileError (a bad spec, a canvas too large at options.scale) as those do.
Image render_spec_to_image(const std::string& path, const RenderOptions& options = {});

// The layout alone (no rasterization): the same info render_figure() reports.
FigureInfo layout_figure(const FigureSpec& spec, double scale = 1);

// Checks the scaled canvas against the size limits; throws SpecFileError naming `what`.
void check_scaled_canvas(const FigureSpec& spec, double scale, const std::string& what);

}  // namespace splinefig::figures
