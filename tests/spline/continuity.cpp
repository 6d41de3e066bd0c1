// Continuity at the joints of curves: C1 for cardinal splines, C2 for the B-spline, and G2
// with velocity ratio b1 for Beta-splines, with the curvature of the 2-D curve computed here
// from the one-sided derivatives as the independent check.
#include <catch2/catch.hpp>
#include <splinefig/spline/continuity.hpp>

#include <cmath>
#include <vector>

using namespace splinefig;

namespace {

Points zigzag() {
  Points p(2);
  for (auto [x, y] : std::vector<std::pair<double, double>>{
           {0, 0}, {1, 3}, {2, 0.5}, {3.5, 2.5}, {4, -1}, {6, 1}, {7, 4}, {9, 2}})
    p.push_back(std::vector<double>{x, y});
  return p;
}

// Signed curvature (x'y'' - y'x'') / |X'|^3 of a plane curve.
double curvature(const std::vector<double>& d1, const std::vector<double>& d2) {
  return (d1[0] * d2[1] - d1[1] * d2[0]) / std::pow(std::hypot(d1[0], d1[1]), 3);
}

}  // namespace

TEST_CASE("Cardinal splines are C1 and not C2 at their joints, tangent a(x[i+1] - x[i-1])") {
  const Points k = zigzag();
  for (double a : {0.5, 1.0, 0.3}) {
    INFO("a = " << a);
    const Curve c = make_curve(cardinal(a), k, Ends::open);
    CHECK(parametric_continuity(c) == 1);
    CHECK(geometric_continuity(c) == 1);
    for (const Joint& j : joints(c)) {
      const size_t i = static_cast<size_t>(j.t) + 1;  // the knot at this joint
      CHECK(j.right[1][0] == Approx(a * (k[i + 1][0] - k[i - 1][0])).margin(1e-13));
      CHECK(j.right[1][1] == Approx(a * (k[i + 1][1] - k[i - 1][1])).margin(1e-13));
      CHECK(j.jump[2] > 1e-3);
    }
  }
  CHECK(parametric_continuity(make_curve(catmull_rom(), k, Ends::closed)) == 1);
}

TEST_CASE("The B-spline is C2 at its joints, open and closed, degree 1 and 2 are C0 and C1") {
  const Points k = zigzag();
  CHECK(parametric_continuity(make_curve(bspline(), k, Ends::open)) == 2);
  CHECK(parametric_continuity(make_curve(bspline(), k, Ends::closed)) == 2);
  CHECK(geometric_continuity(make_curve(bspline(), k, Ends::closed)) == 2);
  CHECK(parametric_continuity(make_curve(uniform_bspline(5), k, Ends::open)) == 2);
  CHECK(parametric_continuity(make_curve(uniform_bspline(2), k, Ends::open)) == 1);
  const Curve poly = make_curve(uniform_bspline(1), k, Ends::open);
  CHECK(parametric_continuity(poly) == 0);
  CHECK(geometric_continuity(poly) == 0);  // the control polygon has corners
}

TEST_CASE("Beta-splines are G2 with velocity ratio b1 at every joint, and not C1 when b1 != 1") {
  const Points k = zigzag();
  for (auto [b1, b2] : std::vector<std::pair<double, double>>{{2.0, 0.0}, {0.5, 3.0}, {1.0, 8.0}, {3.0, 10.0}}) {
    INFO("b1 = " << b1 << ", b2 = " << b2);
    const Curve c = make_curve(beta(b1, b2), k, Ends::open);
    CHECK(geometric_continuity(c) == 2);
    CHECK(parametric_continuity(c) == (b1 != 1 ? 0 : b2 != 0 ? 1 : 2));
    CHECK(beta_constraint_residual(c, b1, b2) < 1e-13);
    for (const Joint& j : joints(c)) {
      CHECK(j.velocity_ratio == Approx(b1).epsilon(1e-13));
      CHECK(curvature(j.right[1], j.right[2]) == Approx(curvature(j.left[1], j.left[2])).epsilon(1e-11));
    }
  }
  // Duff's B_a is the Beta-spline with b1 = 1, b2 = 12(1-a)/a: G2 and C1.
  const Curve duff = make_curve(tensioned_bspline(0.5), k, Ends::open);
  CHECK(parametric_continuity(duff) == 1);
  CHECK(geometric_continuity(duff) == 2);
  CHECK(beta_constraint_residual(duff, 1.0, 12.0) < 1e-13);
  CHECK(beta_constraint_residual(duff, 1.0, 0.0) > 1e-3);
}

TEST_CASE("A triple knot keeps the B-spline C2 but stops at a cusp: not G1") {
  Points k(2);
  for (auto [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {3, 6}, {9, 3}, {9, 3}, {9, 3}, {15, 0}, {18, 6}})
    k.push_back(std::vector<double>{x, y});
  const Curve c = make_curve(bspline(), k, Ends::open);
  CHECK(parametric_continuity(c) == 2);
  CHECK(geometric_continuity(c) == 0);
}
