// The figure spec loader: canvas, layout and pixel-space primitives (axes: spec_parse_axes.cpp).
// Items keep the document order (by source line), so later items draw over earlier ones.
#include "spec_parse.hpp"
#include "caption_fields.hpp"
#include "spec_data.hpp"

#include <splinefig/image/io.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/spline/basis_kernel.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace splinefig::figures {

namespace detail {

Basis checked_basis(TableReader& r, std::string_view key, const std::string& spec) {
  try {
    return parse_basis(spec);
  } catch (const std::exception& e) {
    r.fail(key, "basis " + excerpt(spec) + ": " + e.what());
  }
}

Kernel kernel_value(TableReader& r, std::string_view key, const std::string& spec) {
  try {
    return parse_kernel(spec);
  } catch (const SpecError& e) {
    r.fail(key, e.what());
  } catch (const std::invalid_argument& e) {
    r.fail(key, e.what());
  }
}

Labelling parse_labelling(TableReader& r) {
  Labelling l;
  l.label = r.label("label", "");
  l.in_legend = r.choice("label_position", {"legend", "inline"}, 0) == 0;
  l.label_at = r.opt_number("label_at");
  l.label_offset = r.opt_point("label_offset");
  if (l.label_at || l.label_offset) l.in_legend = false;
  return l;
}

Raster parse_raster(TableReader& r, const ParseContext& ctx) {
  Raster raster;
  auto file = r.opt_string("file");
  auto data = r.matrix("data");
  if (file && !data.empty()) r.fail("data", "give either file or data, not both");
  if (file) {
    std::filesystem::path p(*file);
    if (p.is_relative()) p = std::filesystem::path(ctx.base_dir) / p;
    std::error_code ec;  // a symlink loop or an unreadable directory is said as such, not as missing
    if (const auto st = std::filesystem::status(p, ec); !std::filesystem::exists(st))
      r.fail("file", ec && st.type() != std::filesystem::file_type::not_found
                         ? "cannot open the image file \"" + p.string() + "\" (" + ec.message() + ")"
                         : "no such image file \"" + p.string() + "\"");
    try {
      check_image_header(p.string());  // its size against the limits, before anything is decoded
    } catch (const UnreadableImage& e) {
      r.fail("file", e.what());
    }
    raster.file = p.string();
  } else {
    if (data.empty() || data[0].empty()) r.fail("data", "an image needs `file` or non-empty `data` (rows of grey values)");
    raster.height = static_cast<int>(data.size());
    raster.width = static_cast<int>(data[0].size());
    raster.channels = 1;
    for (const auto& row : data) {
      if (static_cast<int>(row.size()) != raster.width) r.fail("data", "rows must all have the same length");
      for (double v : row) raster.data.push_back(static_cast<float>(v));
    }
  }
  raster.nearest = r.choice("interpolation", {"nearest", "bilinear"}, 0) == 0;
  raster.srgb_data = r.choice("encoding", {"linear", "srgb"}, 0) == 1;
  return raster;
}

render::Marker parse_marker_shape(TableReader& r, std::string_view key, render::Marker fallback) {
  return static_cast<render::Marker>(
      r.choice(key, {"circle", "square", "diamond", "cross", "plus"}, static_cast<int>(fallback)));
}

namespace {

void check_canvas(TableReader& r, const Canvas& c) {
  if (c.width > kMaxCanvasSide) r.fail("width", "larger than " + std::to_string(kMaxCanvasSide) + " px");
  if (c.height > kMaxCanvasSide) r.fail("height", "larger than " + std::to_string(kMaxCanvasSide) + " px");
  if (static_cast<long long>(c.width) * c.height > kMaxCanvasPixels)
    r.fail("height", "canvas of " + std::to_string(static_cast<long long>(c.width) * c.height) +
                         " pixels is over the limit of 2^28");
}

// The largest print width taken, in inches (25 m: a poster's is a few metres).
constexpr double kMaxPrintWidthInches = 1000;

// `print_width`: a number of inches, or a string of a number and a unit, "3.5in", "89mm",
// "8.9cm", "252pt" (a point 1/72 in); positive, finite and at most kMaxPrintWidthInches.
PrintWidth parse_print_width(TableReader& r) {
  static constexpr const char* kForms = "\"3.5in\", \"89mm\", \"8.9cm\", \"252pt\" or a number of inches";
  const toml::node* n = r.node("print_width");
  PrintWidth pw;
  pw.origin = r.origin("print_width");
  std::string shown;  // as written, for messages
  if (n->is_string()) {
    const std::string written = r.string("print_width", "");
    shown = excerpt(written);
    // A sign, a decimal number, a unit; spaces around them allowed.
    static const std::regex re(R"(\s*([+-]?)\s*([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*([A-Za-z]*)\s*)");
    std::smatch m;
    if (!std::regex_match(written, m, re)) r.fail("print_width", shown + " is not a length: write " + kForms);
    const std::string number = m[2], unit = m[3];
    static const std::vector<std::pair<std::string, double>> kUnits = {
        {"in", 1}, {"mm", 1 / 25.4}, {"cm", 1 / 2.54}, {"pt", 1 / 72.0}};
    const auto u = std::find_if(kUnits.begin(), kUnits.end(), [&](const auto& k) { return k.first == unit; });
    if (unit.empty()) r.fail("print_width", shown + " has no unit: write " + kForms);
    if (u == kUnits.end()) r.fail("print_width", "unknown unit " + excerpt(unit) + " in " + shown + ": write " + kForms);
    double v = 0;
    if (std::from_chars(number.data(), number.data() + number.size(), v).ec != std::errc())
      r.fail("print_width", shown + " is out of range");  // the regex took a number: too large or small
    pw.inches = (m[1] == "-" ? -v : v) * u->second;
  } else if (n->is_number()) {
    pw.inches = r.number("print_width", 0);  // NaN and infinities are refused here
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", pw.inches);
    shown = buf;
  } else {
    r.fail("print_width", std::string("must be a length: ") + kForms);
  }
  if (!std::isfinite(pw.inches)) r.fail("print_width", shown + " is not finite");
  if (!(pw.inches > 0)) r.fail("print_width", "must be positive, found " + shown);
  if (pw.inches > kMaxPrintWidthInches) r.fail("print_width", shown + " is over the limit of 1000 in");
  return pw;
}

Canvas parse_canvas(TableReader& r) {
  Canvas c;
  c.width = r.integer("width", c.width, 1, 1 << 30);
  c.height = r.integer("height", c.height, 1, 1 << 30);
  check_canvas(r, c);
  if (r.has("print_width")) {
    c.print_width = parse_print_width(r);
    if (const double dpi = c.print_dpi(); !(dpi >= kMinDpi && dpi <= kMaxDpi)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%d px across %g in is %g px per inch, outside [%g, %g]", c.width,
                    c.print_width->inches, dpi, kMinDpi, kMaxDpi);
      r.fail("print_width", buf);
    }
  }
  c.background = r.color("background", c.background);
  if (auto spec = r.opt_string("filter")) {
    c.filter = kernel_value(r, "filter", *spec);
    // Checked as the renderer checks a pixel filter, so that a filter it refuses is an error
    // here, with the spec's file, line and key.
    try {
      render::validate_pixel_filter(c.filter);
    } catch (const std::invalid_argument& e) {
      r.fail("filter", e.what());
    }
  }
  c.blend = r.choice("blend", {"srgb", "linear"}, 0) == 0 ? render::BlendSpace::srgb : render::BlendSpace::linear;
  c.coverage_tolerance = r.non_negative("coverage_tolerance", c.coverage_tolerance);
  if (c.coverage_tolerance > 1) r.fail("coverage_tolerance", "must be in [0, 1] (a fraction of full coverage; 0: exact)");
  r.finish();
  return c;
}

Layout parse_layout(TableReader& r) {
  Layout l;
  l.rows = r.integer("rows", 1, 1, 64);
  l.cols = r.integer("cols", 1, 1, 64);
  l.margin = r.non_negative("margin", l.margin);
  l.spacing = r.non_negative("spacing", l.spacing);
  r.finish();
  return l;
}

// [animation], read after the items: its panels name [[axes]] by index and must hold filmstrips
// of one frame count; frames, canvas and their product are bounded here, before anything is drawn.
AnimationSpec parse_animation(TableReader& r, const FigureSpec& spec) {
  AnimationSpec a;
  a.where = r.where();
  const std::string delays = "[" + std::to_string(kMinFrameDelayMs) + ", " + std::to_string(kMaxFrameDelayMs) + "]";
  auto delay = [&](const char* key, int fallback, bool zero) {
    const double v = r.number(key, fallback);
    if (!(v == std::floor(v)) || ((v < kMinFrameDelayMs || v > kMaxFrameDelayMs) && !(zero && v == 0)))
      r.fail(key, "expected whole milliseconds in " + delays);
    return static_cast<int>(v);
  };
  a.delay = delay("delay", a.delay, false);
  a.key_delay = delay("key_delay", 0, true);
  a.loops = r.integer("loops", 0, 0, 65535);
  a.width = r.integer("width", a.width, 1, kMaxAnimationSide);
  a.height = r.integer("height", a.height, 1, kMaxAnimationSide);
  if (static_cast<long long>(a.width) * a.height > kMaxCanvasPixels)
    r.fail("height", "animation canvas of " + std::to_string(static_cast<long long>(a.width) * a.height) +
                         " pixels is over the limit of 2^28");
  a.alt = r.string("alt", "");
  // The [[axes]] in document order, and the frame count of each one's filmstrips.
  std::vector<const AxesSpec*> axes;
  for (const Item& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item)) axes.push_back(ax);
  auto strip_frames = [](const AxesSpec& ax) {
    std::vector<std::size_t> counts;
    for (const PlotElement& e : ax.elements)
      if (const auto* ib = std::get_if<InbetweenElement>(&e); ib && ib->steps > 0)
        counts.push_back(static_cast<std::size_t>(ib->steps) * (ib->frames.size() - 1) + 1);
    return counts;
  };
  if (r.has("panels")) {
    for (double v : r.numbers("panels")) {
      if (!(v == std::floor(v)) || v < 0 || v >= static_cast<double>(axes.size()))
        r.fail("panels", "expected indices of the spec's [[axes]], 0 to " + std::to_string(static_cast<long long>(axes.size()) - 1));
      const int i = static_cast<int>(v);
      if (std::find(a.panels.begin(), a.panels.end(), i) != a.panels.end()) r.fail("panels", "axes[" + std::to_string(i) + "] is named twice");
      if (strip_frames(*axes[static_cast<std::size_t>(i)]).empty())
        r.fail("panels", "axes[" + std::to_string(i) + "] holds no filmstrip ([[axes.inbetween]] with steps = N)");
      a.panels.push_back(i);
    }
    if (a.panels.empty()) r.fail("panels", "names no axes");
    if (a.panels.size() > 16) r.fail("panels", "more than 16 panels side by side");
  } else {
    for (std::size_t i = 0; i < axes.size(); ++i)
      if (!strip_frames(*axes[i]).empty()) a.panels.push_back(static_cast<int>(i));
    if (a.panels.empty()) r.fail("", "the spec has no filmstrip to animate ([[axes.inbetween]] with steps = N)");
    if (a.panels.size() > 16) r.fail("", "more than 16 panels with filmstrips: name some in panels = [...]");
  }
  std::size_t frames = 0;
  for (int i : a.panels)
    for (std::size_t n : strip_frames(*axes[static_cast<std::size_t>(i)])) {
      if (frames != 0 && n != frames)
        r.fail(r.has("panels") ? "panels" : "",
               "its filmstrips differ in frame count (" + std::to_string(frames) + " and " + std::to_string(n) + "): animated together they need one");
      frames = n;
    }
  if (frames > kMaxAnimationFrames)
    r.fail("", std::to_string(frames) + " frames, over the limit of " + std::to_string(kMaxAnimationFrames));
  if (static_cast<double>(frames) * a.width * a.height > static_cast<double>(kMaxAnimationPixels))
    r.fail("height", std::to_string(frames) + " frames of " + std::to_string(a.width) + " x " + std::to_string(a.height) +
                         " px, over the limit of 2^28 pixels in all");
  r.finish();
  return a;
}

