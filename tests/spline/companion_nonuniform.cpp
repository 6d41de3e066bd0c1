// Non-uniform B-splines: Cox-de Boor against seed 002's answer 4.103, against the uniform
// matrices on uniform knots (the core's seed-002 m_ij matrices), partition of unity on random
// knot vectors with repeated knots, de Boor against the basis sum, derivatives, knot insertion.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/nonuniform.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace splinefig;

namespace {

Points random_points(std::size_t count, int dim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-5, 5);
  Points p(dim, count);
  for (double& x : p.coords) x = d(rng);
  return p;
}

std::vector<double> random_knots(std::size_t m, unsigned seed) {
  // Non-decreasing, with some repeated knots (multiplicity up to 3).
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> gap(0.1, 2.0);
  std::uniform_int_distribution<int> repeat(0, 5);
  std::vector<double> k{0};
  while (k.size() < m) {
    const int r = repeat(rng);
    const double next = k.back() + gap(rng);
    for (int j = 0; j < (r == 0 ? 3 : r == 1 ? 2 : 1) && k.size() < m; ++j) k.push_back(next);
  }
  return k;
}

}  // namespace

TEST_CASE("Seed 002 answer 4.103: cubic blending functions on (-3,-2,-1,0,1,1,1,2,3,4,5,6)") {
  const std::vector<double> K{-3, -2, -1, 0, 1, 1, 1, 2, 3, 4, 5, 6};
  auto N = [&](std::size_t i, double t) { return cox_de_boor(K, 3, i, t); };
  for (double t = 0; t < 1; t += 0.125) {
    CHECK(N(0, t) == Approx(std::pow(1 - t, 3) / 6).margin(1e-15));
    CHECK(N(1, t) == Approx((11 * t * t * t - 15 * t * t - 3 * t + 7) / 12).margin(1e-15));
    CHECK(N(2, t) == Approx((-7 * t * t * t + 3 * t * t + 3 * t + 1) / 4).margin(1e-15));
    CHECK(N(3, t) == Approx(t * t * t).margin(1e-15));
  }
  for (double t = 1; t < 2; t += 0.125) {
    CHECK(N(3, t) == Approx(std::pow(2 - t, 3)).margin(1e-15));
    CHECK(N(4, t) == Approx((7 * t * t * t - 39 * t * t + 69 * t - 37) / 4).margin(1e-14));
    CHECK(N(5, t) == Approx((-11 * t * t * t + 51 * t * t - 69 * t + 29) / 12).margin(1e-14));
    CHECK(N(6, t) == Approx(std::pow(t - 1, 3) / 6).margin(1e-15));
  }
  for (double t = 2; t < 3; t += 0.125) {
    CHECK(N(4, t) == Approx(std::pow(3 - t, 3) / 4).margin(1e-15));
    CHECK(N(5, t) == Approx((7 * t * t * t - 57 * t * t + 147 * t - 115) / 12).margin(1e-13));
    CHECK(N(6, t) == Approx((-3 * t * t * t + 21 * t * t - 45 * t + 31) / 6).margin(1e-13));
    CHECK(N(7, t) == Approx(std::pow(t - 2, 3) / 6).margin(1e-15));
  }
  // The triple knot at 1: the curve interpolates P_3 there (N_34(1) = 1).
  CHECK(N(3, 1.0) == 1.0);
}

