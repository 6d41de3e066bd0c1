// Plot elements of an axes panel: curves, kernels, series, fills, text, annotations,
// reference lines and images, mapped from data to pixels and clipped to the plot box.
#include "plot.hpp"

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

}  // namespace

void draw_elements(const AxesSpec& ax, const Panel& panel, Painter& p, Occupancy& occ, std::vector<SeriesInfo>& series,
                   std::vector<Entry>& legend) {
  const PixelMap& map = panel.map;
  const Rect clip = panel.box.inflated(0.5);
  const double tol = 0.05 / p.scale();
  const int family = static_cast<int>(std::count_if(ax.elements.begin(), ax.elements.end(), needs_palette));
  int next = 0;
  auto pick = [&](const std::optional<Color>& c) { return c ? *c : palette_color(ax.palette, next++, family); };
  std::vector<InlineLabel> inline_labels;

  auto label = [&](const Labelling& l, const Entry& entry, const std::string& kind, const std::vector<Vec2>& pts,
                   std::optional<Vec2> at_point) {
    if (l.label.empty()) return;
    series.push_back({l.label, to_hex(entry.color), kind});
    if (l.in_legend) {
      legend.push_back(entry);
      return;
    }
    InlineLabel il{l.label, entry.color, {}, l.label_offset};
    if (at_point) il.candidates.push_back(*at_point);
    else il.candidates = middle_points(pts);
    if (!il.candidates.empty()) inline_labels.push_back(std::move(il));
  };

  for (const PlotElement& element : ax.elements) {
    if (const auto* c = std::get_if<CurveElement>(&element)) {
      Points knots(2);
      for (Vec2 k : c->knots) knots.push_back(std::array<double, 2>{k.x, k.y});
      Curve curve = make_curve(c->basis, knots, c->ends);
      std::vector<Vec2> pts = sample_curve(curve, map, tol);
      Color color = pick(c->color);
      bool closed = c->ends == Ends::closed;
      if (closed && pts.size() > 2) pts.pop_back();
      stroke_clipped(p, pts, closed, c->stroke, color, clip);
      occ.mark_polyline(pts, 0.5 * c->stroke.width + 1);
      if (c->show_knots)
        for (Vec2 k : c->knots) {
          Vec2 q = map(k);
          if (clip.contains(q)) p.marker(render::Marker::Circle, q, c->knot_size, color);
        }
      if (c->marks > 0) {
        std::vector<double> ts;
        const double T = static_cast<double>(curve.segments());
        if (c->marks_by_arclength && c->marks >= 2) ts = evenly_spaced_parameters(curve, static_cast<size_t>(c->marks));
        else
          for (int j = 0; j < c->marks; ++j) ts.push_back(c->marks == 1 ? 0 : T * j / (c->marks - 1));
        std::array<double, 2> xy{};
        for (double t : ts) {
          evaluate(curve, t, 0, xy);
          Vec2 q = map({xy[0], xy[1]});
          if (!clip.contains(q)) continue;
          p.marker(render::Marker::Circle, q, c->mark_size, c->mark_color.value_or(color));
          occ.mark_point(q, 0.5 * c->mark_size + 1);
        }
      }
      std::optional<Vec2> at;
      if (c->label.label_at) {
        std::array<double, 2> xy{};
        evaluate(curve, std::clamp(*c->label.label_at, 0.0, static_cast<double>(curve.segments())), 0, xy);
        at = map({xy[0], xy[1]});
      }
      Entry e{c->label.label, color, c->stroke, true, c->marks > 0, false, render::Marker::Circle, c->mark_size};
      label(c->label, e, "curve", pts, at);
    } else if (const auto* k = std::get_if<KernelElement>(&element)) {
      Support sup = kernel_support(k->basis);
      double s0 = k->range ? (*k->range)[0] : sup.lo, s1 = k->range ? (*k->range)[1] : sup.hi;
      auto pieces = sample_kernel(k->basis, s0, s1, k->scale, map, tol);
      std::vector<Vec2> all;
      for (const auto& piece : pieces)
        for (Vec2 q : piece)
          if (all.empty() || q.x != all.back().x || q.y != all.back().y) all.push_back(q);
      Color color = k->piece_colors.empty() ? pick(k->color) : k->piece_colors.back();
      if (k->piece_colors.empty()) {
        stroke_clipped(p, all, false, k->stroke, color, clip);
      } else {
        for (size_t i = 0; i < pieces.size(); ++i)
          if (!pieces[i].empty()) stroke_clipped(p, pieces[i], false, k->stroke, k->piece_colors[i], clip);
      }
      occ.mark_polyline(all, 0.5 * k->stroke.width + 1);
      if (k->show_knots) {
        for (double s = std::ceil(s0); s <= s1; s += 1) {
          Vec2 q = map({s, k->scale * kernel(k->basis, s)});
          if (clip.contains(q)) {
            p.marker(render::Marker::Circle, q, k->knot_size, kDark);
            occ.mark_point(q, 0.5 * k->knot_size + 1);
          }
        }
      }
      for (size_t i = 0; i < k->piece_labels.size() && i < pieces.size(); ++i) {
        if (k->piece_labels[i].empty() || pieces[i].empty()) continue;
        Color pc = k->piece_colors.empty() ? color : k->piece_colors[i];
        series.push_back({k->piece_labels[i], to_hex(pc), "kernel"});
        inline_labels.push_back({k->piece_labels[i], pc, middle_points(pieces[i], 0.25, 0.75, 7), std::nullopt});
      }
      std::optional<Vec2> at;
      if (k->label.label_at) at = nearest_at_x(all, map.x.to_pixel(*k->label.label_at));
      Entry e{k->label.label, color, k->stroke, true, false, false, render::Marker::Circle, 6};
      label(k->label, e, "kernel", all, at);
    } else if (const auto* s = std::get_if<SeriesElement>(&element)) {
      Color color = pick(s->look.color);
      std::vector<Vec2> pts;
      for (Vec2 d : s->points) pts.push_back(map(d));
      bool line = s->look.mode == SeriesMode::Line || s->look.mode == SeriesMode::LineMarkers;
      bool marks = s->look.mode == SeriesMode::Markers || s->look.mode == SeriesMode::LineMarkers || s->look.mode == SeriesMode::Stems;
      if (line) {
        stroke_clipped(p, pts, s->look.closed, s->look.stroke, color, clip);
        occ.mark_polyline(pts, 0.5 * s->look.stroke.width + 1);
      } else if (s->look.mode == SeriesMode::Steps) {
        std::vector<Vec2> steps;
        for (size_t i = 0; i < pts.size(); ++i) {
          if (i > 0) steps.push_back({pts[i].x, pts[i - 1].y});
          steps.push_back(pts[i]);
        }
        stroke_clipped(p, steps, false, s->look.stroke, color, clip);
        occ.mark_polyline(steps, 0.5 * s->look.stroke.width + 1);
      } else if (s->look.mode == SeriesMode::Stems) {
        double base = std::clamp(map.y.scale == Scale::Linear ? map.y.to_pixel(0) : panel.box.bottom, panel.box.top,
                                 panel.box.bottom);
        for (Vec2 q : pts) {
          std::vector<Vec2> stem = {{q.x, base}, q};
          stroke_clipped(p, stem, false, s->look.stroke, color, clip);
          occ.mark_polyline(stem, 0.5 * s->look.stroke.width + 1);
        }
      }
      if (marks) {
        Color mc = s->look.marker_color.value_or(color);
        for (Vec2 q : pts) {
          if (!clip.contains(q)) continue;
          p.marker(s->look.marker, q, s->look.marker_size, mc);
          occ.mark_point(q, 0.5 * s->look.marker_size + 1);
        }
      }
      std::optional<Vec2> at;
      if (s->look.label.label_at) at = nearest_at_x(pts, map.x.to_pixel(*s->look.label.label_at));
      Entry e{s->look.label.label, color, s->look.stroke, line || s->look.mode == SeriesMode::Steps, marks, false, s->look.marker,
              s->look.marker_size};
      label(s->look.label, e, "series", pts, at);
    } else if (const auto* f = std::get_if<FillElement>(&element)) {
      std::vector<Vec2> poly;
      for (Vec2 d : f->upper) poly.push_back(map(d));
      for (size_t i = f->lower.size(); i-- > 0;) poly.push_back(map(f->lower[i]));
      poly = clip_polygon(poly, panel.box);
      if (poly.size() >= 3) p.fill({poly}, render::FillRule::NonZero, f->color);
      Entry e{f->label.label, f->color, {}, false, false, true, render::Marker::Square, 6};
      label(f->label, e, "fill", poly, std::nullopt);
    } else if (const auto* t = std::get_if<TextElement>(&element)) {
      Vec2 q = map(t->at);
      p.text(t->text, {q.x + t->offset.x, q.y + t->offset.y}, t->font, t->anchor);
    } else if (const auto* a = std::get_if<AnnotationElement>(&element)) {
      Vec2 at = map(a->at), to = map(a->to);
      p.text(a->text, at, a->font, a->anchor);
      render::TextExtent ext = p.measure(a->text, a->font);
      double w = ext.width, h = ext.ascent + ext.descent;
      double left = a->anchor.halign == render::HAlign::Left ? at.x : a->anchor.halign == render::HAlign::Center ? at.x - w / 2 : at.x - w;
      double top = a->anchor.valign == render::VAlign::Top ? at.y
                   : a->anchor.valign == render::VAlign::Middle ? at.y - h / 2
                   : a->anchor.valign == render::VAlign::Bottom ? at.y - h
                                                                : at.y - ext.ascent;
      Rect r{left - 3, top - 3, left + w + 3, top + h + 3};
      occ.mark_rect(r, 4);
      // The arrow leaves the text box where the line from its centre to the tip crosses it.
      Vec2 c{0.5 * (r.left + r.right), 0.5 * (r.top + r.bottom)};
      double dx = to.x - c.x, dy = to.y - c.y, len = std::hypot(dx, dy);
      if (len > 1) {
        double tx = dx != 0 ? 0.5 * r.width() / std::abs(dx) : 1e300, ty = dy != 0 ? 0.5 * r.height() / std::abs(dy) : 1e300;
        double t0 = std::min({tx, ty, 1.0});
        Vec2 from{c.x + t0 * dx, c.y + t0 * dy};
        double ux = dx / len, uy = dy / len, head = 4 + 4 * a->arrow_width, tip_gap = 2;
        Vec2 tip{to.x - ux * tip_gap, to.y - uy * tip_gap};
        Vec2 base{tip.x - ux * head, tip.y - uy * head};
        if ((base.x - from.x) * ux + (base.y - from.y) * uy > 0) {
          render::StrokeStyle st;
          st.width = a->arrow_width;
          st.cap = render::Cap::Butt;
          p.stroke({from, base}, false, st, a->arrow_color);
        }
        double hw = head * 0.42;
        p.fill({{tip, {base.x - uy * hw, base.y + ux * hw}, {base.x + uy * hw, base.y - ux * hw}}}, render::FillRule::NonZero,
               a->arrow_color);
      }
    } else if (const auto* r = std::get_if<RuleElement>(&element)) {
      std::vector<Vec2> pts;
      if (r->horizontal) {
        double y = tick_pixel(map.y, r->value);
        pts = {{panel.box.left, y}, {panel.box.right, y}};
      } else {
        double x = tick_pixel(map.x, r->value);
        pts = {{x, panel.box.bottom}, {x, panel.box.top}};
      }
      stroke_clipped(p, pts, false, r->pen.style, r->pen.color, clip);
      occ.mark_polyline(pts, 0.5 * r->pen.style.width + 1);
      Entry e{r->label.label, r->pen.color, r->pen.style, true, false, false, render::Marker::Circle, 6};
      std::optional<Vec2> at;
      if (r->label.label_at) at = r->horizontal ? Vec2{map.x.to_pixel(*r->label.label_at), pts[0].y}
                                                : Vec2{pts[0].x, map.y.to_pixel(*r->label.label_at)};
      label(r->label, e, "rule", {pts[1], pts[0]}, at);
    } else if (const auto* im = std::get_if<ImageElement>(&element)) {
      double x0 = map.x.to_pixel(im->extent[0]), x1 = map.x.to_pixel(im->extent[1]);
      double y0 = map.y.to_pixel(im->extent[3]), y1 = map.y.to_pixel(im->extent[2]);
      p.image(im->raster, std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1));
    }
  }

  Font font{15, {}, false};
  for (auto& il : inline_labels) {
    font.color = il.color;
    if (il.offset) {
      Vec2 q{il.candidates[0].x + il.offset->x, il.candidates[0].y + il.offset->y};
      p.text(il.text, q, font, {render::HAlign::Center, render::VAlign::Middle});
      continue;
    }
    Vec2 anchor = place_label(il.text, font, il.candidates, panel.box, p, occ);
    p.text(il.text, anchor, font, {render::HAlign::Left, render::VAlign::Baseline});
  }
}

}  // namespace splinefig::figures::detail
