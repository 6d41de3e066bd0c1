#pragma once
// A figure spec: the parsed, validated form of a TOML figure file (docs/spec.md).
//
// A spec is a canvas plus a list of items drawn in document order. Items are either
// pixel-space primitives (polyline, polygon, circle, marker, text, image) or axes: panels
// that map data coordinates to pixels and hold plot elements (spline curves, kernels,
// data series, control polygons, fills, labels, annotations). Everything here is plain
// data; load_spec() checks every value so that drawing can assume valid input.
#include <splinefig/base/error.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace splinefig::figures {

using render::Color;
using render::Vec2;

// Where a spec says something: its file as named, the line (0: not known) and the key path
// ("axes[0].curve[2].knots"; empty: the file or a table as a whole). Written "FILE:LINE: KEY",
// without the line or the key where it has none (str()).
struct SpecLocation {
  std::string file;
  std::size_t line = 0;
  std::string key;

  bool empty() const { return file.empty() && line == 0 && key.empty(); }
  // The same file and line, naming `k`.
  SpecLocation with_key(std::string k) const { return {file, line, std::move(k)}; }
  std::string str() const;
  bool operator==(const SpecLocation&) const = default;
};

// A bad spec: the message is one line, "FILE:LINE: KEY: what is wrong". Whatever a message
// repeats from the spec (a value, a key, a label), a control character in it (a newline, an
// ESC) is written as \xNN, so that no message spans lines or drives a terminal; UTF-8 stays.
struct SpecFileError : ErrorOf<std::runtime_error, ErrorKind::bad_input> {
  explicit SpecFileError(const std::string& message);
  explicit SpecFileError(const char* message) : SpecFileError(std::string(message)) {}
  // "AT: message".
  SpecFileError(const SpecLocation& at, const std::string& message) : SpecFileError(at.str() + ": " + message) {}
};

// The limits a spec is checked against (canvas, marks, key parts, ...) are in base/limits.hpp.

// How wide a figure is printed (docs/spec.md, `[canvas] print_width`): read once from the spec
// ("3.5in", "89mm", "8.9cm", "252pt" or a number of inches), with where it was written.
struct PrintWidth {
  double inches = 0;  // > 0 and finite
  SpecLocation origin;
};

struct Canvas {
  int width = 800, height = 500;
  // Unset: font sizes are pixels at 1x. Set: they are points of the printed figure, a point
  // being px_per_pt() pixels at 1x.
  std::optional<PrintWidth> print_width;
  Color background{1, 1, 1, 1};
  // The pixel filter: box, tent or a basis spec, read as the kernel and checked as the renderer
  // checks one (render::validate_pixel_filter).
  Kernel filter = Kernel::box();
  // How coverage and translucent colours blend: in sRGB-encoded values (the default), as SVG and
  // PDF viewers and browsers blend, so that the PNG looks like the figure's SVG and PDF; or in
  // linear light (exact coverage as light), for physical work. The raster comes out in the
  // blend space's encoding; an EXR holds its linear decode (image/srgb.hpp to_linear).
  render::BlendSpace blend = render::BlendSpace::srgb;
  // The coverage error accepted in a pixel where a dense stroke is drawn from its pieces, in
  // [0, 1]; 0 asks for the exact sweep everywhere (render::Scene::set_coverage_tolerance).
  double coverage_tolerance = render::kDefaultCoverageTolerance;
  // Pixels at 1x per printed point, width / (print width in inches x 72); 0 without a print width.
  double px_per_pt() const { return print_width ? width / (print_width->inches * 72) : 0; }
  // Pixels at 1x per printed inch, width / print width, in [kMinDpi, kMaxDpi] (checked when
  // read): the dpi a figure file records when none is asked for; 0 without a print width.
  double print_dpi() const { return print_width ? width / print_width->inches : 0; }
};

// The font sizes of a figure's text roles, in pixels at 1x. A spec with a print width states
// them in points (docs/spec.md): they are converted once, when it is read. These defaults are
// the sizes of a spec without a print width.
struct TextSizes {
  double title = 18;         // the figure's title (bold)
  double panel_title = 14;   // an axes' title (bold)
  double label = 13;         // axis labels
  double tick = 12;          // tick labels
  double legend = 12;        // legend entries and the legend's title
  double inline_label = 15;  // element labels set beside the data
  double text = 13;          // [[text]], [[axes.text]] and [[axes.annotation]] without a size
};
// The defaults in points, for a spec with a print width.
inline constexpr TextSizes kTextSizesPt{10, 9, 9, 8, 8, 9, 8};

