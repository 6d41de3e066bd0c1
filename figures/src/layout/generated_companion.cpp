// The companion texts' plot elements computed by the spline library (generated.hpp).
#include "generated.hpp"

#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/lagrange.hpp>
#include <splinefig/spline/local_beta.hpp>
#include <splinefig/spline/subdivision.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace splinefig::figures::detail {
namespace {

Points to_points(const std::vector<Vec2>& v) {
  Points p(2);
  for (Vec2 q : v) p.push_back(std::vector<double>{q.x, q.y});
  return p;
}

std::vector<Vec2> to_vec(const Points& p) {
  std::vector<Vec2> v;
  for (std::size_t i = 0; i < p.size(); ++i) v.push_back({p[i][0], p[i][1]});
  return v;
}

std::vector<double> integers(std::size_t n) {  // 0, 1, ..., n
  std::vector<double> b;
  for (std::size_t i = 0; i <= n; ++i) b.push_back(static_cast<double>(i));
  return b;
}

GeneratedSeries points(std::vector<Vec2> pts, const SeriesLook& look) { return {{std::move(pts), look}, std::nullopt}; }

GeneratedSeries traced(Path path, const SeriesLook& look) { return {{{}, look}, std::move(path)}; }

// A composite Bezier spline as a path over t in [0, pieces].
Path bezier_path(BezierSpline b) {
  auto s = std::make_shared<const BezierSpline>(std::move(b));
  Path p;
  p.breaks = integers(s->pieces());
  p.at = [s](double t) {
    double x[2];
    evaluate(*s, t, 0, x);
    return Vec2{x[0], x[1]};
  };
  if (s->points.dim == 2) p.bezier = to_vec(s->points);
  return p;
}

[[noreturn]] void reject(const SpecLocation& origin, const std::exception& e) {
  throw SpecFileError(origin, e.what());
}

}  // namespace

std::vector<GeneratedPart> parts_of(const InterpElement& e) {
  Interpolant s;
  try {
    const Points S = to_points(e.points);
    if (e.ends == InterpElement::EndMode::Relaxed) s = interpolate_relaxed(S);
    if (e.ends == InterpElement::EndMode::Clamped) {
      const Vec2 v = e.start_velocity.value_or(Vec2{0, 0}), w = e.end_velocity.value_or(Vec2{0, 0});
      const std::vector<double> a{v.x, v.y}, b{w.x, w.y};
      s = interpolate_clamped(S, a, b);
    }
    if (e.ends == InterpElement::EndMode::Periodic) s = interpolate_periodic(S);
  } catch (const std::invalid_argument& x) {
    reject(e.origin, x);
  }
  switch (e.show) {
    case InterpElement::Show::Curve: return {traced(bezier_path(bezier_pieces(s)), e.look)};
    case InterpElement::Show::Control: return {points(to_vec(s.control), e.look)};
    case InterpElement::Show::Bezier: return {points(to_vec(bezier_pieces(s).points), e.look)};
  }
  return {};
}

std::vector<GeneratedPart> parts_of(const RelaxedBsplineElement& e) {
  using Show = RelaxedBsplineElement::Show;
  const Points B = to_points(e.points);
  BezierSpline b = relaxed_bspline_bezier(B);
  const std::vector<Vec2> pts = to_vec(b.points);
  if (e.show == Show::Curve) return {traced(bezier_path(std::move(b)), e.look)};
  if (e.show == Show::Joints || e.show == Show::Division) {
    std::vector<Vec2> sel;
    for (std::size_t k = 0; k < pts.size(); ++k)
      if ((k % 3 == 0) == (e.show == Show::Joints)) sel.push_back(pts[k]);
    return {points(sel, e.look)};
  }
  if (e.show == Show::Bezier) return {points(pts, e.look)};
  // One A per interior joint: the legs from the outer division points up to the apex B_i,
  // and the cross-bar between the inner division points, through S_i (seed 003 §3-4). One
  // legend entry for all of them; `aframe` keeps only the one at B_aframe.
  std::vector<GeneratedPart> out;
  SeriesLook unlabelled = e.look;
  unlabelled.label = {};
  const std::size_t n = B.size() - 1;
  const std::size_t first = e.aframe > 0 ? static_cast<std::size_t>(e.aframe) : 1;
  const std::size_t last = e.aframe > 0 ? first + 1 : n;
  for (std::size_t i = first; i < last; ++i) {
    const Vec2 P1 = pts[3 * i - 2], P2 = pts[3 * i - 1], Q1 = pts[3 * i + 1], Q2 = pts[3 * i + 2];
    const Vec2 A{B[i][0], B[i][1]};
    out.push_back(points({P1, A, Q2}, i == first ? e.look : unlabelled));
    out.push_back(points({P2, Q1}, unlabelled));
  }
  return out;
}

