// Plot elements of an axes panel: curves, kernels, series, fills, text, annotations,
// reference lines and images, mapped from data to pixels and clipped to the plot box.
#include "clip_path.hpp"
#include "draw.hpp"

#include <splinefig/figures/palette.hpp>
#include <splinefig/spline/arclength.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::figures::detail {
namespace {

const Color kDark = *render::parse_hex_color("#333333");

struct InlineLabel {
  std::string text;
  Color color;
  std::vector<Vec2> candidates;  // pixels, best first
  std::optional<Vec2> offset;    // fixed offset from candidates[0]
};

bool needs_palette(const PlotElement& e) {
  if (const auto* c = std::get_if<CurveElement>(&e)) return !c->color;
  if (const auto* k = std::get_if<KernelElement>(&e)) return !k->color && k->piece_colors.empty();
  if (const auto* s = std::get_if<SeriesElement>(&e)) return !s->look.color;
  return false;
}

// Points of a polyline from fraction a to b of its samples (label candidates).
std::vector<Vec2> middle_points(const std::vector<Vec2>& pts, double a = 0.2, double b = 0.8, int count = 9) {
  std::vector<Vec2> out;
  if (pts.empty()) return out;
  // Best first: the middle, then outwards.
  for (int j = 0; j < count; ++j) {
    int k = (j + 1) / 2 * (j % 2 ? 1 : -1);
    double f = 0.5 + k * (b - a) / (count - 1);
    size_t i = std::min(pts.size() - 1, static_cast<size_t>(std::lround(f * (pts.size() - 1))));
    out.push_back(pts[i]);
  }
  return out;
}

Vec2 nearest_at_x(const std::vector<Vec2>& pts, double px) {
  Vec2 best = pts.front();
  for (Vec2 q : pts)
    if (std::abs(q.x - px) < std::abs(best.x - px)) best = q;
  return best;
}

void stroke_clipped(Painter& p, const std::vector<Vec2>& pts, bool closed, const render::StrokeStyle& st, Color c,
                    const Rect& clip) {
  if (std::all_of(pts.begin(), pts.end(), [&](Vec2 q) { return clip.contains(q); })) {
    p.stroke(pts, closed, st, c);
    return;
  }
  auto runs = clip_polyline(pts, closed, clip);
  for (auto& r : runs) p.stroke(std::move(r), false, st, c);
}

// An exact path clipped to the box: whole when every control point lies in the box (then so
// does the curve, a Bezier lying in the convex hull of its control points), else the parts
// inside, each still exact (clip_path.hpp).
void stroke_clipped(Painter& p, render::Path path, const render::StrokeStyle& st, Color c, const Rect& clip) {
  if (std::all_of(path.points().begin(), path.points().end(), [&](Vec2 q) { return clip.contains(q); })) {
    p.stroke(std::move(path), st, c);
    return;
  }
  for (render::Path& part : clip_path(path, clip)) p.stroke(std::move(part), st, c);
}

// What every element's drawing shares: the panel, the painter, the occupancy grid, the
// palette and what the legend, the index and the inline labels collect.
class ElementPainter {
 public:
  ElementPainter(const AxesSpec& ax, const Panel& panel, Painter& p, Occupancy& occ, std::vector<SeriesInfo>& series,
                 std::vector<Entry>& legend, std::vector<AxesInfo::DataInk>& ink)
      : map(panel.map),
        box(panel.box),
        clip(panel.box.inflated(0.5)),
        tol(0.05 / p.scale()),
        p(p),
        occ(occ),
        palette_(ax.palette),
        dash_cycle_(ax.dash_cycle),
        family_(static_cast<int>(std::count_if(ax.elements.begin(), ax.elements.end(), needs_palette))),
        series_(series),
        legend_(legend),
        ink_(ink) {}

  const PixelMap& map;
  const Rect box, clip;
  const double tol;  // flatness in layout units: 0.05 output pixels
  Painter& p;
  Occupancy& occ;

  // The element's own colour, else the next colour of the axes palette and, for a solid stroke,
  // the dash pattern of the same place in the style cycle (palette.hpp), drawn with butt caps.
  Color pick(const std::optional<Color>& c, render::StrokeStyle& st) {
    if (c) return *c;
    const int i = next_++;
    if (dash_cycle_ && st.dashes.empty()) {
      st.dashes = cycle_dash(i);
      if (!st.dashes.empty()) st.cap = render::Cap::Butt;
    }
    return palette_color(palette_, i, family_);
  }

