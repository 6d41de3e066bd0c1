// Clipping an exact path to a rectangle: each line or cubic piece is split at its parameters on
// the rectangle's sides and the sub-pieces inside are kept, so the clipped path is exact.
#include "clip_path.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace splinefig::figures::detail {
namespace {

double bernstein(const std::array<double, 4>& c, double t) {
  const double s = 1 - t;
  const double a = s * c[0] + t * c[1], b = s * c[1] + t * c[2], d = s * c[2] + t * c[3];
  const double e = s * a + t * b, f = s * b + t * d;
  return s * e + t * f;
}

// The roots in (0, 1) of A t^2 + B t + C, ascending (the product form of the quadratic formula
// avoids cancellation; A = 0 leaves the linear root).
std::vector<double> quadratic_roots_in_unit(double A, double B, double C) {
  std::vector<double> out;
  auto add = [&](double t) {
    if (t > 0 && t < 1) out.push_back(t);
  };
  if (A == 0) {
    if (B != 0) add(-C / B);
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return out;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    add(q / A);
    if (q != 0) add(C / q);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The zero of f in [lo, hi], where f(lo) and f(hi) have opposite signs and f is monotone, by
// bisection down to adjacent doubles; the end with the smaller |f|.
double bisect(const std::array<double, 4>& c, double lo, double hi, double flo) {
  for (int i = 0; i < 2200; ++i) {
    const double m = 0.5 * (lo + hi);
    if (!(m > lo && m < hi)) break;
    const double fm = bernstein(c, m);
    if (fm == 0) return m;
    if ((fm < 0) == (flo < 0)) lo = m, flo = fm;
    else hi = m;
  }
  return std::abs(bernstein(c, lo)) <= std::abs(bernstein(c, hi)) ? lo : hi;
}

// One piece of a path: a line (p[0], p[3]) or a cubic p[0..3].
struct Piece {
  bool cubic;
  std::array<Vec2, 4> p;

  double coord(int k, int axis) const { return axis == 0 ? p[k].x : p[k].y; }
  // The parameters in (0, 1) where coordinate `axis` equals v.
  std::vector<double> crossings(int axis, double v) const {
    const double a = coord(0, axis), b = coord(3, axis);
    if (cubic) return cubic_crossings({a, coord(1, axis), coord(2, axis), b}, v);
    std::vector<double> out;
    if (a == b) return out;
    const double t = (v - a) / (b - a);
    if (t > 0 && t < 1) out.push_back(t);
    return out;
  }
  Vec2 at(double t) const {
    if (!cubic) return {p[0].x + t * (p[3].x - p[0].x), p[0].y + t * (p[3].y - p[0].y)};
    const std::array<double, 4> x{p[0].x, p[1].x, p[2].x, p[3].x}, y{p[0].y, p[1].y, p[2].y, p[3].y};
    return {bernstein(x, t), bernstein(y, t)};
  }
  // The blossom f(u, v, w) of the cubic: de Casteljau with a different parameter per level.
  Vec2 blossom(double u, double v, double w) const {
    auto lerp = [](Vec2 a, Vec2 b, double t) { return Vec2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; };
    const Vec2 a = lerp(p[0], p[1], u), b = lerp(p[1], p[2], u), c = lerp(p[2], p[3], u);
    const Vec2 d = lerp(a, b, v), e = lerp(b, c, v);
    return lerp(d, e, w);
  }
  // The piece restricted to [t0, t1]: for a cubic its control points are the blossoms
  // f(t0,t0,t0), f(t0,t0,t1), f(t0,t1,t1), f(t1,t1,t1).
  Piece part(double t0, double t1) const {
    if (!cubic) return {false, {at(t0), {}, {}, at(t1)}};
    return {true, {blossom(t0, t0, t0), blossom(t0, t0, t1), blossom(t0, t1, t1), blossom(t1, t1, t1)}};
  }
};

// A parameter where a piece meets a side: the coordinates that are exactly that side's there.
struct Split {
  double t;
  std::optional<double> x, y;
};

void snap(Vec2& q, const Split& s) {
  if (s.x) q.x = *s.x;
  if (s.y) q.y = *s.y;
}

// The splits of a piece on the four sides, ascending, one per parameter.
std::vector<Split> splits(const Piece& piece, const Rect& r) {
  std::vector<Split> all;
  for (double v : {r.left, r.right})
    for (double t : piece.crossings(0, v)) all.push_back({t, v, std::nullopt});
  for (double v : {r.top, r.bottom})
    for (double t : piece.crossings(1, v)) all.push_back({t, std::nullopt, v});
  std::sort(all.begin(), all.end(), [](const Split& a, const Split& b) { return a.t < b.t; });
  std::vector<Split> out;
  for (const Split& s : all) {
    if (!out.empty() && out.back().t == s.t) {
      if (s.x) out.back().x = s.x;
      if (s.y) out.back().y = s.y;
    } else {
      out.push_back(s);
    }
  }
  return out;
}

void append_piece(render::Path& path, const Piece& q) {
  if (q.cubic) path.cubic_to(q.p[1], q.p[2], q.p[3]);
  else path.line_to(q.p[3]);
}

// Appends `from`'s pieces (its first subpath, without its move) to `to`.
void append_path(render::Path& to, const render::Path& from) {
  std::size_t k = 0;
  const auto& pt = from.points();
  for (render::Path::Verb v : from.verbs()) {
    if (v == render::Path::Verb::Move) ++k;
    else if (v == render::Path::Verb::Line) to.line_to(pt[k++]);
    else if (v == render::Path::Verb::Cubic) to.cubic_to(pt[k], pt[k + 1], pt[k + 2]), k += 3;
  }
}

// The parts inside `r` of one subpath (its pieces in order), appended to `out`.
void clip_subpath(const std::vector<Piece>& pieces, bool closed, const Rect& r, std::vector<render::Path>& out) {
  const std::size_t first_run = out.size();
  bool open = false, dropped = false, starts_at_start = false, ends_at_end = false;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& piece = pieces[i];
    const std::vector<Split> ss = splits(piece, r);
    for (std::size_t j = 0; j <= ss.size(); ++j) {
      const double t0 = j == 0 ? 0.0 : ss[j - 1].t, t1 = j == ss.size() ? 1.0 : ss[j].t;
      if (!r.contains(piece.at(0.5 * (t0 + t1)))) {
        open = false;
        dropped = true;
        continue;
      }
      Piece part = piece.part(t0, t1);
      if (j > 0) snap(part.p[0], ss[j - 1]);
      if (j < ss.size()) snap(part.p[3], ss[j]);
      if (!open) {
        out.emplace_back().move_to(part.p[0]);
        open = true;
        if (i == 0 && j == 0) starts_at_start = true;
      }
      append_piece(out.back(), part);
      if (i + 1 == pieces.size() && j == ss.size()) ends_at_end = true;
    }
  }
  if (!closed || out.size() == first_run) return;
  if (!dropped) {
    out.back().close();
  } else if (starts_at_start && ends_at_end && out.size() - first_run >= 2) {
    // The subpath's start is inside: its last part continues into its first.
    append_path(out.back(), out[first_run]);
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(first_run));
  }
}

}  // namespace