PolylineItem parse_polyline(TableReader& r) {
  PolylineItem p;
  if (!r.has("points")) r.fail("points", "a polyline needs points");
  p.points = r.points("points");
  if (p.points.empty()) r.fail("points", "empty polyline");
  p.closed = r.boolean("closed", false);
  p.pen.color = r.color("color", p.pen.color);
  p.pen.style = r.stroke(p.pen.style);
  r.finish();
  return p;
}

PolygonItem parse_polygon(TableReader& r) {
  PolygonItem p;
  if (r.has("points") && r.has("contours")) r.fail("contours", "give either points or contours, not both");
  if (r.has("points")) {
    p.contours.push_back(r.points("points"));
  } else {
    const toml::node* n = r.node("contours");
    if (!n || !n->is_array()) r.fail("contours", "a polygon needs points or contours");
    for (const toml::node& c : *n->as_array()) {
      std::vector<Vec2> contour;
      const toml::array* a = c.as_array();
      if (!a) r.fail_at(c, "contours", "expected an array of contours [[[x, y], ...], ...]");
      for (const toml::node& e : *a) {
        const toml::array* pt = e.as_array();
        if (!pt || pt->size() != 2) r.fail_at(e, "contours", "expected a point [x, y]");
        auto num = [&](const toml::node& v) -> double {
          auto d = v.value<double>();
          if (!d || !std::isfinite(*d)) r.fail_at(v, "contours", "expected a finite number");
          return *d;
        };
        contour.push_back({num(*pt->get(0)), num(*pt->get(1))});
      }
      p.contours.push_back(std::move(contour));
    }
  }
  bool any = false;
  for (const auto& c : p.contours) any = any || !c.empty();
  if (!any) r.fail(r.has("points") ? "points" : "contours", "empty polygon");
  p.rule = r.choice("fill_rule", {"nonzero", "evenodd"}, 0) == 0 ? render::FillRule::NonZero : render::FillRule::EvenOdd;
  p.color = r.color("color", {0, 0, 0, 1});
  r.finish();
  return p;
}