  // Records a labelled element for index.json and the legend, or for an inline label next to
  // `at_point` (else next to the middle of `pts`).
  void label(const Labelling& l, const Entry& entry, const std::string& kind, const std::vector<Vec2>& pts,
             std::optional<Vec2> at_point) {
    if (l.label.empty()) return;
    series_.push_back(info(l.label, entry, kind));
    if (l.in_legend) {
      legend_.push_back(entry);
      return;
    }
    InlineLabel il{l.label, entry.color, {}, l.label_offset};
    if (at_point) il.candidates.push_back(*at_point);
    else il.candidates = middle_points(pts);
    if (!il.candidates.empty()) inline_.push_back(std::move(il));
  }
  // A label of one kernel piece, always inline.
  void piece_label(const std::string& text, Color c, const render::StrokeStyle& st, const std::vector<Vec2>& piece) {
    SeriesInfo si = info(text, {text, c, st, true, false, false, render::Marker::Circle, 6}, "kernel");
    si.piece = true;
    series_.push_back(std::move(si));
    inline_.push_back({text, c, middle_points(piece, 0.25, 0.75, 7), std::nullopt});
  }

  void stroke(const std::vector<Vec2>& pts, bool closed, const render::StrokeStyle& st, Color c) {
    stroke_clipped(p, pts, closed, st, c, clip);
    mark_polyline(pts, closed, 0.5 * st.width);
  }
  // The data's ink: into the occupancy grid a pixel wider, and into the panel's data_ink.
  void mark_polyline(const std::vector<Vec2>& pts, bool closed, double half_width) {
    if (closed && pts.size() > 2) {
      std::vector<Vec2> loop = pts;
      loop.push_back(pts[0]);
      return mark_polyline(loop, false, half_width);
    }
    occ.mark_polyline(pts, half_width + 1);
    AxesInfo::DataInk ink;
    const double s = p.scale();
    ink.points.reserve(pts.size());
    for (Vec2 q : pts) ink.points.push_back({q.x * s, q.y * s});
    ink.radius = half_width * s;
    ink_.push_back(std::move(ink));
  }
  // The exact path clipped to the box, else (no exact path) the polyline `pts` of the same curve.
  void stroke(const std::optional<render::Path>& path, const std::vector<Vec2>& pts, bool closed,
              const render::StrokeStyle& st, Color c) {
    if (!path) return stroke(pts, closed, st, c);
    render::Path closed_path = *path;
    if (closed) closed_path.close();
    stroke_clipped(p, std::move(closed_path), st, c, clip);
    mark_polyline(pts, closed, 0.5 * st.width);
  }
  // A marker inside the clip box, marked as used.
  void mark(render::Marker shape, Vec2 q, double size, Color c) {
    if (!clip.contains(q)) return;
    p.marker(shape, q, size, c);
    occ.mark_point(q, 0.5 * size + 1);
    ink_.push_back({{{q.x * p.scale(), q.y * p.scale()}}, 0.5 * size * p.scale()});
  }

  // The inline labels, after every element is drawn (so they avoid all the data).
  void place_inline_labels(Font font) {
    for (auto& il : inline_) {
      font.color = il.color;
      if (il.offset) {
        Vec2 q{il.candidates[0].x + il.offset->x, il.candidates[0].y + il.offset->y};
        p.text(il.text, q, font, {render::HAlign::Center, render::VAlign::Middle});
        continue;
      }
      Vec2 anchor = place_label(il.text, font, il.candidates, box, p, occ);
      p.text(il.text, anchor, font, {render::HAlign::Left, render::VAlign::Baseline});
    }
  }

 private:
  static SeriesInfo info(const std::string& label, const Entry& e, const std::string& kind) {
    static constexpr const char* kMarkers[] = {"circle", "square", "diamond", "cross", "plus"};
    SeriesInfo si{label, to_hex(e.color), kind};
    si.line = e.line;
    if (e.line) si.dash.assign(e.style.dashes.begin(), e.style.dashes.end());
    if (e.markers) si.marker = kMarkers[static_cast<int>(e.marker)];
    return si;
  }