// A stroke's look: width in pixels at 1x, colour, joins, caps and dashes.
struct Pen {
  Color color{0, 0, 0, 1};
  render::StrokeStyle style;
};

struct Font {
  double size = 13;
  Color color{0.0103298f, 0.0103298f, 0.0103298f, 1};  // #1a1a1a in linear light
  bool bold = false;
  std::optional<render::FontFamily> family;  // unset: the figure's font_family
};

struct TextAnchor {
  render::HAlign halign = render::HAlign::Left;
  render::VAlign valign = render::VAlign::Baseline;
};

// ---- Pixel-space primitives -------------------------------------------------------------

struct PolylineItem {
  std::vector<Vec2> points;
  bool closed = false;
  Pen pen;
};

struct PolygonItem {
  std::vector<std::vector<Vec2>> contours;
  render::FillRule rule = render::FillRule::NonZero;
  Color color;
};

struct CircleItem {
  Vec2 centre;
  double radius = 1;
  std::optional<Color> fill;
  std::optional<Pen> stroke;
};

struct MarkerItem {
  std::vector<Vec2> points;
  render::Marker shape = render::Marker::Circle;
  double size = 6;
  Color color;
};

struct TextItem {
  Vec2 at;
  std::string text;
  Font font;
  TextAnchor anchor;
};

// Pixels to place: from a file (any format OpenImageIO reads) or given inline as rows of
// grey values or rows of [r,g,b(,a)] in linear light. Sampled nearest (pixel art) or
// bilinear into the target rectangle.
struct Raster {
  std::string file;  // resolved path, or empty when data is inline
  int width = 0, height = 0, channels = 0;
  std::vector<float> data;  // row-major, `channels` floats per pixel (inline data only)
  bool nearest = true;
  bool srgb_data = false;   // inline data given as sRGB values
};

struct ImageItem {
  Raster raster;
  Vec2 at;      // top-left corner in pixels
  Vec2 size;    // width, height in pixels (default: the raster's own size)
  bool has_size = false;
};

// ---- Plot elements (inside axes, data coordinates) --------------------------------------

// How an element's label is shown.
struct Labelling {
  std::string label;                 // empty: no label
  bool in_legend = true;             // false: placed next to the data instead
  std::optional<double> label_at;    // data x (or curve parameter) where an inline label goes
  std::optional<Vec2> label_offset;  // pixel offset of an inline label from its data point
};

// A spline through/near the knots: X(t) = sum_j x[j] k(t - j), sampled adaptively to
// flatness <= 0.05 px at the output scale and stroked as one path.
struct CurveElement {
  std::vector<Vec2> knots;
  std::string basis_spec;
  Basis basis;
  Ends ends = Ends::open;
  int marks = 0;              // markers along the curve (0: none)
  bool marks_by_arclength = false;  // evenly spaced in arc length instead of in t
  double mark_size = 5;
  std::optional<Color> mark_color;
  std::optional<Color> color;  // unset: taken from the axes palette
  render::StrokeStyle stroke;
  Labelling label;
  bool show_knots = false;
  double knot_size = 5;
};

// A basis function k(s) drawn as its pieces (each polynomial piece on one unit interval).
struct KernelElement {
  std::string basis_spec;
  Basis basis;
  std::optional<std::array<double, 2>> range;  // default: the kernel's support
  std::optional<Color> color;                  // one colour for the whole kernel
  std::vector<Color> piece_colors;             // per piece, left to right
  std::vector<std::string> piece_labels;       // per piece, left to right, inline
  double scale = 1;                            // y multiplier
  render::StrokeStyle stroke;
  Labelling label;
  bool show_knots = false;                     // dots at the integer knots
  double knot_size = 5;
};

enum class SeriesMode { Line, Markers, LineMarkers, Steps, Stems };

// How data points are drawn: the keys of [[axes.series]] other than the data.
struct SeriesLook {
  SeriesMode mode = SeriesMode::Line;
  bool closed = false;
  std::optional<Color> color;  // unset: taken from the axes palette
  render::StrokeStyle stroke;
  render::Marker marker = render::Marker::Circle;
  double marker_size = 6;
  std::optional<Color> marker_color;
  Labelling label;
};

