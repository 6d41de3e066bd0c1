// The caption's computed fields worked out from the elements' data (caption_text.hpp).
#include "caption_text.hpp"

#include "generated.hpp"
#include "../load/caption_fields.hpp"

#include <splinefig/figures/axes.hpp>

#include <splinefig/kernel/analysis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

namespace splinefig::figures::detail {
namespace {

struct Value {
  double v[2];
  bool vector;
};

[[noreturn]] void fail(const CaptionField& f, const std::string& message) {
  throw SpecFileError(f.origin, message);
}

// The element named by the field's key path and its axes.
const PlotElement& find_element(const FigureSpec& spec, const CaptionField& f) {
  for (const auto& item : spec.items)
    if (const auto* ax = std::get_if<AxesSpec>(&item))
      for (std::size_t i = 0; i < ax->elements.size() && i < ax->element_origins.size(); ++i)
        if (ax->element_origins[i].key == f.element) return ax->elements[i];
  fail(f, "element: \"" + f.element + "\" is no plot element of this spec (write its key path, e.g. axes.bezier[0] "
          "or axes[1].bezier[0])");
}

// The input points of an element (`points` or `knots`), if it has them.
const std::vector<Vec2>* input_points(const PlotElement& e) {
  return std::visit(
      [](const auto& x) -> const std::vector<Vec2>* {
        if constexpr (requires { x.knots; }) return &x.knots;
        else if constexpr (requires { x.points; }) {
          if constexpr (std::is_same_v<std::decay_t<decltype(x.points)>, std::vector<Vec2>>) return &x.points;
          else return nullptr;
        } else return nullptr;
      },
      e);
}

// The first traced path of a generated element.
std::optional<Path> path_of(const std::vector<GeneratedPart>& parts) {
  for (const auto& part : parts)
    if (const auto* s = std::get_if<GeneratedSeries>(&part); s && s->path) return s->path;
  return std::nullopt;
}

// The cubic piece holding t (at a joint the piece that starts there) and its local parameter.
struct Piece {
  Vec2 p[4];
  double u, scale;  // d/dt = scale * d/du
};
Piece piece_at(const Path& path, double t, const CaptionField& f) {
  const std::size_t n = path.breaks.size() - 1;
  if (path.bezier.size() != 3 * n + 1)
    fail(f, "value: " + f.function + "() needs a curve made of cubic pieces (bezier of degree 3 or less, interp, "
            "relaxed_bspline); \"" + f.element + "\" is not one");
  std::size_t k = 0;
  while (k + 1 < n && t >= path.breaks[k + 1]) ++k;
  const double a = path.breaks[k], b = path.breaks[k + 1];
  Piece pc{{path.bezier[3 * k], path.bezier[3 * k + 1], path.bezier[3 * k + 2], path.bezier[3 * k + 3]},
           (t - a) / (b - a), 1 / (b - a)};
  return pc;
}

Vec2 d1(const Piece& c) {
  const double u = c.u, v = 1 - u, s = 3 * c.scale;
  auto comp = [&](double Vec2::*m) {
    return s * (v * v * (c.p[1].*m - c.p[0].*m) + 2 * u * v * (c.p[2].*m - c.p[1].*m) + u * u * (c.p[3].*m - c.p[2].*m));
  };
  return {comp(&Vec2::x), comp(&Vec2::y)};
}

Vec2 d2(const Piece& c) {
  const double u = c.u, s = 6 * c.scale * c.scale;
  auto comp = [&](double Vec2::*m) {
    return s * ((1 - u) * (c.p[2].*m - 2 * c.p[1].*m + c.p[0].*m) + u * (c.p[3].*m - 2 * c.p[2].*m + c.p[1].*m));
  };
  return {comp(&Vec2::x), comp(&Vec2::y)};
}

// The t in [a, b] where y(t) is largest (sign = 1) or smallest (sign = -1): the best of 4096
// even steps, then golden-section search between its neighbours.
double extremum(const Path& path, double a, double b, double sign) {
  auto g = [&](double t) { return sign * path.at(t).y; };
  constexpr int kSteps = 4096;
  int best = 0;
  double best_v = g(a);
  for (int i = 1; i <= kSteps; ++i)
    if (const double v = g(a + (b - a) * i / kSteps); v > best_v) best_v = v, best = i;
  double lo = a + (b - a) * std::max(0, best - 1) / kSteps, hi = a + (b - a) * std::min(kSteps, best + 1) / kSteps;
  const double r = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo), g1 = g(x1), g2 = g(x2);
  for (int it = 0; it < 200 && hi - lo > 1e-14 * std::max(1.0, std::abs(lo)); ++it) {
    if (g1 < g2) lo = x1, x1 = x2, g1 = g2, x2 = lo + r * (hi - lo), g2 = g(x2);
    else hi = x2, x2 = x1, g2 = g1, x1 = hi - r * (hi - lo), g1 = g(x1);
  }
  const double t = (lo + hi) / 2;
  return g(t) >= best_v ? t : a + (b - a) * best / kSteps;
}

Value evaluate(const FigureSpec& spec, const CaptionField& f);

// The i-th input point of the element named by the field.
Vec2 knot_of(const FigureSpec& spec, const CaptionField& f, double index) {
  const std::vector<Vec2>* pts = input_points(find_element(spec, f));
  if (!pts) fail(f, "value: \"" + f.element + "\" has no points or knots for " + f.function + "()");
  const auto i = static_cast<std::size_t>(index);
  if (i >= pts->size())
    fail(f, "value: knot " + std::to_string(i) + " of \"" + f.element + "\", which has " + std::to_string(pts->size()) +
                " points (0 .. " + std::to_string(pts->size() - 1) + ")");
  return (*pts)[i];
}

// along(t, i, j): how far along the leg from knot i to knot j the curve's point at t lies, as a
// fraction of the leg; the point must lie on the leg (within 1e-9 of its length).
Value along(const FigureSpec& spec, const CaptionField& f) {
  const Vec2 a = knot_of(spec, f, f.args[1]), b = knot_of(spec, f, f.args[2]);
  CaptionField at = f;
  at.function = "point";
  at.args = {f.args[0]};
  const Value p = evaluate(spec, at);
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (!(len2 > 0)) fail(f, "value: along(): knots " + tick_number(f.args[1], 0) + " and " + tick_number(f.args[2], 0) + " are one point");
  const double px = p.v[0] - a.x, py = p.v[1] - a.y;
  const double s = (px * dx + py * dy) / len2, off = std::abs(px * dy - py * dx) / std::sqrt(len2);
  if (off > 1e-9 * std::sqrt(len2) || s < -1e-12 || s > 1 + 1e-12)
    fail(f, "value: along(): the point at t = " + tick_number(f.args[0], 6) + ", (" + tick_number(p.v[0], 6) + ", " +
                tick_number(p.v[1], 6) + "), is not on the leg from knot " + tick_number(f.args[1], 0) + " to knot " +
                tick_number(f.args[2], 0));
  return {{s, 0}, false};
}

// mirror_x(): the c for which the element's points are their own mirror image under x -> c - x,
// point k mapped to point n-1-k (within 1e-12 of the points' size).
Value mirror_x(const FigureSpec& spec, const CaptionField& f) {
  const std::vector<Vec2>* pts = input_points(find_element(spec, f));
  if (!pts || pts->empty()) fail(f, "value: \"" + f.element + "\" has no points or knots for mirror_x()");
  const std::size_t n = pts->size();
  const double c = (*pts)[0].x + (*pts)[n - 1].x;
  double size = 1;
  for (Vec2 p : *pts) size = std::max({size, std::abs(p.x), std::abs(p.y)});
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 p = (*pts)[k], q = (*pts)[n - 1 - k];
    if (std::abs(p.x + q.x - c) > 1e-12 * size || std::abs(p.y - q.y) > 1e-12 * size)
      fail(f, "value: mirror_x(): the points of \"" + f.element + "\" are not their own mirror image under x -> " +
                  tick_number(c, 6) + " - x (point " + std::to_string(k) + " against point " + std::to_string(n - 1 - k) + ")");
  }
  return {{c, 0}, false};
}