TEST_CASE("Cox-de Boor on uniform knots is the uniform B-spline of seed 002, degrees 1 to 5") {
  for (int n = 1; n <= 5; ++n) {
    const Basis b = uniform_bspline(n);
    const std::vector<double> K = uniform_knots(12, n);
    const int h = (n - 1) / 2;
    // N_{0,n} has support [0, n+1]; the centred kernel has support [h-n, h+1].
    for (double t = 0; t <= n + 1; t += 1.0 / 32) {
      INFO("degree " << n << " t " << t);
      CHECK(cox_de_boor(K, n, 0, t) == Approx(kernel(b, t + h - n)).margin(1e-14));
    }
    // The matrix columns: on span s the n+1 non-zero functions are the basis segments, column j
    // weighting the piece's j-th control point: N_{s-n+j}(s + u) = basis_segment(M, j, u).
    std::vector<double> N(static_cast<std::size_t>(n + 1));
    for (double u = 0; u < 1; u += 1.0 / 16) {
      basis_functions(K, n, static_cast<std::size_t>(n) + 2, n + 2 + u, N);
      for (int j = 0; j <= n; ++j) CHECK(N[static_cast<std::size_t>(j)] == Approx(basis_segment(b, j, u)).margin(1e-14));
    }
  }
}

TEST_CASE("Partition of unity and non-negativity on random knot vectors with repeated knots") {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const int p = 1 + static_cast<int>(seed % 5);
    const std::size_t count = 12;
    const std::vector<double> K = random_knots(count + static_cast<std::size_t>(p) + 1, seed);
    const double lo = K[static_cast<std::size_t>(p)], hi = K[count];
    if (!(hi > lo)) continue;
    std::vector<double> N(static_cast<std::size_t>(p + 1));
    for (int j = 0; j < 97; ++j) {
      const double t = lo + (hi - lo) * j / 97.0;
      const std::size_t s = find_span(K, p, count, t);
      REQUIRE(K[s] <= t);
      REQUIRE(t < K[s + 1]);
      basis_functions(K, p, s, t, N);
      double sum = 0, sum_rec = 0;
      for (std::size_t i = 0; i <= static_cast<std::size_t>(p); ++i) {
        CHECK(N[i] >= -1e-15);
        sum += N[i];
        CHECK(N[i] == Approx(cox_de_boor(K, p, s - static_cast<std::size_t>(p) + i, t)).margin(1e-13));
      }
      for (std::size_t i = 0; i < count; ++i) sum_rec += cox_de_boor(K, p, i, t);
      CHECK(sum == Approx(1).epsilon(1e-14));
      CHECK(sum_rec == Approx(1).epsilon(1e-14));
    }
  }
}

TEST_CASE("de Boor's algorithm equals the sum of basis functions times control points") {
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const int p = 1 + static_cast<int>(seed % 4);
    const std::size_t count = 9;
    BSplineCurve c{p, random_knots(count + static_cast<std::size_t>(p) + 1, seed + 50), random_points(count, 3, seed)};
    if (!(c.t_max() > c.t_min())) continue;
    REQUIRE_NOTHROW(validate(c));
    for (int j = 0; j < 50; ++j) {
      const double t = c.t_min() + (c.t_max() - c.t_min()) * j / 50.0;
      std::vector<double> x(3);
      de_boor(c, t, x);
      for (std::size_t d = 0; d < 3; ++d) {
        double sum = 0;
        for (std::size_t i = 0; i < count; ++i) sum += cox_de_boor(c.knots, p, i, t) * c.control[i][d];
        CHECK(x[d] == Approx(sum).margin(1e-12));
      }
    }
  }
}

TEST_CASE("Clamped cubic with 4 control points is the Bezier curve, with its derivatives") {
  const Points P = random_points(4, 2, 77);
  const BSplineCurve c{3, clamped_knots(4, 3), P};
  const Points D = bezier_derivative(P), DD = bezier_derivative(D);
  for (double t = 0; t <= 1; t += 0.125) {
    std::vector<double> a(2), b(2);
    for (int k = 0; k <= 2; ++k) {
      evaluate(c, t, k, a);
      de_casteljau(k == 0 ? P : k == 1 ? D : DD, t, b);
      for (std::size_t d = 0; d < 2; ++d) CHECK(a[d] == Approx(b[d]).margin(1e-12));
    }
  }
}

