#pragma once
// An independent oracle for exact stroke coverage, sharing no code with the renderer.
//
// The stroke is built literally as its pieces (SVG 2 / docs/conventions.md): a rectangle per segment,
// a join piece at each interior vertex (round: the circular sector between the outer corners;
// miter: the quadrilateral to the miter tip, or the bevel triangle past the limit; bevel: the
// triangle), caps at the ends (square: half-square; round: half-disk). Arcs are polygons with
// sagitta below 1e-6 px. Every piece is convex.
//
// Union area inside a pixel: each piece is clipped to the pixel square (Sutherland-Hodgman);
// then a vertical-slab sweep: between consecutive x values at which any clipped vertex lies or
// two edges of different pieces cross, every vertical line meets each piece in an interval
// whose ends move linearly and keep their order, so the length of the union of the intervals
// is linear in x and the midpoint rule integrates it exactly.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace oracle {

struct P2 {
  double x, y;
};
using Poly = std::vector<P2>;

inline constexpr double kPi = std::numbers::pi;

enum class Join { Miter, Round, Bevel };
enum class Cap { Butt, Round, Square };

// Convex polygon of the circular sector (centre c, radius r) from angle a0 through signed sweep.
inline Poly sector(P2 c, double r, double a0, double sweep) {
  Poly p{c};
  const double step = 2 * std::acos(1 - std::min(1.0, 1e-6 / r));
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / step)));
  for (int k = 0; k <= n; ++k) {
    const double a = a0 + sweep * k / n;
    p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return p;
}

inline std::vector<Poly> stroke_pieces(std::vector<P2> pts, bool closed, double width, Join join, double miter_limit,
                                       Cap cap) {
  std::vector<Poly> out;
  const double h = width / 2;
  std::vector<P2> p;
  for (P2 q : pts)
    if (p.empty() || q.x != p.back().x || q.y != p.back().y) p.push_back(q);
  if (closed)
    while (p.size() > 1 && p.back().x == p.front().x && p.back().y == p.front().y) p.pop_back();
  if (p.size() < 2 || h <= 0) return out;
  const std::size_t nseg = closed ? p.size() : p.size() - 1;
  struct Seg {
    P2 a, b, d, n;
    double len;
  };
  std::vector<Seg> s;
  for (std::size_t i = 0; i < nseg; ++i) {
    P2 a = p[i], b = p[(i + 1) % p.size()];
    double len = std::hypot(b.x - a.x, b.y - a.y);
    P2 d{(b.x - a.x) / len, (b.y - a.y) / len};
    P2 n{-d.y, d.x};
    s.push_back({a, b, d, n, len});
    out.push_back({{a.x + h * n.x, a.y + h * n.y}, {b.x + h * n.x, b.y + h * n.y}, {b.x - h * n.x, b.y - h * n.y},
                   {a.x - h * n.x, a.y - h * n.y}});
  }
  auto add_join = [&](const Seg& A, const Seg& B) {
    P2 P = A.b;
    double c = A.d.x * B.d.y - A.d.y * B.d.x, dt = A.d.x * B.d.x + A.d.y * B.d.y;
    if (c == 0 && dt > 0) return;
    // The turn bends towards +n when c > 0, so the outer corners are on the -n side.
    double side = c < 0 ? 1 : -1;
    P2 oa{P.x + side * h * A.n.x, P.y + side * h * A.n.y}, ob{P.x + side * h * B.n.x, P.y + side * h * B.n.y};
    if (join == Join::Round) {
      // From oa to ob the short way; a reversal (c = 0) takes the half-disk ahead of A.
      double sw = c == 0 ? kPi : (c > 0 ? 1 : -1) * std::acos(std::clamp(dt, -1.0, 1.0));
      out.push_back(sector(P, h, std::atan2(oa.y - P.y, oa.x - P.x), sw));
      return;
    }
    double cos_half = std::sqrt(std::max(0.0, (1 + dt) / 2));
    if (join == Join::Miter && cos_half > 0 && 1 / cos_half <= miter_limit) {
      P2 m{P.x + side * h * (A.n.x + B.n.x) / (1 + dt), P.y + side * h * (A.n.y + B.n.y) / (1 + dt)};
      out.push_back({P, oa, m, ob});
    } else {
      out.push_back({P, oa, ob});
    }
  };
  for (std::size_t i = 1; i < nseg; ++i) add_join(s[i - 1], s[i]);
  if (closed) add_join(s[nseg - 1], s[0]);
  if (!closed) {
    for (int end = 0; end < 2; ++end) {
      const Seg& g = end ? s.back() : s.front();
      P2 P = end ? g.b : g.a;
      P2 d = end ? g.d : P2{-g.d.x, -g.d.y};
      if (cap == Cap::Square) {
        P2 n = g.n;
        out.push_back({{P.x + h * n.x, P.y + h * n.y}, {P.x + h * n.x + h * d.x, P.y + h * n.y + h * d.y},
                       {P.x - h * n.x + h * d.x, P.y - h * n.y + h * d.y}, {P.x - h * n.x, P.y - h * n.y}});
      } else if (cap == Cap::Round) {
        double ad = std::atan2(d.y, d.x);
        out.push_back(sector(P, h, ad - kPi / 2, kPi));  // the half-disk beyond the end
      }
    }
  }
  return out;
}