Value evaluate(const FigureSpec& spec, const CaptionField& f) {
  const PlotElement& e = find_element(spec, f);
  const std::string& fn = f.function;
  if (fn == "along") return along(spec, f);
  if (fn == "mirror_x") return mirror_x(spec, f);
  if (fn == "knot") {
    const std::vector<Vec2>* pts = input_points(e);
    if (!pts) fail(f, "value: \"" + f.element + "\" has no points or knots for knot()");
    const auto i = static_cast<std::size_t>(f.args[0]);
    if (i >= pts->size())
      fail(f, "value: knot(" + std::to_string(i) + ") of \"" + f.element + "\", which has " +
                  std::to_string(pts->size()) + " points (0 .. " + std::to_string(pts->size() - 1) + ")");
    return {{(*pts)[i].x, (*pts)[i].y}, true};
  }
  if (fn == "b1" || fn == "b2") {
    const auto* lb = std::get_if<LocalBetasElement>(&e);
    if (!lb) fail(f, "value: " + fn + "() reads the betas of a local_betas element; \"" + f.element + "\" is not one");
    const auto i = static_cast<std::size_t>(f.args[0]);
    if (i >= lb->betas.size())
      fail(f, "value: " + fn + "(" + std::to_string(i) + ") of \"" + f.element + "\", which has " +
                  std::to_string(lb->betas.size()) + " knots");
    return {{lb->betas[i][fn == "b1" ? 0 : 1], 0}, false};
  }
  if (fn == "steps") {  // a filmstrip's subintervals per time unit
    const auto* ib = std::get_if<InbetweenElement>(&e);
    if (!ib || ib->steps == 0)
      fail(f, "value: steps() reads an inbetween filmstrip (steps = N); \"" + f.element + "\" is not one");
    return {{static_cast<double>(ib->steps), 0}, false};
  }
  if (fn == "leakage") {  // the percentage of a filter's energy above Nyquist (kernel/analysis.hpp)
    const auto* r = std::get_if<ResponseElement>(&e);
    const auto* fc = std::get_if<FilterCurveElement>(&e);
    if (!r && !fc) fail(f, "value: leakage() reads a response or filter element; \"" + f.element + "\" is neither");
    return {{100 * analyse(r ? r->filter : fc->filter).leakage, 0}, false};
  }
  if (fn == "bias" || fn == "tension") {  // b1 or b2 of a curve's Beta-spline basis (the B-spline: 1, 0)
    const auto* c = std::get_if<CurveElement>(&e);
    if (c && c->basis.family == "bspline") return {{fn == "bias" ? 1.0 : 0.0, 0}, false};
    if (!c || c->basis.family != "beta")
      fail(f, "value: " + fn + "() reads a curve whose basis is a beta or bspline; \"" + f.element + "\" is not one");
    // The canonical spec is "beta:b1=V,b2=V" with every digit of V (spline/basis.hpp).
    const std::string& spec = c->basis.spec;
    const auto at = spec.find(fn == "bias" ? "b1=" : "b2=");
    if (at == std::string::npos) fail(f, "value: " + fn + "(): no parameter in \"" + spec + "\"");
    return {{std::strtod(spec.c_str() + at + 3, nullptr), 0}, false};
  }
  if (fn == "marks") {  // the markers placed along a curve
    const auto* c = std::get_if<CurveElement>(&e);
    if (!c || c->marks == 0) fail(f, "value: marks() reads a curve with marks; \"" + f.element + "\" has none");
    return {{static_cast<double>(c->marks), 0}, false};
  }
  if (fn == "k") {  // k(s) of a kernel (times its scale) or of a filter curve
    if (const auto* k = std::get_if<KernelElement>(&e)) return {{k->scale * kernel(k->basis, f.args[0]), 0}, false};
    if (const auto* fc = std::get_if<FilterCurveElement>(&e)) return {{fc->filter(f.args[0]), 0}, false};
    fail(f, "value: k() reads a kernel or filter element; \"" + f.element + "\" is neither");
  }
  if (const auto* c = std::get_if<CurveElement>(&e); c && (fn == "point" || fn == "x" || fn == "y")) {
    // A spline curve: built as the figure builds it, evaluated at t in [0, its piece count].
    Points knots(2);
    for (Vec2 k : c->knots) knots.push_back(std::array<double, 2>{k.x, k.y});
    const Curve curve = make_curve(c->basis, knots, c->ends);
    const double t = f.args[0], t1 = static_cast<double>(curve.segments());
    if (!(t >= 0 && t <= t1))
      fail(f, "value: " + fn + "(): t = " + tick_number(t, 6) + " is outside the curve's parameter range [0, " +
                  tick_number(t1, 6) + "]");
    std::array<double, 2> xy{};
    splinefig::evaluate(curve, t, 0, xy);
    if (fn == "point") return {{xy[0], xy[1]}, true};
    return {{fn == "x" ? xy[0] : xy[1], 0}, false};
  }
  if (!is_generated(e))
    fail(f, "element: \"" + f.element + "\" is not a generated element (bezier, lagrange, interp, relaxed_bspline, "
            "subdivision, local_betas, ...): " + fn + "() reads generated data");
  const std::vector<GeneratedPart> parts = generate(e);
  if (fn == "count" || fn == "item") {
    std::vector<Vec2> pts;
    for (const auto& part : parts)
      if (const auto* s = std::get_if<GeneratedSeries>(&part)) {
        if (s->path) fail(f, "value: " + fn + "() reads the points of a point set; \"" + f.element + "\" draws a curve");
        pts.insert(pts.end(), s->series.points.begin(), s->series.points.end());
      }
    if (fn == "count") return {{static_cast<double>(pts.size()), 0}, false};
    const auto i = static_cast<std::size_t>(f.args[0]);
    if (i >= pts.size())
      fail(f, "value: item(" + std::to_string(i) + ") of \"" + f.element + "\", which draws " + std::to_string(pts.size()) +
                  " points");
    return {{pts[i].x, pts[i].y}, true};
  }
  const std::optional<Path> path = path_of(parts);
  if (!path || path->breaks.size() < 2)
    fail(f, "value: " + fn + "() needs a curve; \"" + f.element + "\" draws points only");
  const double t0 = path->breaks.front(), t1 = path->breaks.back();
  for (double t : f.args)
    if (!(t >= t0 && t <= t1))
      fail(f, "value: " + fn + "(): t = " + tick_number(t, 6) + " is outside the curve's parameter range [" +
                  tick_number(t0, 6) + ", " + tick_number(t1, 6) + "]");
  const double t = f.args[0];
  if (fn == "db") {  // 20 log10 |y(t)|, as a db axis draws it
    const double y = std::abs(path->at(t).y);
    if (!(y > 0)) fail(f, "value: db(): y is 0 at t = " + tick_number(t, 6) + " (minus infinity dB)");
    return {{20 * std::log10(y), 0}, false};
  }
  if (fn == "point" || fn == "x" || fn == "y") {
    const Vec2 p = path->at(t);
    if (fn == "point") return {{p.x, p.y}, true};
    return {{fn == "x" ? p.x : p.y, 0}, false};
  }
  if (fn == "d1" || fn == "d2") {
    const Vec2 d = fn == "d1" ? d1(piece_at(*path, t, f)) : d2(piece_at(*path, t, f));
    return {{d.x, d.y}, true};
  }
  if (fn == "curvature") {
    const Piece c = piece_at(*path, t, f);
    const Vec2 v = d1(c), a = d2(c);
    const double speed = std::hypot(v.x, v.y);
    if (!(speed > 0)) fail(f, "value: curvature(): the curve stands still at t = " + tick_number(t, 6));
    return {{(v.x * a.y - v.y * a.x) / (speed * speed * speed), 0}, false};
  }
  // max_y, min_y, argmax_y, argmin_y
  const double sign = fn.find("max") != std::string::npos ? 1 : -1;
  const double te = extremum(*path, f.args[0], f.args[1], sign);
  return {{fn.rfind("arg", 0) == 0 ? te : path->at(te).y, 0}, false};
}