// Generic data: points joined by lines, marked, stepped or stemmed. Control polygons
// ([[axes.polygon]]) and marker sets ([[axes.markers]]) are series with other defaults.
struct SeriesElement {
  std::vector<Vec2> points;
  SeriesLook look;
  // A generated curve that is a cubic spline: its Bezier control points in data space (3n + 1,
  // the curve itself), drawn exactly on linear axes where it fits the axes box; `points` is its
  // polyline. Empty for other series.
  std::vector<Vec2> bezier = {};
};

// A filled area: between y and y2 (or a baseline) over x, or a polygon in data space.
struct FillElement {
  std::vector<Vec2> upper;
  std::vector<Vec2> lower;  // same x's reversed at drawing; empty when polygon
  bool polygon = false;
  Color color;
  Labelling label;
  // `under = "LABEL"`: the area between the curve, kernel or series of that label and the
  // line y = baseline, or the element labelled `to` (upper and lower are then empty).
  std::string under, to;
  double baseline = 0;
  SpecLocation origin, to_origin;  // of `under` and `to`, for the check of the labels
};

struct TextElement {
  Vec2 at;  // data
  std::string text;
  Vec2 offset;  // pixels
  Font font;
  TextAnchor anchor;
};

// Text at `at` with an arrow from near the text to `to` (both data).
struct AnnotationElement {
  Vec2 at, to;
  std::string text;
  Font font;
  TextAnchor anchor;
  Color arrow_color;
  double arrow_width = 1;
};

// A horizontal or vertical reference line across the whole axes.
struct RuleElement {
  bool horizontal = true;
  double value = 0;
  Pen pen;
  Labelling label;
};

struct ImageElement {
  Raster raster;
  std::array<double, 4> extent{};  // x0, x1, y0, y1 in data
};

// ---- Generated plot elements ----------------------------------------------------------
// Elements whose data the layout computes with the spline library, the filter analysis or the
// resampler (docs/companion.md, docs/resample.md). The spec holds only their parameters; the
// layout turns them into series (curves sampled to 0.05 px like [[axes.curve]]) or an image.
// `where` is the location of the element's table and `origin` that of the key a computation
// can reject, for messages.

struct InterpElement {  // [[axes.interp]]: the spline through data
  SpecLocation where;
  enum class EndMode { Relaxed, Clamped, Periodic };
  enum class Show { Curve, Control, Bezier };
  std::vector<Vec2> points;
  EndMode ends = EndMode::Relaxed;
  Show show = Show::Curve;
  std::optional<Vec2> start_velocity, end_velocity;  // clamped ends only
  SeriesLook look;
  SpecLocation origin;
};

struct RelaxedBsplineElement {  // [[axes.relaxed_bspline]]
  SpecLocation where;
  enum class Show { Curve, Joints, Division, Bezier, AFrames };
  std::vector<Vec2> points;
  Show show = Show::Curve;
  int aframe = 0;  // show = aframes: only the A-frame with apex B_aframe (1 .. n-1); 0: all
  SeriesLook look;
};

struct BezierElement {  // [[axes.bezier]]: one Bezier curve of any degree
  SpecLocation where;
  std::vector<Vec2> points;
  SeriesLook look;
};

struct LagrangeElement {  // [[axes.lagrange]]: y(x) through the data
  SpecLocation where;
  std::vector<Vec2> points;
  std::optional<std::array<double, 2>> range;  // default: the data's x extent
  SeriesLook look;
  SpecLocation origin;
};

struct RelaxedBasisElement {  // [[axes.relaxed_basis]]: f_k of relaxed interpolation
  SpecLocation where;
  int n = 4, k = 0;
  SeriesLook look;
};

struct SubdivisionElement {  // [[axes.subdivision]]
  SpecLocation where;
  std::vector<Vec2> points;
  int steps = 1;
  bool limit = false;  // the limit points instead of the refined polygon
  SeriesLook look;
};

struct LocalBetasElement {  // [[axes.local_betas]]: one (b1, b2) per knot
  SpecLocation where;
  std::vector<Vec2> knots;
  std::vector<std::array<double, 2>> betas;
  Ends ends = Ends::open;
  SeriesLook look;
  SpecLocation origin;
};