CircleItem parse_circle(TableReader& r) {
  CircleItem c;
  c.centre = r.required_point("center", "a circle needs center = [x, y]");
  c.radius = r.positive("radius", 1);
  c.fill = r.opt_color("fill");
  if (auto s = r.opt_color("stroke")) {
    Pen pen;
    pen.color = *s;
    pen.style = r.stroke(pen.style);
    c.stroke = pen;
  }
  if (!c.fill && !c.stroke) c.fill = Color{0, 0, 0, 1};
  r.finish();
  return c;
}

MarkerItem parse_marker(TableReader& r) {
  MarkerItem m;
  if (r.has("at")) {
    m.points.push_back(*r.opt_point("at"));
  } else {
    m.points = r.points("points");
  }
  if (m.points.empty()) r.fail("points", "a marker needs at = [x, y] or points = [[x, y], ...]");
  m.shape = parse_marker_shape(r, "shape", m.shape);
  m.size = r.positive("size", m.size);
  m.color = r.color("color", {0, 0, 0, 1});
  r.finish();
  return m;
}

TextItem parse_text(TableReader& r) {
  TextItem t;
  t.at = r.required_point("at", "text needs at = [x, y]");
  t.text = r.required_label("text", "text needs text = \"...\"");
  t.font.size = r.text_size();
  t.font = r.font(t.font);
  t.anchor = r.anchor(t.anchor);
  r.finish();
  return t;
}