  std::string palette_;
  bool dash_cycle_;
  int family_, next_ = 0;
  std::vector<SeriesInfo>& series_;
  std::vector<Entry>& legend_;
  std::vector<AxesInfo::DataInk>& ink_;
  std::vector<InlineLabel> inline_;
};

void draw_curve(const CurveElement& c, const Curve& curve, ElementPainter& d) {
  std::vector<Vec2> pts = sample_curve(curve, d.map, d.tol);
  render::StrokeStyle stroke = c.stroke;
  const Color color = d.pick(c.color, stroke);
  const bool closed = c.ends == Ends::closed;
  if (closed && pts.size() > 2) pts.pop_back();
  d.stroke(curve_path(curve, d.map), pts, closed, stroke, color);
  if (c.show_knots)
    for (Vec2 k : c.knots) {
      Vec2 q = d.map(k);
      if (d.clip.contains(q)) d.p.marker(render::Marker::Circle, q, c.knot_size, color);
    }
  if (c.marks > 0) {
    std::vector<double> ts;
    const double T = static_cast<double>(curve.segments());
    if (c.marks_by_arclength && c.marks >= 2) ts = evenly_spaced_parameters(curve, static_cast<size_t>(c.marks));
    else
      for (int j = 0; j < c.marks; ++j) ts.push_back(c.marks == 1 ? 0 : T * j / (c.marks - 1));
    std::array<double, 2> xy{};
    for (double t : ts) {
      evaluate(curve, t, 0, xy);
      d.mark(render::Marker::Circle, d.map({xy[0], xy[1]}), c.mark_size, c.mark_color.value_or(color));
    }
  }
  std::optional<Vec2> at;
  if (c.label.label_at) {
    std::array<double, 2> xy{};
    evaluate(curve, std::clamp(*c.label.label_at, 0.0, static_cast<double>(curve.segments())), 0, xy);
    at = d.map({xy[0], xy[1]});
  }
  Entry e{c.label.label, color, stroke, true, c.marks > 0, false, render::Marker::Circle, c.mark_size};
  d.label(c.label, e, "curve", pts, at);
}

void draw_kernel(const KernelElement& k, ElementPainter& d) {
  Support sup = kernel_support(k.basis);
  double s0 = k.range ? (*k.range)[0] : sup.lo, s1 = k.range ? (*k.range)[1] : sup.hi;
  auto pieces = sample_kernel(k.basis, s0, s1, k.scale, d.map, d.tol);
  std::vector<Vec2> all;
  for (const auto& piece : pieces)
    for (Vec2 q : piece)
      if (all.empty() || q.x != all.back().x || q.y != all.back().y) all.push_back(q);
  render::StrokeStyle stroke = k.stroke;
  Color color = k.piece_colors.empty() ? d.pick(k.color, stroke) : k.piece_colors.back();
  // The exact pieces clipped to the box, else (no exact pieces) the polylines.
  auto paths = kernel_paths(k.basis, s0, s1, k.scale, d.map);
  if (k.piece_colors.empty()) {
    if (paths) {
      render::Path whole;
      for (const render::Path& q : *paths) {
        std::size_t j = 0;
        for (render::Path::Verb v : q.verbs()) {
          const auto& pt = q.points();
          if (v == render::Path::Verb::Cubic) {
            whole.cubic_to(pt[j], pt[j + 1], pt[j + 2]);
            j += 3;
            continue;
          }
          const Vec2 to = pt[j++];
          if (whole.empty()) whole.move_to(to);
          else if (const Vec2 cur = whole.points().back(); cur.x != to.x || cur.y != to.y) whole.line_to(to);
        }
      }
      stroke_clipped(d.p, std::move(whole), stroke, color, d.clip);
    } else {
      stroke_clipped(d.p, all, false, stroke, color, d.clip);
    }
  } else {
    for (size_t i = 0; i < pieces.size(); ++i) {
      if (pieces[i].empty()) continue;
      if (paths) stroke_clipped(d.p, (*paths)[i], k.stroke, k.piece_colors[i], d.clip);
      else stroke_clipped(d.p, pieces[i], false, k.stroke, k.piece_colors[i], d.clip);
    }
  }
  d.mark_polyline(all, false, 0.5 * k.stroke.width);
  if (k.show_knots)
    for (double s = std::ceil(s0); s <= s1; s += 1) d.mark(render::Marker::Circle, d.map({s, k.scale * kernel(k.basis, s)}), k.knot_size, kDark);
  for (size_t i = 0; i < k.piece_labels.size() && i < pieces.size(); ++i) {
    if (k.piece_labels[i].empty() || pieces[i].empty()) continue;
    d.piece_label(k.piece_labels[i], k.piece_colors.empty() ? color : k.piece_colors[i], stroke, pieces[i]);
  }
  std::optional<Vec2> at;
  if (k.label.label_at) at = nearest_at_x(all, d.map.x.to_pixel(*k.label.label_at));
  Entry e{k.label.label, color, stroke, true, false, false, render::Marker::Circle, 6};
  d.label(k.label, e, "kernel", all, at);
}

void draw_series(const SeriesElement& s, ElementPainter& d) {
  SeriesLook look = s.look;
  render::StrokeStyle cycled = look.stroke;
  const Color color = d.pick(look.color, cycled);
  std::vector<Vec2> pts;
  for (Vec2 q : s.points) pts.push_back(d.map(q));
  const bool line = look.mode == SeriesMode::Line || look.mode == SeriesMode::LineMarkers;
  if (line || look.mode == SeriesMode::Steps) look.stroke = cycled;  // stems and markers stay solid
  const bool marks = look.mode == SeriesMode::Markers || look.mode == SeriesMode::LineMarkers || look.mode == SeriesMode::Stems;
  if (line && !s.bezier.empty() && d.map.affine()) {
    // A cubic spline: its Bezier pieces mapped to pixels (an affine map keeps them exact).
    render::Path path;
    path.move_to(d.map(s.bezier[0]));
    for (std::size_t i = 1; i + 2 < s.bezier.size(); i += 3)
      path.cubic_to(d.map(s.bezier[i]), d.map(s.bezier[i + 1]), d.map(s.bezier[i + 2]));
    d.stroke(path, pts, look.closed, look.stroke, color);
  } else if (line) {
    d.stroke(pts, look.closed, look.stroke, color);
  } else if (look.mode == SeriesMode::Steps) {
    std::vector<Vec2> steps;
    for (size_t i = 0; i < pts.size(); ++i) {
      if (i > 0) steps.push_back({pts[i].x, pts[i - 1].y});
      steps.push_back(pts[i]);
    }
    d.stroke(steps, false, look.stroke, color);
  } else if (look.mode == SeriesMode::Stems) {
    const double base = std::clamp(d.map.y.scale == Scale::Linear ? d.map.y.to_pixel(0) : d.box.bottom, d.box.top,
                                   d.box.bottom);
    for (Vec2 q : pts) d.stroke({{q.x, base}, q}, false, look.stroke, color);
  }
  if (marks) {
    const Color mc = look.marker_color.value_or(color);
    for (Vec2 q : pts) d.mark(look.marker, q, look.marker_size, mc);
  }
  std::optional<Vec2> at;
  if (look.label.label_at) at = nearest_at_x(pts, d.map.x.to_pixel(*look.label.label_at));
  Entry e{look.label.label, color, look.stroke, line || look.mode == SeriesMode::Steps, marks, false, look.marker,
          look.marker_size};
  d.label(look.label, e, "series", pts, at);
}

void draw_fill(const FillElement& f, const PreparedAxes& prepared, ElementPainter& d) {
  std::vector<Vec2> poly;
  if (!f.under.empty()) poly = fill_under_polygon(prepared, f, d.map, d.tol);
  for (Vec2 q : f.upper) poly.push_back(d.map(q));
  for (size_t i = f.lower.size(); i-- > 0;) poly.push_back(d.map(f.lower[i]));
  poly = clip_polygon(poly, d.box);
  if (poly.size() >= 3) d.p.fill({poly}, render::FillRule::NonZero, f.color);
  Entry e{f.label.label, f.color, {}, false, false, true, render::Marker::Square, 6};
  d.label(f.label, e, "fill", poly, std::nullopt);
}

void draw_text_element(const TextElement& t, ElementPainter& d) {
  Vec2 q = d.map(t.at);
  d.p.text(t.text, {q.x + t.offset.x, q.y + t.offset.y}, t.font, t.anchor);
}

void draw_annotation(const AnnotationElement& a, ElementPainter& d) {
  Vec2 at = d.map(a.at), to = d.map(a.to);
  d.p.text(a.text, at, a.font, a.anchor);
  render::TextExtent ext = d.p.measure(a.text, a.font);
  double w = ext.width, h = ext.ascent + ext.descent;
  double left = a.anchor.halign == render::HAlign::Left ? at.x : a.anchor.halign == render::HAlign::Center ? at.x - w / 2 : at.x - w;
  double top = a.anchor.valign == render::VAlign::Top ? at.y
               : a.anchor.valign == render::VAlign::Middle ? at.y - h / 2
               : a.anchor.valign == render::VAlign::Bottom ? at.y - h
                                                            : at.y - ext.ascent;
  Rect r{left - 3, top - 3, left + w + 3, top + h + 3};
  d.occ.mark_rect(r);
  // The arrow leaves the text box where the line from its centre to the tip crosses it.
  Vec2 c{0.5 * (r.left + r.right), 0.5 * (r.top + r.bottom)};
  double dx = to.x - c.x, dy = to.y - c.y, len = std::hypot(dx, dy);
  if (len <= 1) return;
  double tx = dx != 0 ? 0.5 * r.width() / std::abs(dx) : 1e300, ty = dy != 0 ? 0.5 * r.height() / std::abs(dy) : 1e300;
  double t0 = std::min({tx, ty, 1.0});
  Vec2 from{c.x + t0 * dx, c.y + t0 * dy};
  double ux = dx / len, uy = dy / len, head = 4 + 4 * a.arrow_width, tip_gap = 2;
  Vec2 tip{to.x - ux * tip_gap, to.y - uy * tip_gap};
  Vec2 base{tip.x - ux * head, tip.y - uy * head};
  if ((base.x - from.x) * ux + (base.y - from.y) * uy > 0) {
    render::StrokeStyle st;
    st.width = a.arrow_width;
    st.cap = render::Cap::Butt;
    d.p.stroke({from, base}, false, st, a.arrow_color);
  }
  double hw = head * 0.42;
  d.p.fill({{tip, {base.x - uy * hw, base.y + ux * hw}, {base.x + uy * hw, base.y - ux * hw}}}, render::FillRule::NonZero,
           a.arrow_color);
}

void draw_rule(const RuleElement& r, ElementPainter& d) {
  std::vector<Vec2> pts;
  if (r.horizontal) {
    double y = tick_pixel(d.map.y, r.value);
    pts = {{d.box.left, y}, {d.box.right, y}};
  } else {
    double x = tick_pixel(d.map.x, r.value);
    pts = {{x, d.box.bottom}, {x, d.box.top}};
  }
  d.stroke(pts, false, r.pen.style, r.pen.color);
  Entry e{r.label.label, r.pen.color, r.pen.style, true, false, false, render::Marker::Circle, 6};
  std::optional<Vec2> at;
  if (r.label.label_at) at = r.horizontal ? Vec2{d.map.x.to_pixel(*r.label.label_at), pts[0].y}
                                          : Vec2{pts[0].x, d.map.y.to_pixel(*r.label.label_at)};
  d.label(r.label, e, "rule", {pts[1], pts[0]}, at);
}

void draw_image_element(const ImageElement& im, ElementPainter& d) {
  double x0 = d.map.x.to_pixel(im.extent[0]), x1 = d.map.x.to_pixel(im.extent[1]);
  double y0 = d.map.y.to_pixel(im.extent[3]), y1 = d.map.y.to_pixel(im.extent[2]);
  d.p.image(im.raster, std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1));
}

}  // namespace