std::vector<GeneratedPart> parts_of(const BezierElement& e) {
  auto P = std::make_shared<const Points>(to_points(e.points));
  Path p;
  p.breaks = {0, 1};
  p.at = [P](double t) {
    double x[2];
    de_casteljau(*P, t, x);
    return Vec2{x[0], x[1]};
  };
  // Up to degree 3 the curve is one cubic (degree elevation is exact).
  const std::vector<Vec2>& c = e.points;
  auto lerp = [](Vec2 a, Vec2 b, double t) { return Vec2{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; };
  if (c.size() == 2) p.bezier = {c[0], lerp(c[0], c[1], 1.0 / 3), lerp(c[0], c[1], 2.0 / 3), c[1]};
  if (c.size() == 3) p.bezier = {c[0], lerp(c[0], c[1], 2.0 / 3), lerp(c[2], c[1], 2.0 / 3), c[2]};
  if (c.size() == 4) p.bezier = c;
  return {traced(std::move(p), e.look)};
}

std::vector<GeneratedPart> parts_of(const LagrangeElement& e) {
  std::vector<double> t;
  Points y(1);
  for (Vec2 q : e.points) {
    t.push_back(q.x);
    y.push_back(std::vector<double>{q.y});
  }
  auto poly = std::make_shared<LagrangePolynomial>();
  try {
    *poly = lagrange(t, y);
  } catch (const std::invalid_argument& x) {
    reject(e.origin, x);
  }
  const double lo = e.range ? (*e.range)[0] : *std::min_element(t.begin(), t.end());
  const double hi = e.range ? (*e.range)[1] : *std::max_element(t.begin(), t.end());
  Path p;
  // The data's x's inside the range start the subdivision where the polynomial is pinned.
  p.breaks = {lo, hi};
  for (double x : t)
    if (x > lo && x < hi) p.breaks.push_back(x);
  std::sort(p.breaks.begin(), p.breaks.end());
  p.breaks.erase(std::unique(p.breaks.begin(), p.breaks.end()), p.breaks.end());
  if (p.breaks.size() < 2) p.breaks = {lo, lo};
  p.at = [poly](double x) {
    double v;
    evaluate(*poly, x, std::span<double>(&v, 1));
    return Vec2{x, v};
  };
  return {traced(std::move(p), e.look)};
}

std::vector<GeneratedPart> parts_of(const RelaxedBasisElement& e) {
  auto f = std::make_shared<const Interpolant>(relaxed_basis(e.n));
  const std::size_t k = static_cast<std::size_t>(e.k), n = static_cast<std::size_t>(e.n);
  Path p;
  p.breaks = integers(n);
  p.at = [f, k, n](double t) {
    std::vector<double> x(n + 1);
    evaluate(*f, t, 0, x);
    return Vec2{t, x[k]};
  };
  return {traced(std::move(p), e.look)};
}

std::vector<GeneratedPart> parts_of(const SubdivisionElement& e) {
  const Points R = refine(to_points(e.points), e.steps);
  return {points(to_vec(e.limit ? limit_points(R) : R), e.look)};
}

std::vector<GeneratedPart> parts_of(const LocalBetasElement& e) {
  std::vector<ShapeParameters> betas;
  for (const auto& b : e.betas) betas.push_back({b[0], b[1]});
  // The knots extended for the end mode, with their parameters (as sample_local_betas does).
  struct Data {
    Points control;
    std::vector<ShapeParameters> betas;
  };
  auto d = std::make_shared<Data>();
  try {
    const Curve c = make_curve(beta(1, 0), to_points(e.knots), e.ends);
    d->control = c.control;
    d->betas = extend_betas(betas, e.ends);
    validate_local_betas(d->control, d->betas);
  } catch (const std::invalid_argument& x) {
    reject(e.origin, x);
  }
  const std::size_t pieces = d->control.size() - 3;  // pieces 1 .. n-3 of n control points
  Path p;
  p.breaks = integers(pieces);
  p.closed = e.ends == Ends::closed;
  p.at = [d, pieces](double t) {
    const std::size_t i = std::min(pieces, 1 + static_cast<std::size_t>(std::max(0.0, std::floor(t))));
    double x[2];
    local_beta_point(d->control, d->betas, i, t - static_cast<double>(i - 1), 0, x);
    return Vec2{x[0], x[1]};
  };
  return {traced(std::move(p), e.look)};
}

std::vector<GeneratedPart> parts_of(const InbetweenElement& e) {
  // Each keyframe is one point of R^(2m); an in-between frame lies on the relaxed spline through
  // them (seed 003 section 6), or on the straight line between the two keyframes around it (the
  // linear in-betweening the notes warn about).
  const std::size_t m = e.frames[0].size();
  Points keys;
  for (const auto& frame : e.frames) {
    std::vector<double> flat;
    for (Vec2 q : frame) flat.insert(flat.end(), {q.x, q.y});
    keys.push_back(flat);
  }
  const bool linear = e.interpolation == InbetweenElement::Interpolation::Linear;
  const Interpolant relaxed = linear ? Interpolant{} : interpolate_relaxed(keys);
  auto frame_at = [&](double t, Vec2 moved) {
    std::vector<double> x(2 * m);
    if (!linear) {
      evaluate(relaxed, t, 0, x);
    } else {
      const std::size_t k = std::min(keys.size() - 2, static_cast<std::size_t>(std::floor(t)));
      const double u = t - static_cast<double>(k);
      for (std::size_t j = 0; j < 2 * m; ++j) x[j] = (1 - u) * keys[k][j] + u * keys[k + 1][j];
    }
    std::vector<Vec2> pts;
    for (std::size_t i = 0; i < m; ++i) pts.push_back({x[2 * i] + moved.x, x[2 * i + 1] + moved.y});
    return pts;
  };
  if (e.steps == 0) return {points(frame_at(e.t, {0, 0}), e.look)};
  // A filmstrip: the frame at t = i / steps moved by i * shift, for i = 0 .. steps * n. The
  // keyframes (i a multiple of steps) are drawn from their data, with markers, in key_color; the
  // legend names the first in-between frame and the first keyframe.
  SeriesLook between = e.look, key = e.look;
  if (e.key_color) key.color = e.key_color;
  key.mode = SeriesMode::LineMarkers;
  key.stroke.dashes = {};
  key.label = e.key_label;
  std::vector<GeneratedPart> parts;
  const int count = e.steps * static_cast<int>(keys.size() - 1);
  for (int i = 0; i <= count; ++i) {
    const Vec2 moved{i * e.shift.x, i * e.shift.y};
    if (i % e.steps == 0) {
      std::vector<Vec2> pts;
      for (Vec2 q : e.frames[static_cast<std::size_t>(i / e.steps)]) pts.push_back({q.x + moved.x, q.y + moved.y});
      parts.push_back(points(pts, key));
      key.label = {};
    } else {
      parts.push_back(points(frame_at(static_cast<double>(i) / e.steps, moved), between));
      between.label = {};
    }
  }
  return parts;
}

}  // namespace splinefig::figures::detail