ImageItem parse_image(TableReader& r, const ParseContext& ctx) {
  ImageItem im;
  auto at = r.opt_point("at");
  im.at = at.value_or(Vec2{0, 0});
  if (auto size = r.opt_point("size")) {
    if (!(size->x > 0 && size->y > 0)) r.fail("size", "must be positive");
    im.size = *size;
    im.has_size = true;
  }
  im.raster = parse_raster(r, ctx);
  r.finish();
  return im;
}

}  // namespace

// The font sizes of the text roles (top-level keys), in pixels at 1x: given in points with a
// print width (the defaults kTextSizesPt), else in pixels (the defaults TextSizes{}).
TextSizes text_sizes(TableReader& r, const Canvas& canvas) {
  const double unit = canvas.px_per_pt();
  TextSizes s;
  if (canvas.print_width) {
    const TextSizes& pt = kTextSizesPt;
    s = {pt.title * unit, pt.panel_title * unit, pt.label * unit, pt.tick * unit,
         pt.legend * unit, pt.inline_label * unit, pt.text * unit};
  }
  r.set_text_units(canvas.print_width ? unit : 1, s.text);
  const std::pair<const char*, double*> keys[] = {
      {"title_size", &s.title},   {"panel_title_size", &s.panel_title}, {"label_size", &s.label},
      {"tick_size", &s.tick},     {"legend_size", &s.legend},           {"inline_label_size", &s.inline_label},
      {"text_size", &s.text}};
  // The defaults stay under kMaxFontSize: a print width gives at most kMaxDpi / 72 px a point
  // (parse_canvas), 1389 px for the 10 pt title.
  for (const auto& [key, size] : keys) *size = r.font_size(key, *size);
  return s;
}

