// The figure spec loader, part 2: [axes] panels and their plot elements (docs/spec.md).
#include "spec_parse.hpp"

#include <splinefig/figures/axes.hpp>
#include <splinefig/figures/palette.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace splinefig::figures::detail {
namespace {

const Color kGrey = *render::parse_hex_color("#888888");

render::StrokeStyle curve_stroke() {
  render::StrokeStyle s;
  s.width = 2;
  s.join = render::Join::Round;
  s.cap = render::Cap::Round;
  return s;
}

void parse_axis(TableReader& r, char name, AxisSpec& axis) {
  const std::string p(1, name);
  if (r.has(p + "_range")) {
    auto v = r.numbers(p + "_range");
    if (v.size() != 2) r.fail(p + "_range", "expected [" + p + "0, " + p + "1]");
    if (v[0] == v[1]) r.fail(p + "_range", p + "0 = " + p + "1 (the axis would have no extent)");
    if (const std::string why = range_problem(v[0], v[1]); !why.empty()) r.fail(p + "_range", why);
    axis.range = std::array<double, 2>{v[0], v[1]};
  }
  axis.scale = static_cast<Scale>(r.choice(p + "_scale", {"linear", "log", "db"}, 0));
  if (axis.scale == Scale::Log && axis.range && ((*axis.range)[0] <= 0 || (*axis.range)[1] <= 0))
    r.fail(p + "_range", "a log axis needs a positive range");
  axis.label = r.label(p + "_label", "");
  if (p == "y") axis.label_rotated = r.boolean("y_label_rotated", false);
  if (r.has(p + "_ticks")) {
    const toml::node* n = r.node(p + "_ticks");
    if (auto b = n->as_boolean()) {
      if (!b->get()) axis.ticks = std::vector<double>{};
    } else {
      axis.ticks = r.numbers(p + "_ticks");
      if (axis.ticks->size() > static_cast<std::size_t>(kMaxTicks))
        r.fail(p + "_ticks", std::to_string(axis.ticks->size()) + " ticks (limit " + std::to_string(kMaxTicks) + ")");
    }
  }
  axis.tick_labels = r.labels(p + "_tick_labels");
  if (!axis.tick_labels.empty() && (!axis.ticks || axis.ticks->size() != axis.tick_labels.size()))
    r.fail(p + "_tick_labels", "needs explicit " + p + "_ticks of the same length");
  if (auto s = r.opt_number(p + "_tick_step")) {
    if (!(*s > 0)) r.fail(p + "_tick_step", "must be positive");
    if (axis.range && axis.scale != Scale::Log && !(std::abs((*axis.range)[1] - (*axis.range)[0]) / *s < kMaxTicks))
      r.fail(p + "_tick_step", "gives more than " + std::to_string(kMaxTicks) + " ticks over the " + p + "_range");
    axis.tick_step = *s;
  }
  axis.marks = r.numbers(p + "_marks");
  if (axis.marks.size() > kMaxMarks)
    r.fail(p + "_marks", std::to_string(axis.marks.size()) + " marks (limit " + std::to_string(kMaxMarks) + ")");
}

std::vector<Vec2> xy_data(TableReader& r, bool required, const char* what) {
  std::vector<Vec2> pts;
  if (r.has("points")) {
    if (r.has("x") || r.has("y")) r.fail("points", "give either points or x and y, not both");
    pts = r.points("points");
  } else if (r.has("x") || r.has("y")) {
    auto x = r.numbers("x");
    auto y = r.numbers("y");
    if (!r.has("y")) r.fail("x", "x without y");
    if (!r.has("x")) r.fail("y", "y without x");
    if (x.size() != y.size())
      r.fail("y", "x has " + std::to_string(x.size()) + " values but y has " + std::to_string(y.size()));
    for (size_t i = 0; i < x.size(); ++i) pts.push_back({x[i], y[i]});
  }
  if (required && pts.empty()) r.fail(r.has("x") ? "x" : "points", std::string(what) + " without data (give points or x and y)");
  return pts;
}

CurveElement parse_curve(TableReader& r) {
  CurveElement c;
  c.knots = r.points("knots");
  if (c.knots.empty()) r.fail("knots", "a curve needs knots = [[x, y], ...]");
  c.basis_spec = r.string("basis", "catmull-rom");
  c.basis = checked_basis(r, "basis", c.basis_spec);
  c.ends = static_cast<Ends>(r.choice("ends", {"open", "double", "closed"}, 0));
  size_t need = min_knots(c.basis, c.ends);
  if (c.knots.size() < need)
    r.fail("knots", std::to_string(c.knots.size()) + " knots are too few for one piece of this curve with " +
                        to_string(c.ends) + " ends (need " + std::to_string(need) + ")");
  c.marks = r.integer("marks", 0, 0, static_cast<int>(kMaxMarks));
  c.marks_by_arclength = r.choice("mark_spacing", {"parameter", "arclength"}, 0) == 1;
  c.mark_size = r.positive("mark_size", c.mark_size);
  c.mark_color = r.opt_color("mark_color");
  c.color = r.opt_color("color");
  c.stroke = r.stroke(curve_stroke());
  c.label = parse_labelling(r);
  c.show_knots = r.boolean("show_knots", false);
  c.knot_size = r.positive("knot_size", c.knot_size);
  return c;
}

KernelElement parse_kernel_element(TableReader& r) {
  KernelElement k;
  k.basis_spec = r.string("basis", "");
  if (k.basis_spec.empty()) r.fail("basis", "a kernel needs basis = \"SPEC\"");
  k.basis = checked_basis(r, "basis", k.basis_spec);
  if (r.has("range")) {
    auto v = r.numbers("range");
    if (v.size() != 2 || !(v[0] < v[1])) r.fail("range", "expected [s0, s1] with s0 < s1");
    k.range = std::array<double, 2>{v[0], v[1]};
  }
  k.color = r.opt_color("color");
  k.piece_colors = r.colors("colors");
  k.piece_labels = r.labels("labels");
  size_t pieces = static_cast<size_t>(k.basis.order());
  if (!k.piece_colors.empty() && k.piece_colors.size() != pieces)
    r.fail("colors", "the kernel has " + std::to_string(pieces) + " pieces, " + std::to_string(k.piece_colors.size()) + " colours given");
  if (!k.piece_labels.empty() && k.piece_labels.size() != pieces)
    r.fail("labels", "the kernel has " + std::to_string(pieces) + " pieces, " + std::to_string(k.piece_labels.size()) + " labels given");
  if (k.color && !k.piece_colors.empty()) r.fail("colors", "give either color or colors, not both");
  k.scale = r.number("scale", 1);
  k.stroke = r.stroke(curve_stroke());
  k.label = parse_labelling(r);
  k.show_knots = r.boolean("show_knots", false);
  k.knot_size = r.positive("knot_size", k.knot_size);
  return k;
}

SeriesElement parse_series(TableReader& r, LookDefault defaults, const char* what) {
  SeriesElement s;
  s.points = xy_data(r, true, what);
  s.look = parse_series_look(r, defaults);
  return s;
}

FillElement parse_fill(TableReader& r) {
  if (r.has("under")) return parse_fill_under(r);  // spec_fill.cpp
  FillElement f;
  if (r.has("points")) {
    f.polygon = true;
    f.upper = r.points("points");
    if (f.upper.size() < 3) r.fail("points", "a filled polygon needs at least 3 points");
  } else {
    auto x = r.numbers("x");
    auto y = r.numbers("y");
    if (x.empty()) r.fail("x", "a fill without data (give points, or x and y)");
    if (x.size() != y.size()) r.fail("y", "x and y differ in length");
    std::vector<double> y2;
    if (r.has("y2")) {
      y2 = r.numbers("y2");
      if (y2.size() != x.size()) r.fail("y2", "x and y2 differ in length");
    } else {
      y2.assign(x.size(), r.number("baseline", 0));
    }
    for (size_t i = 0; i < x.size(); ++i) {
      f.upper.push_back({x[i], y[i]});
      f.lower.push_back({x[i], y2[i]});
    }
  }
  f.color = r.color("color", *render::parse_hex_color("#1f77b440"));
  f.label = parse_labelling(r);
  return f;
}

TextElement parse_text_element(TableReader& r) {
  TextElement t;
  t.at = r.required_point("at", "text needs at = [x, y] (data)");
  t.text = r.required_label("text", "text needs text = \"...\"");
  t.offset = r.opt_point("offset").value_or(Vec2{0, 0});
  t.font.size = r.text_size();
  t.font = r.font(t.font);
  t.anchor = r.anchor({render::HAlign::Center, render::VAlign::Middle});
  return t;
}

AnnotationElement parse_annotation(TableReader& r) {
  AnnotationElement a;
  a.at = r.required_point("at", "an annotation needs at = [x, y] (the text, data)");
  a.to = r.required_point("to", "an annotation needs to = [x, y] (the arrow's tip, data)");
  a.text = r.required_label("text", "an annotation needs text = \"...\"");
  a.font.size = r.text_size();
  a.font = r.font(a.font);
  a.anchor = r.anchor({render::HAlign::Center, render::VAlign::Middle});
  a.arrow_color = r.color("arrow_color", a.font.color);
  a.arrow_width = r.positive("arrow_width", 1);
  return a;
}

RuleElement parse_rule(TableReader& r, bool horizontal) {
  RuleElement e;
  e.horizontal = horizontal;
  const char* key = horizontal ? "y" : "x";
  auto v = r.opt_number(key);
  if (!v) r.fail(key, std::string(horizontal ? "an hline needs y = VALUE" : "a vline needs x = VALUE"));
  e.value = *v;
  e.pen.color = r.color("color", kGrey);
  render::StrokeStyle st;
  st.width = 1;
  e.pen.style = r.stroke(st);
  e.label = parse_labelling(r);
  return e;
}

ImageElement parse_image_element(TableReader& r, const ParseContext& ctx) {
  ImageElement im;
  auto v = r.numbers("extent");
  if (v.size() != 4 || v[0] == v[1] || v[2] == v[3]) r.fail("extent", "expected extent = [x0, x1, y0, y1] with x0 != x1, y0 != y1");
  im.extent = {v[0], v[1], v[2], v[3]};
  im.raster = parse_raster(r, ctx);
  return im;
}

// [[axes.inset]]: the ranges it magnifies (inside what a log axis can show), and where it goes.
InsetSpec parse_inset(TableReader& r, const AxesSpec& ax) {
  InsetSpec in;
  in.where = r.where();
  for (const char name : {'x', 'y'}) {
    const std::string key = std::string(1, name) + "_range";
    if (!r.has(key)) r.fail(key, "an inset needs " + key + " = [lo, hi] (the data it magnifies)");
    const std::vector<double> v = r.numbers(key);
    if (v.size() != 2 || !(v[0] < v[1])) r.fail(key, "expected [lo, hi] with lo < hi");
    if (const std::string why = range_problem(v[0], v[1]); !why.empty()) r.fail(key, why);
    if ((name == 'x' ? ax.x : ax.y).scale == Scale::Log && !(v[0] > 0)) r.fail(key, "a log axis needs a positive range");
    (name == 'x' ? in.x_range : in.y_range) = {v[0], v[1]};
  }
  if (r.has("at") && r.has("size")) r.fail("size", "give either at or size, not both");
  if (r.has("at")) {
    const std::vector<double> v = r.numbers("at");
    if (v.size() != 4 || !(v[0] >= 0) || !(v[1] >= 0) || !(v[2] > 0) || !(v[3] > 0) || !(v[0] + v[2] <= 1) ||
        !(v[1] + v[3] <= 1))
      r.fail("at", "expected [x, y, width, height], fractions of the plot box from its lower left corner, the inset "
                   "inside the box");
    in.at = std::array<double, 4>{v[0], v[1], v[2], v[3]};
  }
  if (r.has("size")) {
    const std::vector<double> v = r.numbers("size");
    if (v.size() != 2 || !(v[0] > 0 && v[0] <= 1) || !(v[1] > 0 && v[1] <= 1))
      r.fail("size", "expected [width, height], fractions of the plot box in (0, 1]");
    in.size = {v[0], v[1]};
  }
  return in;
}

}  // namespace

