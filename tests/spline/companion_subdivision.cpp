// Subdivision of the uniform cubic B-spline (seed 002 §4.16.9): point counts, the refinement
// matrix, limit points, exercise 4.100, and refinement as knot insertion.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/nonuniform.hpp>
#include <splinefig/spline/subdivision.hpp>

#include <random>
#include <vector>

using namespace splinefig;

namespace {

// P_k = e_k in R^4: every result's coordinates are its coefficients on P_0..P_3.
Points unit_points(std::size_t n) {
  Points p(static_cast<int>(n), n);
  for (std::size_t k = 0; k < n; ++k) p.coords[k * n + k] = 1;
  return p;
}

void check_coefficients(std::span<const double> got, std::vector<double> num, double den) {
  REQUIRE(got.size() == num.size());
  for (std::size_t k = 0; k < num.size(); ++k) CHECK(got[k] == Approx(num[k] / den).margin(1e-15));
}

Points random_points(std::size_t count, int dim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-5, 5);
  Points p(dim, count);
  for (double& x : p.coords) x = d(rng);
  return p;
}

}  // namespace

TEST_CASE("Seed 002: one segment refines to 3 + 2^k points: 4, 5, 7, 11, 19") {
  const Points P = random_points(4, 2, 1);
  const std::size_t expect[] = {4, 5, 7, 11, 19, 35};
  for (int k = 0; k <= 5; ++k) CHECK(refine(P, k).size() == expect[k]);
  // Whole polygons: c points -> 2c - 3; closed polygons double.
  CHECK(refine(random_points(9, 3, 2)).size() == 15);
  CHECK(refine_closed(random_points(5, 2, 3)).size() == 10);
}

TEST_CASE("Seed 002: the first step is 1/8 [4 4 0 0, 1 6 1 0, 0 4 4 0, 0 1 6 1, 0 0 4 4]") {
  const Points r = refine(unit_points(4));
  check_coefficients(r[0], {4, 4, 0, 0}, 8);
  check_coefficients(r[1], {1, 6, 1, 0}, 8);
  check_coefficients(r[2], {0, 4, 4, 0}, 8);
  check_coefficients(r[3], {0, 1, 6, 1}, 8);
  check_coefficients(r[4], {0, 0, 4, 4}, 8);  // docs/errata.md: the seed's vector entry misprints this row
}

TEST_CASE("Seed 002: limit points P(0), P(1/2) (example 3) and P(3/4) (exercise 4.100)") {
  const Points P = unit_points(4);
  const Points l0 = limit_points(P);
  check_coefficients(l0[0], {1, 4, 1, 0}, 6);  // example 1: P(0)
  check_coefficients(l0[1], {0, 1, 4, 1}, 6);  // example 2: P(1)
  check_coefficients(limit_points(refine(P))[1], {1, 23, 23, 1}, 48);  // example 3: triplet P^1_123
  // Exercise 4.100: k = 3, i = 6: (P_6 + 4P_7 + P_8)/6 of step 3 = (P0 + 121P1 + 235P2 + 27P3)/384.
  const Points r3 = refine(P, 3);
  REQUIRE(r3.size() == 11);
  check_coefficients(limit_points(r3)[6], {1, 121, 235, 27}, 384);  // centre vertex 7
}

TEST_CASE("Limit points of every step lie on the B-spline curve at the expected parameters") {
  const Points P = random_points(6, 2, 4);
  const Curve c = make_curve(bspline(), P, Ends::open);  // pieces on t in [0, 3]
  for (int k = 0; k <= 4; ++k) {
    const Points L = limit_points(refine(P, k));
    const double step = 1.0 / static_cast<double>(1 << k);  // vertex j of step k sits at t = j step
    for (std::size_t j = 0; j < L.size(); ++j) {
      std::vector<double> x(2);
      evaluate(c, static_cast<double>(j) * step, 0, x);
      for (std::size_t d = 0; d < 2; ++d) CHECK(L[j][d] == Approx(x[d]).margin(1e-13));
    }
  }
}

TEST_CASE("A refinement step is knot insertion at the middle of every span (Boehm)") {
  // P_0..P_6 on knots 0..10: the curve lives on [3, 7] and vertex P_i's limit is at t = i + 2.
  const Points P = random_points(7, 3, 6);
  const BSplineCurve c{3, uniform_knots(P.size(), 3), P};
  // The refined polygon R (11 points) is the same curve on knots of half the spacing, shifted so
  // that R_1 (the vertex point of P_1) again has its limit at t = 3: knots 1.5, 2, ..., 8.5.
  const Points R = refine(P);
  std::vector<double> half(R.size() + 4);
  for (std::size_t j = 0; j < half.size(); ++j) half[j] = 1.5 + 0.5 * static_cast<double>(j);
  const BSplineCurve h{3, half, R};
  REQUIRE(h.t_min() == 3);
  REQUIRE(h.t_max() == 7);
  for (double t = 3; t <= 7; t += 1.0 / 16) {
    std::vector<double> a(3), b(3);
    de_boor(c, t, a);
    de_boor(h, t, b);
    for (std::size_t d = 0; d < 3; ++d) CHECK(a[d] == Approx(b[d]).margin(1e-12));
  }
  // Boehm insertion of the span midpoints 3.5 .. 6.5 gives the refined points wherever the
  // knots around a control point are all halved: points 2..8, exactly R_2..R_8.
  BSplineCurve r = c;
  for (double t : {3.5, 4.5, 5.5, 6.5}) r = insert_knot(r, t);
  REQUIRE(r.control.size() == 11);
  for (std::size_t j = 2; j <= 8; ++j)
    for (std::size_t d = 0; d < 3; ++d) CHECK(r.control[j][d] == Approx(R[j][d]).margin(1e-13));
}