void draw_elements(const PreparedAxes& prepared, const Panel& panel, Painter& p, Occupancy& occ,
                   std::vector<SeriesInfo>& series, std::vector<Entry>& legend, std::vector<AxesInfo::DataInk>& ink,
                   const Guides& g) {
  const AxesSpec& ax = prepared.axes;
  ElementPainter d(ax, panel, p, occ, series, legend, ink);
  for (size_t i = 0; i < ax.elements.size(); ++i) {
    const SpecLocation origin = i < ax.element_origins.size() ? ax.element_origins[i] : ax.where.with_key("axes");
    p.set_origin(origin);
    naming_origin(origin, [&] { std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, CurveElement>) draw_curve(e, prepared.curves.at(i), d);
          else if constexpr (std::is_same_v<T, KernelElement>) draw_kernel(e, d);
          else if constexpr (std::is_same_v<T, SeriesElement>) draw_series(e, d);
          else if constexpr (std::is_same_v<T, FillElement>) draw_fill(e, prepared, d);
          else if constexpr (std::is_same_v<T, TextElement>) draw_text_element(e, d);
          else if constexpr (std::is_same_v<T, AnnotationElement>) draw_annotation(e, d);
          else if constexpr (std::is_same_v<T, RuleElement>) draw_rule(e, d);
          else if constexpr (std::is_same_v<T, ImageElement>) draw_image_element(e, d);
          // Generated elements were replaced by what they generate (PreparedAxes).
        },
        ax.elements[i]); });
  }
  p.set_origin(ax.where.with_key("axes"));
  d.place_inline_labels(g.inline_font);
}

}  // namespace splinefig::figures::detail
