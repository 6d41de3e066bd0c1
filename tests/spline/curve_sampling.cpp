// Curves through knots: counts per end mode, exact values at rational u, seed 002's
// subdivision answers, repeated knots, derivatives at the joints.
#include <catch2/catch.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/segment.hpp>

#include <cmath>
#include <vector>

using namespace splinefig;

namespace {

Points points2(std::initializer_list<std::pair<double, double>> ps) {
  Points p(2);
  for (auto [x, y] : ps) p.push_back(std::vector<double>{x, y});
  return p;
}

std::vector<double> at(const Curve& c, double t, int derivative = 0) {
  std::vector<double> out(static_cast<size_t>(c.dim()));
  evaluate(c, t, derivative, out);
  return out;
}

void check_point(std::span<const double> got, std::vector<double> expect, double tol = 1e-14) {
  REQUIRE(got.size() == expect.size());
  for (size_t d = 0; d < expect.size(); ++d) {
    INFO("coordinate " << d);
    CHECK(got[d] == Approx(expect[d]).margin(tol));
  }
}

}  // namespace

TEST_CASE("Seed 002: B-spline P(1/2) = (P0+23P1+23P2+P3)/48 and P(3/4) = (P0+121P1+235P2+27P3)/384") {
  const Points k = points2({{0, 0}, {48, 96}, {-96, 384}, {960, -480}});
  const Curve c = make_curve(bspline(), k, Ends::open);
  REQUIRE(c.segments() == 1);
  auto combo = [&](double a, double b, double cc, double d, double den) {
    return std::vector<double>{(a * k[0][0] + b * k[1][0] + cc * k[2][0] + d * k[3][0]) / den,
                               (a * k[0][1] + b * k[1][1] + cc * k[2][1] + d * k[3][1]) / den};
  };
  check_point(at(c, 0.5), combo(1, 23, 23, 1, 48), 1e-12);
  check_point(at(c, 0.75), combo(1, 121, 235, 27, 384), 1e-12);
  // The same points from the grain sampler: grain 4 gives u = 0, 1/4, 1/2, 3/4, 1.
  const Points s = sample(c, 4);
  REQUIRE(s.size() == 5);
  check_point(s[2], combo(1, 23, 23, 1, 48), 1e-12);
  check_point(s[3], combo(1, 121, 235, 27, 384), 1e-12);
  // Ends of the segment: (P0 + 4P1 + P2)/6 and (P1 + 4P2 + P3)/6 (seed 002, examples 1 and 2).
  check_point(s[0], combo(1, 4, 1, 0, 6), 1e-12);
  check_point(s[4], combo(0, 1, 4, 1, 6), 1e-12);
}

TEST_CASE("Catmull-Rom at u = 1/2 is (-x0 + 9x1 + 9x2 - x3)/16, cardinal gives (-a, 4+a, 4+a, -a)/8") {
  Points k(1);
  for (double x : {3.0, -5.0, 7.0, 11.0}) k.push_back(std::vector<double>{x});
  const double cr = (-3.0 + 9 * -5.0 + 9 * 7.0 - 11.0) / 16;
  CHECK(at(make_curve(catmull_rom(), k, Ends::open), 0.5)[0] == cr);
  for (double a : {0.0, 0.25, 1.0, 2.0}) {
    const double e = (-a * 3.0 + (4 + a) * -5.0 + (4 + a) * 7.0 - a * 11.0) / 8;
    INFO("a = " << a);
    CHECK(at(make_curve(cardinal(a), k, Ends::open), 0.5)[0] == Approx(e).margin(1e-14));
  }
}

TEST_CASE("Open ends: n knots give (n-3)*grain+1 points, through x[1]..x[n-2] for Catmull-Rom") {
  const Points k = points2({{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}, {7, 4}, {9, 5}});
  const Curve c = make_curve(catmull_rom(), k, Ends::open);
  for (int grain : {1, 2, 5, 16}) {
    const Points s = sample(c, grain);
    INFO("grain " << grain);
    REQUIRE(s.size() == static_cast<size_t>((7 - 3) * grain + 1));
    for (size_t i = 0; i < 5; ++i) check_point(s[i * grain], {k[i + 1][0], k[i + 1][1]}, 0);
  }
  CHECK_THROWS_AS(make_curve(catmull_rom(), points2({{0, 0}, {1, 1}, {2, 2}}), Ends::open), CurveError);
  CHECK_THROWS_AS(sample(c, 0), CurveError);
}