// An item with its source line (for document order) and its location (for messages).
struct Placed {
  size_t line;
  Item item;
  SpecLocation origin;
};

// Reads every [key] / [[key]] table as an item.
template <class F>
static void collect(TableReader& r, std::string_view key, std::vector<Placed>& out, F&& read) {
  r.each_table(key, [&](TableReader& sub, const toml::table& t) {
    out.push_back({t.source().begin.line, read(sub, t), sub.origin("")});
  });
}

}  // namespace detail

namespace {

std::string cell_name(const std::array<int, 2>& c) {
  return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + "]";
}

// Gives every panel without `cell` or `box` the first cell in reading order that no explicit
// `cell` claims and no earlier automatic panel took; explicit cells must lie in the grid.
void place_panels(FigureSpec& spec) {
  const Layout& L = spec.layout;
  const std::string grid = std::to_string(L.rows) + "x" + std::to_string(L.cols) + " layout (add [layout] rows/cols)";
  std::vector<char> taken(static_cast<size_t>(L.rows) * L.cols, 0);
  for (const auto& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item); ax && ax->cell) {
      const auto [r, c] = *ax->cell;
      if (r >= L.rows || c >= L.cols)
        throw SpecFileError(ax->where.with_key("axes.cell"), cell_name(*ax->cell) + " is outside the " + grid);
      taken[static_cast<size_t>(r) * L.cols + c] = 1;
    }
  size_t next = 0;
  for (auto& item : spec.items) {
    auto* ax = std::get_if<AxesSpec>(&item);
    if (!ax || ax->cell || ax->box) continue;
    while (next < taken.size() && taken[next]) ++next;
    if (next == taken.size()) throw SpecFileError(ax->where.with_key("axes"), "no free cell left in the " + grid);
    taken[next] = 1;
    ax->cell = std::array<int, 2>{static_cast<int>(next) / L.cols, static_cast<int>(next) % L.cols};
  }
}

}  // namespace