struct InbetweenElement {  // [[axes.inbetween]]: frames between keyframes
  enum class Interpolation { Relaxed, Linear };
  SpecLocation where;
  std::vector<std::vector<Vec2>> frames;  // equally long
  double t = 0;                           // the one frame drawn, when steps == 0
  int steps = 0;                          // > 0: a filmstrip, the frames at t = i / steps, 0 .. last keyframe
  Interpolation interpolation = Interpolation::Relaxed;
  Vec2 shift{0, 0};                       // a filmstrip's i-th frame is drawn moved by i * shift
  std::optional<Color> key_color;         // a filmstrip's keyframes (unset: the look's colour)
  Labelling key_label;                    // a filmstrip's keyframes' legend entry
  SeriesLook look;
};

struct FilterCurveElement {  // [[axes.filter]]: k(s) of a filter spec
  SpecLocation where;
  Kernel filter;  // a basis spec, box, tent or lanczos3, read as the kernel
  std::optional<std::array<double, 2>> range;  // default: the support
  SeriesLook look;
};

struct ResponseElement {  // [[axes.response]]: |K(f)|, f in cycles per sample
  SpecLocation where;
  Kernel filter;
  std::array<double, 2> range{0, 2};
  SeriesLook look;
};

struct StepElement {  // [[axes.step]]: a filter's reconstruction of samples
  SpecLocation where;
  Kernel filter;
  std::vector<double> values{0, 0, 0, 0, 1, 1, 1, 1};
  Edge edge = Edge::clamp;
  bool interpolating = false;
  std::optional<std::array<double, 2>> range;  // default: [-1/2, n - 1/2]
  SeriesLook look;
  SpecLocation origin;
};

struct ZoneplateElement {  // [[axes.zoneplate]]: a zone plate resampled, as an image
  SpecLocation where;
  Kernel filter;
  int source = 64, size = 512;
  Edge edge = Edge::mirror;
  bool interpolating = false;
  std::array<int, 4> crop{0, 0, 512, 512};  // x, y, width, height in output pixels
  std::array<double, 4> extent{};
  bool nearest = true;
  double contrast = 1;
  SpecLocation origin;
};

using PlotElement = std::variant<CurveElement, KernelElement, SeriesElement, FillElement, TextElement,
                                 AnnotationElement, RuleElement, ImageElement, InterpElement, RelaxedBsplineElement,
                                 BezierElement, LagrangeElement, RelaxedBasisElement, SubdivisionElement,
                                 LocalBetasElement, InbetweenElement, FilterCurveElement, ResponseElement, StepElement,
                                 ZoneplateElement>;

enum class Scale { Linear, Log, Decibel };
enum class Frame { Box, LeftBottom, None };

struct AxisSpec {
  std::optional<std::array<double, 2>> range;  // unset: from the data
  Scale scale = Scale::Linear;
  std::string label;
  bool label_rotated = false;                   // y only: the label reads upwards beside the axis
  std::optional<std::vector<double>> ticks;     // unset: nice 1-2-5 ticks; empty: none
  std::vector<std::string> tick_labels;         // with explicit ticks only
  std::optional<double> tick_step;              // force the step of automatic ticks
  std::vector<double> marks;                    // knots marked on the axis (small triangles)
};

// OutsideRight: right of the plot box, its top level with the box's; the box narrows to make room.
enum class LegendPlace { Auto, None, UpperLeft, UpperRight, LowerLeft, LowerRight, UpperCenter, LowerCenter, OutsideRight };

// A magnified view of a rectangle of its axes' data (docs/spec.md, [[axes.inset]]): a region
// of the plot box drawing the axes' elements again at the inset's ranges, the rectangle marked
// on the axes and joined to the inset by connector lines.
struct InsetSpec {
  std::array<double, 2> x_range{}, y_range{};  // lo < hi, in the axes' units
  // [x, y, width, height]: the lower-left corner and the size, fractions of the plot box;
  // none: placed where it covers no data, at `size`.
  std::optional<std::array<double, 4>> at;
  std::array<double, 2> size{0.4, 0.4};
  SpecLocation where;  // of the [[axes.inset]] table
};

