// Spline kernels as pixel filters: the value must be the shape's indicator convolved with
// k(x) k(y) at the pixel centre, normalized by (integral of k)^2. The reference integrates it
// independently: for each x the shape (a union of convex polygons) meets the vertical line in
// intervals found exactly, whose kernel weight is integrated piece by piece with Gauss-Legendre
// (exact for polynomials), and the outer integral over x is split at every polygon vertex and
// kernel breakpoint so that Gauss-Legendre of high order is exact up to rounding there too.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <random>

namespace sr = splinefig::render;

namespace {

// 16-point Gauss-Legendre on [a, b].
template <class F>
double gauss16(F f, double a, double b) {
  static const double x[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                              0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
  static const double w[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                              0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
  const double m = 0.5 * (a + b), r = 0.5 * (b - a);
  double s = 0;
  for (int i = 0; i < 8; ++i) s += w[i] * (f(m + r * x[i]) + f(m - r * x[i]));
  return s * r;
}

struct RefKernel {  // the oracle's own piecewise polynomial, independent of kernel/
  double lo;
  std::vector<std::vector<double>> pieces;
  double operator()(double t) const {
    double u = t - lo;
    int p = static_cast<int>(std::floor(u));
    if (p < 0 || p >= static_cast<int>(pieces.size())) return 0;
    double v = u - p, s = 0, pw = 1;
    for (double c : pieces[static_cast<std::size_t>(p)]) { s += c * pw; pw *= v; }
    return s;
  }
  // integral of k over [a, b], split at the breakpoints
  double integral(double a, double b) const {
    double s = 0;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      double lo_p = std::max(a, lo + p), hi_p = std::min(b, lo + p + 1.0);
      if (hi_p > lo_p) s += gauss16(*this, lo_p, hi_p);
    }
    return s;
  }
};

double filtered_value(const std::vector<oracle::Poly>& shape, const RefKernel& k, double cx, double cy) {
  // value = integral over the shape of k(cx - x) k(cy - y) dx dy / (integral k)^2
  std::vector<double> xs;
  for (std::size_t p = 0; p <= k.pieces.size(); ++p) xs.push_back(cx - (k.lo + p));
  for (const auto& poly : shape)
    for (std::size_t i = 0; i < poly.size(); ++i) {
      auto u = poly[i], v = poly[(i + 1) % poly.size()];
      xs.push_back(u.x);
      // where the edge crosses a kernel breakpoint row: the y-weight has a kink there
      for (std::size_t p = 0; p <= k.pieces.size(); ++p) {
        double yb = cy - (k.lo + p);
        if ((u.y < yb) != (v.y < yb)) xs.push_back(u.x + (yb - u.y) * (v.x - u.x) / (v.y - u.y));
      }
    }
  // where edges of different pieces cross: the union of the intervals changes form there
  for (std::size_t a = 0; a < shape.size(); ++a)
    for (std::size_t b = a + 1; b < shape.size(); ++b)
      for (std::size_t i = 0; i < shape[a].size(); ++i)
        for (std::size_t j = 0; j < shape[b].size(); ++j) {
          auto p = shape[a][i], r = shape[a][(i + 1) % shape[a].size()];
          auto q = shape[b][j], t = shape[b][(j + 1) % shape[b].size()];
          double rx = r.x - p.x, ry = r.y - p.y, sx = t.x - q.x, sy = t.y - q.y;
          double den = rx * sy - ry * sx;
          if (den == 0) continue;
          double tt = ((q.x - p.x) * sy - (q.y - p.y) * sx) / den, uu = ((q.x - p.x) * ry - (q.y - p.y) * rx) / den;
          if (tt >= 0 && tt <= 1 && uu >= 0 && uu <= 1) xs.push_back(p.x + tt * rx);
        }
  std::sort(xs.begin(), xs.end());
  const double xmin = cx - (k.lo + k.pieces.size()), xmax = cx - k.lo;
  auto column = [&](double x) {
    std::vector<std::pair<double, double>> iv;
    for (const auto& poly : shape) {
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        auto u = poly[i], v = poly[(i + 1) % poly.size()];
        if ((u.x < x) == (v.x < x)) continue;
        double y = u.y + (x - u.x) * (v.y - u.y) / (v.x - u.x);
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
      if (hi > lo) iv.push_back({lo, hi});
    }
    std::sort(iv.begin(), iv.end());
    double s = 0, a = -INFINITY, b = -INFINITY;
    auto flush = [&] { if (b > a) s += k.integral(cy - b, cy - a); };
    for (auto [lo, hi] : iv) {
      if (lo > b) { flush(); a = lo; b = hi; } else b = std::max(b, hi);
    }
    flush();
    return k(cx - x) * s;
  };
  double v = 0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    double a = std::max(xs[i], xmin), b = std::min(xs[i + 1], xmax);
    if (b > a) v += gauss16(column, a, b);
  }
  double norm = k.integral(-1e9, 1e9);
  return v / (norm * norm);
}

splinefig::Kernel to_filter(const RefKernel& k, const char* name) { return splinefig::Kernel::piecewise(name, k.lo, k.pieces); }

const RefKernel kTent{-1, {{0, 1}, {1, -1}}};
const RefKernel kBSpline{-2, {{0, 0, 0, 1.0 / 6}, {1.0 / 6, 0.5, 0.5, -0.5}, {4.0 / 6, 0, -1, 0.5}, {1.0 / 6, -0.5, 0.5, -1.0 / 6}}};
// Catmull-Rom (negative lobes) and a lopsided kernel that pins the convolution's orientation.
const RefKernel kCatmullRom{-2, {{0, 0, -0.5, 0.5}, {0, 0.5, 2, -1.5}, {1, 0, -2.5, 1.5}, {0, -0.5, 1, -0.5}}};
const RefKernel kLopsided{-0.75, {{1, 2}, {0.5, -0.5}, {0.25}}};

void check_kernel(const RefKernel& k, const char* name) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int rep = 0; rep < 3; ++rep) {
    // a triangle and a bevel-joined two-segment stroke (a union of convex pieces)
    std::vector<oracle::P2> tri{{4 + 8 * u(rng), 3 + 5 * u(rng)}, {18 + 4 * u(rng), 6 + 8 * u(rng)}, {6 + 6 * u(rng), 16 + 3 * u(rng)}};
    std::vector<oracle::P2> path{{4.3 + u(rng), 5.1 + u(rng)}, {15.7, 9.2 + 2 * u(rng)}, {7.2 + u(rng), 17.6}};
    double width = 1 + 3 * u(rng);
    std::vector<oracle::Poly> shapes[2] = {{tri}, oracle::stroke_pieces(path, false, width, oracle::Join::Bevel, 4, oracle::Cap::Butt)};
    for (int which = 0; which < 2; ++which) {
      sr::Scene s(22, 22, {0, 0, 0, 0}, to_filter(k, name));
      if (which == 0) {
        std::vector<sr::Vec2> c;
        for (auto q : tri) c.push_back({q.x, q.y});
        s.fill_polygon({c}, sr::FillRule::NonZero, {1, 1, 1, 1});
      } else {
        std::vector<sr::Vec2> c;
        for (auto q : path) c.push_back({q.x, q.y});
        sr::StrokeStyle st;
        st.width = width;
        st.join = sr::Join::Bevel;
        s.stroke_polyline(c, false, st, {1, 1, 1, 1});
      }
      auto img = sr::rasterize(s, 1);
      double worst = 0;
      for (int y = 0; y < 22; ++y)
        for (int x = 0; x < 22; ++x) {
          double want = filtered_value(shapes[which], k, x + 0.5, y + 0.5);
          double got = img.pixel(x, y)[3];
          worst = std::max(worst, std::abs(got - want));
          INFO(name << " shape " << which << " pixel " << x << "," << y);
          REQUIRE(got == Approx(want).margin(1e-6));
        }
      WARN(name << " shape " << which << ": worst |error| " << worst);
    }
  }
}

}  // namespace