std::vector<double> cubic_crossings(const std::array<double, 4>& b, double v) {
  const std::array<double, 4> c{b[0] - v, b[1] - v, b[2] - v, b[3] - v};
  std::vector<double> out;
  if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) return out;
  // Monotone intervals: between the zeros of the derivative, 3 times the quadratic with
  // Bernstein coefficients d_k = c_{k+1} - c_k.
  const double d0 = c[1] - c[0], d1 = c[2] - c[1], d2 = c[3] - c[2];
  std::vector<double> breaks{0.0};
  for (double t : quadratic_roots_in_unit(d0 - 2 * d1 + d2, 2 * (d1 - d0), d0)) breaks.push_back(t);
  breaks.push_back(1.0);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = breaks[i], hi = breaks[i + 1];
    const double flo = bernstein(c, lo), fhi = bernstein(c, hi);
    if (flo == 0) {
      if (lo > 0) out.push_back(lo);  // at a turning point: the curve touches v there
    } else if (fhi != 0 && (flo < 0) != (fhi < 0)) {
      out.push_back(bisect(c, lo, hi, flo));
    }  // fhi == 0 inside (0, 1) is the next interval's start
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<render::Path> clip_path(const render::Path& path, const Rect& r) {
  std::vector<render::Path> out;
  std::vector<Piece> pieces;
  Vec2 cur{}, start{};
  std::size_t k = 0;
  const auto& pt = path.points();
  auto finish = [&](bool closed) {
    if (!pieces.empty()) clip_subpath(pieces, closed, r, out);
    pieces.clear();
  };
  for (render::Path::Verb v : path.verbs()) {
    switch (v) {
      case render::Path::Verb::Move:
        finish(false);
        cur = start = pt[k++];
        break;
      case render::Path::Verb::Line:
        pieces.push_back({false, {cur, {}, {}, pt[k]}});
        cur = pt[k++];
        break;
      case render::Path::Verb::Cubic:
        pieces.push_back({true, {cur, pt[k], pt[k + 1], pt[k + 2]}});
        cur = pt[k + 2];
        k += 3;
        break;
      case render::Path::Verb::Close:
        if (cur.x != start.x || cur.y != start.y) pieces.push_back({false, {cur, {}, {}, start}});
        finish(true);
        cur = start;
        break;
    }
  }
  finish(false);
  return out;
}

}  // namespace splinefig::figures::detail