// Sutherland-Hodgman clip of a convex polygon to [x0,x1] x [y0,y1].
inline Poly clip_to_box(const Poly& in, double x0, double y0, double x1, double y1) {
  Poly cur = in, next;
  auto pass = [&](auto inside, auto cut) {
    next.clear();
    for (std::size_t i = 0; i < cur.size(); ++i) {
      P2 a = cur[i], b = cur[(i + 1) % cur.size()];
      bool ia = inside(a), ib = inside(b);
      if (ia) next.push_back(a);
      if (ia != ib) next.push_back(cut(a, b));
    }
    std::swap(cur, next);
  };
  auto cx = [](double X) {
    return [X](P2 a, P2 b) { double t = (X - a.x) / (b.x - a.x); return P2{X, a.y + t * (b.y - a.y)}; };
  };
  auto cy = [](double Y) {
    return [Y](P2 a, P2 b) { double t = (Y - a.y) / (b.y - a.y); return P2{a.x + t * (b.x - a.x), Y}; };
  };
  pass([&](P2 p) { return p.x >= x0; }, cx(x0));
  if (cur.empty()) return cur;
  pass([&](P2 p) { return p.x <= x1; }, cx(x1));
  if (cur.empty()) return cur;
  pass([&](P2 p) { return p.y >= y0; }, cy(y0));
  if (cur.empty()) return cur;
  pass([&](P2 p) { return p.y <= y1; }, cy(y1));
  return cur;
}

inline double polygon_area(const Poly& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    P2 u = p[i], v = p[(i + 1) % p.size()];
    a += u.x * v.y - v.x * u.y;
  }
  return std::abs(a) / 2;
}

// Area of the union of convex polygons (already clipped into one pixel).
inline double union_area(const std::vector<Poly>& polys) {
  std::vector<double> xs;
  for (const Poly& p : polys)
    for (P2 q : p) xs.push_back(q.x);
  for (std::size_t i = 0; i < polys.size(); ++i)
    for (std::size_t j = i + 1; j < polys.size(); ++j) {
      const Poly &A = polys[i], &B = polys[j];
      for (std::size_t a = 0; a < A.size(); ++a) {
        P2 p = A[a], r{A[(a + 1) % A.size()].x - p.x, A[(a + 1) % A.size()].y - p.y};
        for (std::size_t b = 0; b < B.size(); ++b) {
          P2 q = B[b], s{B[(b + 1) % B.size()].x - q.x, B[(b + 1) % B.size()].y - q.y};
          double den = r.x * s.y - r.y * s.x;
          if (den == 0) continue;
          double t = ((q.x - p.x) * s.y - (q.y - p.y) * s.x) / den;
          double u = ((q.x - p.x) * r.y - (q.y - p.y) * r.x) / den;
          if (t >= 0 && t <= 1 && u >= 0 && u <= 1) xs.push_back(p.x + t * r.x);
        }
      }
    }
  std::sort(xs.begin(), xs.end());
  double area = 0;
  std::vector<std::pair<double, double>> iv;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double xa = xs[k], xb = xs[k + 1];
    if (!(xb > xa)) continue;
    const double xm = 0.5 * (xa + xb);
    iv.clear();
    for (const Poly& p : polys) {
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < p.size(); ++i) {
        P2 u = p[i], v = p[(i + 1) % p.size()];
        if ((u.x < xm) == (v.x < xm)) continue;
        double y = u.y + (xm - u.x) * (v.y - u.y) / (v.x - u.x);
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
      if (hi > lo) iv.push_back({lo, hi});
    }
    std::sort(iv.begin(), iv.end());
    double len = 0, cur_lo = -INFINITY, cur_hi = -INFINITY;
    for (auto [lo, hi] : iv) {
      if (lo > cur_hi) {
        len += cur_hi - cur_lo > 0 ? cur_hi - cur_lo : 0;
        cur_lo = lo;
        cur_hi = hi;
      } else {
        cur_hi = std::max(cur_hi, hi);
      }
    }
    if (cur_hi > cur_lo) len += cur_hi - cur_lo;
    area += (xb - xa) * len;
  }
  return area;
}

// Coverage of the union of `pieces` in every pixel of a width x height canvas, row-major.
inline std::vector<double> union_coverage(const std::vector<Poly>& pieces, int width, int height) {
  std::vector<double> cov(static_cast<std::size_t>(width) * height, 0.0);
  struct BB {
    double x0, y0, x1, y1;
  };
  std::vector<BB> bb;
  for (const Poly& p : pieces) {
    BB b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (P2 q : p) {
      b.x0 = std::min(b.x0, q.x); b.y0 = std::min(b.y0, q.y);
      b.x1 = std::max(b.x1, q.x); b.y1 = std::max(b.y1, q.y);
    }
    bb.push_back(b);
  }
  std::vector<Poly> local;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      local.clear();
      bool full = false;
      for (std::size_t i = 0; i < pieces.size() && !full; ++i) {
        if (bb[i].x1 <= x || bb[i].x0 >= x + 1 || bb[i].y1 <= y || bb[i].y0 >= y + 1) continue;
        Poly c = clip_to_box(pieces[i], x, y, x + 1, y + 1);
        if (c.size() < 3) continue;
        double a = polygon_area(c);
        if (a >= 1 - 1e-12) full = true;
        if (a > 0) local.push_back(std::move(c));
      }
      cov[static_cast<std::size_t>(y) * width + x] = full ? 1.0 : std::min(1.0, union_area(local));
    }
  return cov;
}

}  // namespace oracle
