// Adaptive sampling of spline pieces into pixel polylines (see sampling.hpp).
#include <splinefig/figures/sampling.hpp>

#include <splinefig/spline/bezier_form.hpp>
#include <splinefig/spline/segment.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace splinefig::figures {
namespace {

constexpr int kMaxSteps = 1 << 14;

// A polynomial piece in pixel space: P(u) = sum_k cx[k] u^k, likewise y (ascending powers).
struct PixelPoly {
  std::vector<double> cx, cy;
  Vec2 at(double u) const { return {horner(cx, u), horner(cy, u)}; }
  static double horner(const std::vector<double>& c, double u) {
    double v = 0;
    for (size_t k = c.size(); k-- > 0;) v = v * u + c[k];
    return v;
  }
  // Bound on |P''(u)| over u in [u0, u1]: sum_k k(k-1) |c_k| max(|u0|,|u1|)^(k-2) per axis.
  double second_derivative_bound(double u0, double u1) const {
    double um = std::max(std::abs(u0), std::abs(u1));
    auto bound = [&](const std::vector<double>& c) {
      double b = 0, p = 1;
      for (size_t k = 2; k < c.size(); ++k, p *= um) b += k * (k - 1) * std::abs(c[k]) * p;
      return b;
    };
    return std::hypot(bound(cx), bound(cy));
  }
};

// A data-space piece mapped by an affine map: the coefficients scale, the constant term
// also shifts.
PixelPoly in_pixels(const PixelPoly& data, const PixelMap& map) {
  const double sx = (map.x.p1 - map.x.p0) / (map.x.d1 - map.x.d0);
  const double sy = (map.y.p1 - map.y.p0) / (map.y.d1 - map.y.d0);
  PixelPoly px = data;
  for (auto& v : px.cx) v *= sx;
  for (auto& v : px.cy) v *= sy;
  px.cx[0] = map.x.to_pixel(data.cx[0]);
  px.cy[0] = map.y.to_pixel(data.cy[0]);
  return px;
}

// Uniform steps of a polynomial piece over [u0, u1], appending (skipping the first point
// when `skip_first`).
void sample_poly(const PixelPoly& p, double u0, double u1, double tol, bool skip_first, std::vector<Vec2>& out) {
  double len = u1 - u0;
  double m2 = p.second_derivative_bound(u0, u1) * len * len;
  const double n = std::ceil(std::sqrt(m2 / (8 * tol)));  // clamped before the conversion
  const int steps = !(n >= 1) ? 1 : n >= kMaxSteps ? kMaxSteps : static_cast<int>(n);
  for (int j = skip_first ? 1 : 0; j <= steps; ++j) out.push_back(p.at(u0 + len * j / steps));
}

double chord_distance(Vec2 p, Vec2 a, Vec2 b) {
  double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Recursive flatness subdivision of any map u -> pixel: emit(u, f(u)) for the end of every
// chord, left to right. A piece is cut at least `min_depth` times and at most 18 times.
template <class Emit>
void subdivide(const std::function<Vec2(double)>& f, double u0, double u1, Vec2 a, Vec2 b, double tol, int depth,
               int min_depth, Emit&& emit) {
  double um = 0.5 * (u0 + u1);
  Vec2 m = f(um);
  bool flat = depth >= 18;
  if (!flat) {
    Vec2 q1 = f(0.5 * (u0 + um)), q3 = f(0.5 * (um + u1));
    flat = depth >= min_depth && chord_distance(m, a, b) <= tol && chord_distance(q1, a, b) <= tol &&
           chord_distance(q3, a, b) <= tol;
  }
  if (flat || !std::isfinite(m.x) || !std::isfinite(m.y)) {
    emit(u1, b);
    return;
  }
  subdivide(f, u0, um, a, m, tol, depth + 1, min_depth, emit);
  subdivide(f, um, u1, m, b, tol, depth + 1, min_depth, emit);
}

// For log axes: the points of the chords' ends.
void sample_recursive(const std::function<Vec2(double)>& f, double u0, double u1, Vec2 a, Vec2 b, double tol,
                      std::vector<Vec2>& out) {
  subdivide(f, u0, u1, a, b, tol, 0, 2, [&](double, Vec2 p) { out.push_back(p); });
}

void append_unique(std::vector<Vec2>& out, Vec2 p) {
  if (out.empty() || out.back().x != p.x || out.back().y != p.y) out.push_back(p);
}

}  // namespace

std::vector<Vec2> sample_curve(const Curve& c, const PixelMap& map, double tol) {
  const int n = c.degree(), dim = c.dim();
  std::vector<double> a(static_cast<size_t>((n + 1) * dim));
  std::vector<Vec2> raw;
  for (size_t i = 0; i < c.segments(); ++i) {
    piece_coefficients(c, i, a);
    // a[r*dim + d] multiplies u^(n-r): ascending powers k = n - r.
    PixelPoly data;
    data.cx.assign(n + 1, 0);
    data.cy.assign(n + 1, 0);
    for (int r = 0; r <= n; ++r) {
      data.cx[n - r] = a[r * dim];
      data.cy[n - r] = dim > 1 ? a[r * dim + 1] : 0;
    }
    if (map.affine()) {
      sample_poly(in_pixels(data, map), 0, 1, tol, i > 0, raw);
    } else {
      auto f = [&](double u) { return map(data.at(u)); };
      Vec2 p0 = f(0);
      if (i == 0) raw.push_back(p0);
      sample_recursive(f, 0, 1, p0, f(1), tol, raw);
    }
  }
  std::vector<Vec2> out;
  out.reserve(raw.size());
  for (Vec2 p : raw) append_unique(out, p);
  return out;
}

std::vector<std::vector<Vec2>> sample_kernel(const Basis& b, double s0, double s1, double scale, const PixelMap& map,
                                             double tol) {
  const int n = b.degree;
  Support sup = kernel_support(b);
  std::vector<std::vector<Vec2>> pieces(static_cast<size_t>(n + 1));
  for (int p = 0; p <= n; ++p) {
    // Piece p covers [lo + p, lo + p + 1): column c = n - p (c_n is the leftmost piece).
    int col = n - p;
    double left = sup.lo + p;
    double u0 = std::max(0.0, s0 - left), u1 = std::min(1.0, s1 - left);
    if (!(u0 < u1)) continue;
    PixelPoly data;
    data.cx = {left, 1.0};
    data.cy.assign(n + 1, 0);
    for (int r = 0; r <= n; ++r) data.cy[n - r] = scale * b(r, col);
    auto& out = pieces[p];
    if (map.affine()) {
      sample_poly(in_pixels(data, map), u0, u1, tol, false, out);
    } else {
      auto f = [&](double u) { return map(data.at(u)); };
      out.push_back(f(u0));
      sample_recursive(f, u0, u1, out.back(), f(u1), tol, out);
    }
  }
  // Zero outside the support.
  auto first = std::find_if(pieces.begin(), pieces.end(), [](const auto& v) { return !v.empty(); });
  auto last = std::find_if(pieces.rbegin(), pieces.rend(), [](const auto& v) { return !v.empty(); });
  if (s0 < sup.lo) {
    std::vector<Vec2> zero = {map({s0, 0.0}), map({std::min(sup.lo, s1), 0.0})};
    if (first != pieces.end()) first->insert(first->begin(), zero[0]);
    else pieces.front() = zero;
  }
  if (s1 > sup.hi && last != pieces.rend()) last->push_back(map({s1, 0.0}));
  else if (s1 > sup.hi && s0 >= sup.hi) pieces.back() = {map({s0, 0.0}), map({s1, 0.0})};
  return pieces;
}

namespace {

// Appends a Bezier of degree 1..3 (control points in data space, 2-D) mapped to pixels; starts
// a subpath if the path is empty, joins with a line if the piece starts elsewhere.
void append_bezier(render::Path& path, const Points& bz, const PixelMap& map) {
  const int n = static_cast<int>(bz.size()) - 1;
  auto at = [&](int k) { return map(Vec2{bz.coords[2 * k], bz.coords[2 * k + 1]}); };
  const Vec2 p0 = at(0);
  // Pieces of a continuous spline meet up to rounding (1e-13 px): no joining line for that.
  if (path.empty()) path.move_to(p0);
  else if (const Vec2 cur = path.points().back(); std::hypot(cur.x - p0.x, cur.y - p0.y) > 1e-9) path.line_to(p0);
  if (n == 1) path.line_to(at(1));
  else if (n == 2) path.quad_to(at(1), at(2));
  else path.cubic_to(at(1), at(2), at(3));
}

void append_line(render::Path& path, Vec2 a, Vec2 b) {
  if (path.empty()) path.move_to(a);
  else if (const Vec2 cur = path.points().back(); cur.x != a.x || cur.y != a.y) path.line_to(a);
  path.line_to(b);
}

}  // namespace

std::optional<render::Path> curve_path(const Curve& c, const PixelMap& map) {
  if (!map.affine() || c.degree() < 1 || c.degree() > 3 || c.segments() == 0) return std::nullopt;
  render::Path path;
  Points xy(2, static_cast<std::size_t>(c.degree() + 1));
  for (std::size_t i = 0; i < c.segments(); ++i) {
    const Points bz = piece_bezier(c, i);
    for (std::size_t k = 0; k < bz.size(); ++k) {
      xy.coords[2 * k] = bz.coords[k * static_cast<std::size_t>(c.dim())];
      xy.coords[2 * k + 1] = c.dim() > 1 ? bz.coords[k * static_cast<std::size_t>(c.dim()) + 1] : 0;
    }
    append_bezier(path, xy, map);
  }
  return path;
}

std::optional<std::vector<render::Path>> kernel_paths(const Basis& b, double s0, double s1, double scale,
                                                      const PixelMap& map) {
  const int n = b.degree;
  if (!map.affine() || n < 1 || n > 3) return std::nullopt;
  Support sup = kernel_support(b);
  std::vector<render::Path> pieces(static_cast<size_t>(n + 1));
  for (int p = 0; p <= n; ++p) {
    double left = sup.lo + p;
    double u0 = std::max(0.0, s0 - left), u1 = std::min(1.0, s1 - left);
    if (!(u0 < u1)) continue;
    append_bezier(pieces[p], kernel_piece_bezier(b, p, u0, u1, scale), map);
  }
  // Zero outside the support, joined to the first and last piece as sample_kernel does.
  auto first = std::find_if(pieces.begin(), pieces.end(), [](const auto& v) { return !v.empty(); });
  auto last = std::find_if(pieces.rbegin(), pieces.rend(), [](const auto& v) { return !v.empty(); });
  if (s0 < sup.lo) {
    render::Path zero;
    append_line(zero, map({s0, 0.0}), map({std::min(sup.lo, s1), 0.0}));
    if (first != pieces.end()) {
      const render::Path rest = *first;
      *first = zero;
      std::size_t k = 0;
      for (render::Path::Verb v : rest.verbs()) {
        const auto& q = rest.points();
        if (v == render::Path::Verb::Move) {
          const Vec2 cur = first->points().back();
          if (cur.x != q[k].x || cur.y != q[k].y) first->line_to(q[k]);
          ++k;
        }
        else if (v == render::Path::Verb::Line) first->line_to(q[k]), ++k;
        else if (v == render::Path::Verb::Cubic) first->cubic_to(q[k], q[k + 1], q[k + 2]), k += 3;
      }
    } else {
      pieces.front() = zero;
    }
  }
  if (s1 > sup.hi && last != pieces.rend()) append_line(*last, last->points().back(), map({s1, 0.0}));
  else if (s1 > sup.hi && s0 >= sup.hi) {
    pieces.back() = render::Path();
    append_line(pieces.back(), map({s0, 0.0}), map({s1, 0.0}));
  }
  return pieces;
}

std::vector<double> flat_parameters(const std::function<Vec2(double)>& f, double u0, double u1, double tol,
                                    int min_depth) {
  std::vector<double> out;
  if (!(u1 > u0)) return out;
  subdivide(f, u0, u1, f(u0), f(u1), tol, 0, min_depth, [&](double u, Vec2) { out.push_back(u); });
  return out;
}

}  // namespace splinefig::figures