SeriesLook parse_series_look(TableReader& r, LookDefault defaults) {
  SeriesLook look;
  look.stroke = curve_stroke();
  if (defaults == LookDefault::Polygon) {
    look.stroke.width = 1;
    look.stroke.join = render::Join::Miter;
    look.stroke.cap = render::Cap::Butt;
    look.stroke.dashes = {5, 3};
    look.mode = SeriesMode::LineMarkers;
    look.color = kGrey;
  } else if (defaults == LookDefault::Points) {
    look.mode = SeriesMode::Markers;
  }
  look.mode = static_cast<SeriesMode>(
      r.choice("style", {"line", "markers", "line+markers", "steps", "stems"}, static_cast<int>(look.mode)));
  look.closed = r.boolean("closed", false);
  if (auto c = r.opt_color("color")) look.color = c;
  look.stroke = r.stroke(look.stroke);
  look.marker = parse_marker_shape(r, "marker", look.marker);
  look.marker_size = r.positive("marker_size", look.marker_size);
  look.marker_color = r.opt_color("marker_color");
  look.label = parse_labelling(r);
  return look;
}

AxesSpec parse_axes(TableReader& r, const ParseContext& ctx) {
  AxesSpec ax;
  ax.where = r.where();
  parse_axis(r, 'x', ax.x);
  parse_axis(r, 'y', ax.y);
  if (ax.x.scale == Scale::Decibel) r.fail("x_scale", "db is for the y axis");
  ax.title = r.label("title", "");
  ax.grid = r.boolean("grid", false);
  ax.equal_aspect = r.choice("aspect", {"auto", "equal"}, 0) == 1;
  ax.zero_line = r.boolean("zero_line", false);
  ax.frame = static_cast<Frame>(r.choice("frame", {"box", "left-bottom", "none"}, 1));
  ax.legend = static_cast<LegendPlace>(std::min(8, r.choice("legend", {"auto", "none", "upper left", "upper right",
      "lower left", "lower right", "upper center", "lower center", "outside right", "outside-right"}, 0)));
  ax.legend_title = r.label("legend_title", "");
  ax.legend_columns = r.integer("legend_columns", 1, 1, 16);
  ax.legend_order = r.strings("legend_order");
  ax.palette = r.string("palette", ax.palette);
  if (!palette_known(ax.palette)) r.fail("palette", "unknown palette \"" + ax.palette + "\" (viridis | tab10 | grey)");
  ax.dash_cycle = r.boolean("dash_cycle", ax.dash_cycle);
  if (r.has("cell")) {
    auto v = r.numbers("cell");
    // Range first: converting a number past an int (1e10) to int is undefined.
    auto index = [](double x) { return x >= 0 && x < 1e6 && x == std::floor(x); };
    if (v.size() != 2 || !index(v[0]) || !index(v[1])) r.fail("cell", "expected [row, col], non-negative integers");
    ax.cell = std::array<int, 2>{static_cast<int>(v[0]), static_cast<int>(v[1])};
  }
  if (r.has("box")) {
    auto v = r.numbers("box");
    if (v.size() != 4 || !(v[0] < v[2]) || !(v[1] < v[3])) r.fail("box", "expected [left, top, right, bottom] with left < right, top < bottom");
    ax.box = std::array<double, 4>{v[0], v[1], v[2], v[3]};
  }

  std::vector<std::pair<size_t, PlotElement>> elements;
  std::map<size_t, SpecLocation> origins;  // by source line; generated elements carry `where`
  auto each = [&](std::string_view key, auto&& read) {
    r.each_table(key, [&](TableReader& sub, const toml::table& t) {
      elements.emplace_back(t.source().begin.line, PlotElement{read(sub)});
      origins[t.source().begin.line] = sub.origin("");
    });
  };
  each("curve", parse_curve);
  each("kernel", parse_kernel_element);
  each("series", [](TableReader& s) { return parse_series(s, LookDefault::Curve, "a series"); });
  each("polygon", [](TableReader& s) { return parse_series(s, LookDefault::Polygon, "a control polygon"); });
  each("markers", [](TableReader& s) { return parse_series(s, LookDefault::Points, "markers"); });
  each("fill", parse_fill);
  each("text", parse_text_element);
  each("annotation", parse_annotation);
  each("hline", [](TableReader& s) { return parse_rule(s, true); });
  each("vline", [](TableReader& s) { return parse_rule(s, false); });
  each("image", [&](TableReader& s) { return parse_image_element(s, ctx); });
  parse_generated_elements(r, elements);  // docs/companion.md, docs/resample.md
  r.each_table("inset", [&](TableReader& sub, const toml::table&) { ax.insets.push_back(parse_inset(sub, ax)); });
  r.finish();
  std::stable_sort(elements.begin(), elements.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [line, e] : elements) {
    SpecLocation origin = std::visit(
        [](const auto& x) -> SpecLocation {
          if constexpr (requires { x.where; }) return x.where;
          else return {};
        },
        e);
    if (auto it = origins.find(line); origin.empty() && it != origins.end()) origin = it->second;
    ax.elements.push_back(std::move(e));
    ax.element_origins.push_back(origin.empty() ? ax.where.with_key(r.path()) : origin);
  }
  check_fill_references(ax);  // spec_fill.cpp

  if (ax.y.scale == Scale::Log) {
    for (const auto& e : ax.elements)
      if (const auto* s = std::get_if<SeriesElement>(&e))
        for (const auto& p : s->points)
          if (!(p.y > 0)) r.fail("series", "a log y axis needs positive y data");
  }
  return ax;
}

}  // namespace splinefig::figures::detail