// Every input point of the element, "(x, y), (x, y), ...", each number with at most `decimals`
// decimals and no trailing zeros.
std::string point_list(const FigureSpec& spec, const CaptionField& f) {
  const std::vector<Vec2>* pts = input_points(find_element(spec, f));
  if (!pts || pts->empty()) fail(f, "value: \"" + f.element + "\" has no points or knots for points()");
  auto num = [&](double v) {
    std::string s = tick_number(v, f.decimals);
    if (s.find('.') != std::string::npos) {
      while (s.back() == '0') s.pop_back();
      if (s.back() == '.') s.pop_back();
    }
    return s == "\u22120" ? std::string("0") : s;
  };
  std::string out;
  for (std::size_t i = 0; i < pts->size(); ++i) {
    if (i) out += ", ";
    out += '(';
    out += num((*pts)[i].x);
    out += ", ";
    out += num((*pts)[i].y);
    out += ')';
  }
  return out;
}

// v as p/q in lowest terms, q <= 1000 (an integer as itself, a negative with U+2212); a value
// no such fraction gives to within 1e-9 is an error naming the field.
std::string fraction_text(double v, const CaptionField& f) {
  for (long q = 1; q <= 1000; ++q) {
    const double p = std::round(v * static_cast<double>(q));
    if (std::abs(p / static_cast<double>(q) - v) <= 1e-9 * std::max(1.0, std::abs(v))) {
      const long num = static_cast<long>(std::abs(p));
      std::string s = (p < 0 ? "\u2212" : "") + std::to_string(num);
      if (q > 1) {
        s += '/';
        s += std::to_string(q);
      }
      return s;
    }
  }
  fail(f, "fraction: " + tick_number(v, 12) + " is no fraction p/q with q <= 1000 (write decimals instead)");
}