TEST_CASE("tent filter: pixel value is the exact convolution at the pixel centre") { check_kernel(kTent, "tent"); }
TEST_CASE("cubic B-spline filter: exact convolution") { check_kernel(kBSpline, "bspline"); }
TEST_CASE("Catmull-Rom filter (negative lobes): exact convolution") { check_kernel(kCatmullRom, "catmull-rom"); }
TEST_CASE("an asymmetric filter convolves (k(c - x)), it does not correlate") { check_kernel(kLopsided, "lopsided"); }

TEST_CASE("Kernel::tent is the linear B-spline and a solid fill under it gives 1") {
  auto f = splinefig::Kernel::tent();
  REQUIRE(f.pieces().size() == 2);
  sr::Scene s(8, 8, {0, 0, 0, 0}, f);
  s.fill_polygon({{{-5, -5}, {20, -5}, {20, 20}, {-5, 20}}}, sr::FillRule::NonZero, {1, 1, 1, 1});
  auto img = sr::rasterize(s, 1);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) REQUIRE(img.pixel(x, y)[3] == Approx(1.0).margin(1e-9));
}

TEST_CASE("a bad pixel filter is rejected with a message naming it") {
  using splinefig::Kernel;
  REQUIRE_THROWS_WITH(Kernel::piecewise("empty", -0.5, {}), Catch::Contains("empty"));
  REQUIRE_THROWS_AS(Kernel::piecewise("nan", -0.5, {{NAN}}), std::invalid_argument);
  // integral zero
  REQUIRE_THROWS_WITH(sr::Scene(8, 8, {}, Kernel::piecewise("flat", -0.5, {{1, -2}})), Catch::Contains("'flat': its integral"));
  REQUIRE_THROWS_WITH(sr::Scene(8, 8, {}, Kernel::lanczos(3)), Catch::Contains("'lanczos3': not a piecewise polynomial"));
  REQUIRE_THROWS_WITH(sr::Scene(8, 8, {}, Kernel::piecewise("wide", -5, std::vector<std::vector<double>>(9, {1.0}))),
                      Catch::Contains("wider than 8"));
}