TEST_CASE("Derivatives on uniform knots match the uniform matrix path, repeated knots drop continuity") {
  const Points P = random_points(8, 2, 8);
  const BSplineCurve c{3, uniform_knots(8, 3), P};
  const Curve u = make_curve(bspline(), P, Ends::open);  // t in [0, 5] is knot parameter t + 3
  for (double t = 0; t <= 5; t += 0.1) {
    for (int k = 0; k <= 2; ++k) {
      std::vector<double> a(2), b(2);
      evaluate(c, t + 3, k, a);
      evaluate(u, t, k, b);
      for (std::size_t d = 0; d < 2; ++d) CHECK(a[d] == Approx(b[d]).margin(1e-12));
    }
  }
  // A triple knot leaves the cubic only C0 there: the curve passes through a control point
  // with a corner.
  const BSplineCurve r{3, {0, 1, 2, 3, 4, 4, 4, 5, 6, 7, 8, 9}, P};
  std::vector<double> x(2), left(2), right(2);
  evaluate(r, 4, 0, x);
  CHECK(x[0] == Approx(P[3][0]).margin(1e-14));
  CHECK(x[1] == Approx(P[3][1]).margin(1e-14));
  evaluate(r, std::nextafter(4.0, 0.0), 1, left);
  evaluate(r, 4, 1, right);
  CHECK(std::abs(left[0] - right[0]) + std::abs(left[1] - right[1]) > 1e-3);
}

TEST_CASE("Knot insertion leaves the curve unchanged") {
  const Points P = random_points(7, 2, 9);
  const BSplineCurve c{3, {0, 0, 0, 0, 1, 2.5, 3, 4, 4, 4, 4}, P};
  BSplineCurve r = insert_knot(c, 1.7);
  r = insert_knot(r, 2.5);
  r = insert_knot(r, 0.2);
  CHECK(r.control.size() == 10);
  for (double t = 0; t <= 4; t += 0.05) {
    std::vector<double> a(2), b(2);
    de_boor(c, t, a);
    de_boor(r, t, b);
    for (std::size_t d = 0; d < 2; ++d) CHECK(a[d] == Approx(b[d]).margin(1e-12));
  }
}

TEST_CASE("Invalid knot vectors are rejected with the reason") {
  const Points P = random_points(4, 2, 1);
  CHECK_THROWS_WITH(validate(BSplineCurve{3, {0, 1, 2}, P}), Catch::Contains("needs 8 knots"));
  CHECK_THROWS_WITH(validate(BSplineCurve{3, {0, 1, 2, 3, 2, 5, 6, 7}, P}), Catch::Contains("smaller than knot 3"));
  CHECK_THROWS_WITH(validate(BSplineCurve{5, uniform_knots(4, 5), P}), Catch::Contains("at least 6 control points"));
  CHECK_THROWS_WITH(validate(BSplineCurve{3, {0, 0, 0, 1, 1, 1, 1, 1}, P}), Catch::Contains("empty domain"));
}

TEST_CASE("Sampling by spans equals de Boor at the same parameters, uniform and not") {
  for (int dim : {2, 3, 5})
  for (const std::vector<double>& K : {uniform_knots(9, 3), std::vector<double>{0, 0, 0, 0, 0.5, 2, 2, 3, 3.25, 4, 4, 4, 4}}) {
    const Points P = random_points(9, dim, 12);
    const BSplineCurve c{3, K, P};
    const Points s = sample(c, 5);
    std::size_t row = 0;
    for (std::size_t span = 3; span < 9; ++span) {
      if (!(K[span + 1] > K[span])) continue;
      for (int j = 0; j < 5; ++j, ++row) {
        std::vector<double> x(static_cast<std::size_t>(dim));
        de_boor(c, K[span] + (K[span + 1] - K[span]) * j / 5.0, x);
        for (std::size_t d = 0; d < x.size(); ++d) CHECK(s[row][d] == Approx(x[d]).margin(1e-13));
      }
    }
    REQUIRE(row + 1 == s.size());
    std::vector<double> end(static_cast<std::size_t>(dim));
    de_boor(c, c.t_max(), end);
    CHECK(s[row][0] == Approx(end[0]).margin(1e-13));
  }
}