std::string number_text(double v, const CaptionField& f) {
  return f.fraction ? fraction_text(v, f) : tick_number(v, f.decimals);
}

}  // namespace

std::string caption_text(const FigureSpec& spec) {
  if (spec.caption_fields.empty()) return spec.caption;
  std::string problem;
  const std::vector<Ref> refs = references(spec.caption, problem);
  std::map<std::string, std::string> values;
  for (const CaptionField& f : spec.caption_fields) {
    if (f.function == "points") {
      values[f.name] = point_list(spec, f);
      continue;
    }
    const Value v = evaluate(spec, f);
    std::string text = number_text(v.v[0], f);
    if (v.vector) {  // "(x, y)", built by appends (GCC 12 -Wrestrict, PR 105329, on "(" + s)
      text.insert(text.begin(), '(');
      text += ", ";
      text += number_text(v.v[1], f);
      text += ')';
    }
    values[f.name] = std::move(text);
  }
  std::string out;
  std::size_t at = 0;
  for (const Ref& ref : refs) {
    out += spec.caption.substr(at, ref.begin - at);
    const auto it = values.find(ref.name);
    out += it != values.end() ? it->second : spec.caption.substr(ref.begin, ref.end - ref.begin);
    at = ref.end;
  }
  return out + spec.caption.substr(at);
}

}  // namespace splinefig::figures::detail