struct AxesSpec {
  AxisSpec x, y;
  std::string title;
  bool grid = false;
  bool equal_aspect = false;
  bool zero_line = false;          // thin lines at x = 0 and y = 0 where inside
  Frame frame = Frame::LeftBottom;
  LegendPlace legend = LegendPlace::Auto;
  std::string legend_title;
  int legend_columns = 1;
  // The legend's entries by label, first to last (the order a parameter runs); entries it does
  // not name follow in drawing order.
  std::vector<std::string> legend_order;
  std::string palette = "viridis";
  bool dash_cycle = true;  // elements coloured from the palette also take the cycle's dashes
  std::optional<std::array<int, 2>> cell;       // [row, col] in the figure's layout grid
  std::optional<std::array<double, 4>> box;     // explicit pixel box [left, top, right, bottom]
  std::vector<PlotElement> elements;
  std::vector<InsetSpec> insets;
  SpecLocation where;  // of the [axes] header (no key), for messages
  // Of each element's table (parallel to `elements`), naming it in errors found while drawing;
  // may be shorter (then messages name the axes).
  std::vector<SpecLocation> element_origins;
};

using Item = std::variant<PolylineItem, PolygonItem, CircleItem, MarkerItem, TextItem, ImageItem, AxesSpec>;

struct Layout {
  int rows = 1, cols = 1;
  double margin = 16;   // around the panel grid, pixels at 1x
  double spacing = 24;  // between panels
};

// A computed field of the caption, `{=name}` in its text (docs/spec.md): a value of one plot
// element's data, read by the loader (src/load/caption_fields.cpp) and worked out when the
// figure is laid out (src/layout/caption_text.cpp).
struct CaptionField {
  std::string name;     // as written in the caption
  std::string element;  // the element's key path, "axes[1].bezier[0]"
  std::string function; // point, x, y, d1, d2, curvature, max_y, ..., knot, count, b1, b2
  std::vector<double> args;
  int decimals = 2;
  bool fraction = false;  // printed as p/q in lowest terms (q <= 1000) instead of with decimals
  SpecLocation origin;  // of its [[caption_field]] table, for messages
};

// [animation]: the figure's filmstrips ([[axes.inbetween]] with steps = N) also written as an
// animated WebP (docs/figures.md): frame i shows the panels named in `panels` side by side, each
// filmstrip at t = i / steps alone and unshifted, over its keyframes drawn faintly, the keyframes
// themselves marked as in the strip.
struct AnimationSpec {
  int delay = 200;              // ms an in-between frame is shown
  int key_delay = 0;            // ms a keyframe is shown; 0: delay
  int loops = 0;                // plays; 0: for ever
  int width = 720, height = 400;  // the animation's canvas, pixels at 1x
  std::vector<int> panels;      // indices of the spec's [[axes]]; empty: every one holding a filmstrip
  std::string alt;              // the gallery's alt text for it; empty: made from the title
  SpecLocation where;           // of the [animation] header, for messages
};

struct FigureSpec {
  std::string name;     // file stem
  std::string path;     // where it was read from
  std::string title;    // drawn at the top unless show_title = false; also in index/gallery
  std::string caption;  // gallery and index only; {=name} fields filled in when built
  std::string source;   // the figure of the source texts it reproduces or illustrates, as a reader cites it
  std::vector<CaptionField> caption_fields;
  bool show_title = true;
  // [gallery] pixel_exact: the figure's point is its pixels (aliasing, a zone plate), so the
  // gallery shows it at its pixel size, never resampled by the browser.
  bool pixel_exact = false;
  TextSizes sizes;  // pixels at 1x
  render::FontFamily font_family = render::FontFamily::Sans;  // of every text without its own
  SpecLocation title_origin;  // of title_size (or title, or canvas.print_width), for messages
  Canvas canvas;
  Layout layout;
  std::vector<Item> items;  // in document order
  std::optional<AnimationSpec> animation;  // [animation]
  // Of each item's table (parallel to `items`), naming it in errors found while drawing; may be
  // shorter (then messages name the file).
  std::vector<SpecLocation> item_origins;
};

// Reads and validates a spec file. Throws SpecFileError (one line: file, line, key).
FigureSpec load_spec(const std::string& path);
// The same from text; `name` stands for the file in messages, `base_dir` resolves image paths.
FigureSpec parse_spec(std::string_view text, const std::string& name, const std::string& base_dir = ".");

}  // namespace splinefig::figures