namespace detail {

FigureSpec read_spec(std::string_view text, const std::string& name, const std::string& base_dir) {
  toml::table doc;
  if (std::string bad = utf8_problem(text, name); !bad.empty()) throw SpecFileError(bad);
  if (std::string bad = key_depth_problem(text, name); !bad.empty()) throw SpecFileError(bad);
  try {
    doc = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    std::string d(e.description());
    std::replace(d.begin(), d.end(), '\n', ' ');
    throw SpecFileError(location_of(name, e.source()), d);
  }
  ParseContext ctx{name, base_dir};
  TableReader r(doc, name, "");
  const SpecData data = parse_data(r, base_dir);
  r.set_data(&data);
  FigureSpec spec;
  spec.name = std::filesystem::path(name).stem().string();
  spec.path = name;
  spec.title = r.label("title", "");
  spec.caption = r.string("caption", "");
  spec.source = r.string("source", "");
  spec.caption_fields = parse_caption_fields(r, spec.caption, r.origin("caption"));
  spec.show_title = r.boolean("show_title", true);
  spec.font_family = r.font_family("font_family", spec.font_family);
  r.number("order", 0);  // gallery order (catalog.cpp reads it)
  // [canvas] first: its print width makes every font size a size in points.
  if (auto t = r.tables("canvas"); !t.empty()) {
    if (t.size() > 1) r.fail("canvas", "only one [canvas] table");
    TableReader c(*t[0], name, "canvas");
    spec.canvas = parse_canvas(c);
  }
  spec.sizes = text_sizes(r, spec.canvas);
  r.set_text_units(spec.canvas.print_width ? spec.canvas.px_per_pt() : 1, spec.sizes.text);
  spec.title_origin = r.origin(r.has("title_size") ? "title_size" : "title");
  if (auto t = r.tables("layout"); !t.empty()) {
    if (t.size() > 1) r.fail("layout", "only one [layout] table");
    TableReader l(*t[0], name, "layout");
    spec.layout = parse_layout(l);
  }
  if (auto t = r.tables("gallery"); !t.empty()) {
    if (t.size() > 1) r.fail("gallery", "only one [gallery] table");
    TableReader g(*t[0], name, "gallery");
    spec.pixel_exact = g.boolean("pixel_exact", false);
    g.finish();
  }
  std::vector<Placed> items;
  collect(r, "polyline", items, [](TableReader& s, const toml::table&) { return Item{parse_polyline(s)}; });
  collect(r, "polygon", items, [](TableReader& s, const toml::table&) { return Item{parse_polygon(s)}; });
  collect(r, "circle", items, [](TableReader& s, const toml::table&) { return Item{parse_circle(s)}; });
  collect(r, "marker", items, [](TableReader& s, const toml::table&) { return Item{parse_marker(s)}; });
  collect(r, "text", items, [](TableReader& s, const toml::table&) { return Item{parse_text(s)}; });
  collect(r, "image", items, [&](TableReader& s, const toml::table&) { return Item{parse_image(s, ctx)}; });
  collect(r, "axes", items, [&](TableReader& s, const toml::table&) { return Item{parse_axes(s, ctx)}; });
  // [animation] names [[axes]] by index: read once they are all in place.
  const auto animation = r.tables("animation");
  if (animation.size() > 1) r.fail("animation", "only one [animation] table");
  r.finish();
  std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  for (auto& placed : items) {
    spec.items.push_back(std::move(placed.item));
    spec.item_origins.push_back(std::move(placed.origin));
  }

  place_panels(spec);
  if (!animation.empty()) {
    TableReader a(*animation[0], name, "animation");
    spec.animation = parse_animation(a, spec);
  }
  return spec;
}

}  // namespace detail

}  // namespace splinefig::figures
