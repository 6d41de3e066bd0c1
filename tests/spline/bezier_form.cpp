// The exact Bezier form of uniform spline pieces (change of basis) against seed 003's A-frame
// construction, values derived by hand, and evaluation by de Casteljau at many parameters.
#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/bezier_form.hpp>
#include <splinefig/spline/curve.hpp>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace splinefig;

namespace {
Points knots1(std::initializer_list<double> v) {
  Points p(1);
  p.coords = v;
  return p;
}
Points knots2(std::initializer_list<std::array<double, 2>> v) {
  Points p(2);
  for (auto q : v) p.push_back(q);
  return p;
}
}  // namespace

TEST_CASE("the B-spline's change of basis is seed 003's A-frame construction") {
  // S_i = 1/6 B_{i-1} + 2/3 B_i + 1/6 B_{i+1}; the division points 2/3 B_i + 1/3 B_{i+1} and
  // 1/3 B_i + 2/3 B_{i+1}; S_{i+1} = 1/6 B_i + 2/3 B_{i+1} + 1/6 B_{i+2}.
  const double expected[16] = {1. / 6, 4. / 6, 1. / 6, 0,  //
                               0, 2. / 3, 1. / 3, 0,      //
                               0, 1. / 3, 2. / 3, 0,      //
                               0, 1. / 6, 4. / 6, 1. / 6};
  const auto m = bezier_matrix(bspline());
  REQUIRE(m.size() == 16);
  for (int k = 0; k < 16; ++k) CHECK(m[k] == Approx(expected[k]).margin(1e-15));
}

TEST_CASE("Bezier points of B-spline and Catmull-Rom pieces, derived by hand") {
  // Knots 0, 6, 12, 18 (evenly spaced): S_1 = (0 + 24 + 12)/6 = 6, division points 8 and 10,
  // S_2 = (6 + 48 + 18)/6 = 12.
  const Points even = piece_bezier(make_curve(bspline(), knots1({0, 6, 12, 18}), Ends::open), 0);
  REQUIRE(even.size() == 4);
  CHECK(even.coords[0] == Approx(6).epsilon(1e-15));
  CHECK(even.coords[1] == Approx(8).epsilon(1e-15));
  CHECK(even.coords[2] == Approx(10).epsilon(1e-15));
  CHECK(even.coords[3] == Approx(12).epsilon(1e-15));
  // Knots 0, 3, 12, 6: B-spline S_1 = (0 + 12 + 12)/6 = 4, 2/3*3 + 1/3*12 = 6, 1/3*3 + 2/3*12 = 9,
  // S_2 = (3 + 48 + 6)/6 = 9.5.
  const Points b = piece_bezier(make_curve(bspline(), knots1({0, 3, 12, 6}), Ends::open), 0);
  CHECK(b.coords[0] == Approx(4).epsilon(1e-15));
  CHECK(b.coords[1] == Approx(6).epsilon(1e-15));
  CHECK(b.coords[2] == Approx(9).epsilon(1e-15));
  CHECK(b.coords[3] == Approx(9.5).epsilon(1e-15));
  // Catmull-Rom interpolates P1, P2 with tangents (P2 - P0)/2, (P3 - P1)/2: Bezier points
  // P1, P1 + (P2 - P0)/6 = 3 + 2 = 5, P2 - (P3 - P1)/6 = 12 - 0.5 = 11.5, P2.
  const Points c = piece_bezier(make_curve(catmull_rom(), knots1({0, 3, 12, 6}), Ends::open), 0);
  CHECK(c.coords[0] == Approx(3).epsilon(1e-15));
  CHECK(c.coords[1] == Approx(5).epsilon(1e-15));
  CHECK(c.coords[2] == Approx(11.5).epsilon(1e-15));
  CHECK(c.coords[3] == Approx(12).epsilon(1e-15));
  // Cardinal C_a: tangent a (P2 - P0), so the second point is P1 + a (P2 - P0)/3: a = 0.25 gives 4.
  const Points ca = piece_bezier(make_curve(cardinal(0.25), knots1({0, 3, 12, 6}), Ends::open), 0);
  CHECK(ca.coords[1] == Approx(4).epsilon(1e-15));
}

TEST_CASE("the Bezier pieces trace the spline: every basis, many parameters") {
  const Points k = knots2({{0, 0}, {40, 90}, {110, 30}, {150, 160}, {90, 210}, {20, 140}, {60, 60}});
  for (const Basis& b : {bspline(), catmull_rom(), cardinal(0.8), tensioned_bspline(3.0), beta(1.5, 4.0), beta(0.3, -2.0),
                         mitchell_netravali_basis(1.0 / 3, 1.0 / 3), uniform_bspline(2), uniform_bspline(5)}) {
    for (Ends e : {Ends::open, Ends::doubled, Ends::closed}) {
      const Curve c = make_curve(b, k, e);
      double worst = 0;
      for (std::size_t i = 0; i < c.segments(); ++i) {
        const Points bz = piece_bezier(c, i);
        REQUIRE(static_cast<int>(bz.size()) == b.degree + 1);
        for (int j = 0; j <= 64; ++j) {
          const double u = j / 64.0;
          std::array<double, 2> want{}, got{};
          evaluate(c, static_cast<double>(i) + u, 0, want);
          de_casteljau(bz, u, got);
          worst = std::max({worst, std::abs(want[0] - got[0]), std::abs(want[1] - got[1])});
        }
      }
      INFO(b.spec << " " << to_string(e));
      CHECK(worst < 1e-11);
    }
  }
}

TEST_CASE("kernel pieces as Bezier graphs: (x, k(x)) on every unit interval and on part of one") {
  for (const Basis& b : {bspline(), catmull_rom(), beta(2.0, 5.0), uniform_bspline(2), uniform_bspline(4)}) {
    const Support sup = kernel_support(b);
    for (int p = 0; p <= b.degree; ++p) {
      for (auto [u0, u1] : {std::pair{0.0, 1.0}, std::pair{0.25, 0.6}}) {
        const Points bz = kernel_piece_bezier(b, p, u0, u1, 2.0);
        double worst = 0;
        for (int j = 0; j <= 50; ++j) {
          const double v = j / 50.0;
          std::array<double, 2> q{};
          de_casteljau(bz, v, q);
          const double x = sup.lo + p + u0 + (u1 - u0) * v;
          worst = std::max({worst, std::abs(q[0] - x), std::abs(q[1] - 2.0 * kernel(b, std::min(x, sup.hi - 1e-15)))});
        }
        INFO(b.spec << " piece " << p << " [" << u0 << ", " << u1 << "]");
        CHECK(worst < 1e-12);
      }
    }
  }
  // The cubic B-spline's middle-right piece on [0, 1): k(0) = 2/3, k'(0) = 0, k(1) = 1/6,
  // k'(1) = -1/2, so its Bezier heights are 2/3, 2/3, 1/6 + 1/6 = 1/3, 1/6 (derived by hand).
  const Points m = kernel_piece_bezier(bspline(), 2);
  CHECK(m.coords[1] == Approx(2. / 3).margin(1e-15));
  CHECK(m.coords[3] == Approx(2. / 3).margin(1e-15));
  CHECK(m.coords[5] == Approx(1. / 3).margin(1e-15));
  CHECK(m.coords[7] == Approx(1. / 6).margin(1e-15));
  CHECK(m.coords[2] == Approx(1. / 3).margin(1e-15));  // x elevated: 0, 1/3, 2/3, 1
}