TEST_CASE("Closed ends: n knots give n*grain+1 points, the last equal to the first") {
  const Points k = points2({{0, 0}, {4, 0}, {4, 3}, {0, 3}, {-1, 1}});
  for (const Basis& b : {catmull_rom(), bspline(), beta(2.0, 3.0), uniform_bspline(5), uniform_bspline(2)}) {
    INFO(b.spec);
    const Curve c = make_curve(b, k, Ends::closed);
    const Points s = sample(c, 8);
    REQUIRE(s.size() == 5 * 8 + 1);
    check_point(s[40], {s[0][0], s[0][1]}, 0);
    // Cyclic: the piece after the last is the first again, so u = 1 of the last piece is the start.
    check_point(at(c, 5.0), {s[0][0], s[0][1]}, 1e-13);
  }
  const Curve cr = make_curve(catmull_rom(), k, Ends::closed);
  const Points s = sample(cr, 8);
  for (size_t i = 0; i < 5; ++i) check_point(s[i * 8], {k[i][0], k[i][1]}, 0);
}

TEST_CASE("Doubled ends: the curve starts at the first knot (Catmull-Rom) or at (5x0+x1)/6 (B-spline)") {
  const Points k = points2({{0, 0}, {6, 12}, {12, 6}, {18, 18}});
  const Curve cr = make_curve(catmull_rom(), k, Ends::doubled);
  const Points s = sample(cr, 4);
  REQUIRE(s.size() == (4 + 2 - 3) * 4 + 1);
  check_point(s[0], {0, 0}, 0);
  check_point(s[12], {18, 18}, 0);
  const Curve b = make_curve(bspline(), k, Ends::doubled);
  check_point(at(b, 0), {1, 2}, 1e-14);
  check_point(at(b, 3), {17, 16}, 1e-14);  // (x2 + 5x3)/6
  // Two knots are enough once both are doubled: x0 x0 x1 x1 is one piece.
  CHECK(make_curve(catmull_rom(), points2({{0, 0}, {1, 1}}), Ends::doubled).segments() == 1);
}

TEST_CASE("A knot of multiplicity 3 pulls the B-spline onto it, with zero velocity there") {
  const Points k = points2({{0, 0}, {3, 6}, {9, 3}, {9, 3}, {9, 3}, {15, 0}, {18, 6}});
  const Curve c = make_curve(bspline(), k, Ends::open);
  // Joint t = 2 sits on control[2..4] = the triple knot: (x + 4x + x)/6 = x.
  check_point(at(c, 2), {9, 3}, 1e-14);
  check_point(at(c, 2, 1), {0, 0}, 1e-14);
}

TEST_CASE("Derivatives at joints: (x[i+1]-x[i-1])/2 for Catmull-Rom and B-spline, x[i-1]-2x[i]+x[i+1] for B") {
  const Points k = points2({{0, 1}, {2, 5}, {3, -1}, {7, 2}, {8, 8}, {4, 9}});
  const Curve cr = make_curve(catmull_rom(), k, Ends::open);
  const Curve bs = make_curve(bspline(), k, Ends::open);
  for (size_t i = 1; i + 1 < k.size(); ++i) {
    const double t = static_cast<double>(i - 1);
    INFO("knot " << i);
    const std::vector<double> v = {(k[i + 1][0] - k[i - 1][0]) / 2, (k[i + 1][1] - k[i - 1][1]) / 2};
    check_point(at(cr, t, 1), v, 1e-13);
    check_point(at(bs, t, 1), v, 1e-13);
    check_point(at(bs, t, 2),
                {k[i - 1][0] - 2 * k[i][0] + k[i + 1][0], k[i - 1][1] - 2 * k[i][1] + k[i + 1][1]}, 1e-13);
  }
  // The sampler's derivative rows agree with evaluate() at the same parameters.
  for (int deriv : {1, 2}) {
    const Points s = sample(bs, 3, deriv);
    for (size_t j = 0; j < s.size(); ++j) check_point(s[j], at(bs, j / 3.0, deriv), 1e-12);
  }
}

TEST_CASE("Degree-n curves: n-th degree pieces, (knots - n)*grain + 1 points") {
  Points k(1);
  for (double x : {0.0, 6.0, 0.0, 12.0, 24.0, 6.0, 0.0}) k.push_back(std::vector<double>{x});
  // Degree 1 is the control polygon itself.
  const Curve lin = make_curve(uniform_bspline(1), k, Ends::open);
  const Points s1 = sample(lin, 2);
  REQUIRE(s1.size() == (7 - 1) * 2 + 1);
  CHECK(s1[1][0] == 3.0);
  CHECK(s1[12][0] == 0.0);
  // Degree 2 (h = 0): piece i uses x[i..i+2]; starts at (x0+x1)/2, ends at (x1+x2)/2.
  const Curve quad = make_curve(uniform_bspline(2), k, Ends::open);
  REQUIRE(sample(quad, 4).size() == (7 - 2) * 4 + 1);
  CHECK(at(quad, 0)[0] == Approx(3.0).margin(1e-14));
  CHECK(at(quad, 1)[0] == Approx(3.0).margin(1e-14));
  CHECK(at(quad, 0.5)[0] == Approx((0.0 + 6 * 6.0 + 0.0) / 8).margin(1e-14));
  // Degree 5: (x0 + 26x1 + 66x2 + 26x3 + x4)/120 at the start of a piece (h = 2).
  const Curve quint = make_curve(uniform_bspline(5), k, Ends::open);
  REQUIRE(sample(quint, 3).size() == (7 - 5) * 3 + 1);
  CHECK(at(quint, 0)[0] == Approx((0.0 + 26 * 6.0 + 66 * 0.0 + 26 * 12.0 + 24.0) / 120).margin(1e-13));
}

TEST_CASE("Points of any dimension: 1-D, 3-D and the memo's 6-D Genesis path agree per coordinate") {
  const std::vector<double> xs = {0, 1, 4, 2, 7, 5, 3};
  Points one(1), six(6);
  for (size_t i = 0; i < xs.size(); ++i) {
    one.push_back(std::vector<double>{xs[i]});
    six.push_back(std::vector<double>{xs[i], -xs[i], 2 * xs[i], xs[i] + 1, 0.5 * xs[i], 3.0});
  }
  for (const Basis& b : {catmull_rom(), bspline(), beta(0.5, 2.0)}) {
    const Points s1 = sample(make_curve(b, one, Ends::open), 7);
    const Points s6 = sample(make_curve(b, six, Ends::open), 7);
    REQUIRE(s1.size() == s6.size());
    for (size_t j = 0; j < s1.size(); ++j) {
      const double x = s1[j][0];
      check_point(s6[j], {x, -x, 2 * x, x + 1, 0.5 * x, 3.0}, 1e-13);
    }
  }
}

TEST_CASE("Partition of unity: the basis weights sum to 1 at every u, for every family") {
  for (const Basis& b : {catmull_rom(), cardinal(1.3), bspline(), tensioned_bspline(0.3), beta(2.5, 4.0),
                         beta(0.25, 0.0), uniform_bspline(1), uniform_bspline(2), uniform_bspline(4),
                         uniform_bspline(5), uniform_bspline(7)}) {
    INFO(b.spec);
    std::vector<double> w(static_cast<size_t>(b.order()));
    for (int j = 0; j <= 32; ++j) {
      basis_weights(b, j / 32.0, 0, w);
      double sum = 0;
      for (double x : w) sum += x;
      CHECK(sum == Approx(1.0).margin(1e-14));
      // So derivatives of a constant curve vanish: the weights' derivatives sum to 0.
      for (int d = 1; d <= 2 && d <= b.degree; ++d) {
        basis_weights(b, j / 32.0, d, w);
        double ds = 0;
        for (double x : w) ds += x;
        CHECK(ds == Approx(0.0).margin(1e-13));
      }
    }
  }
}
