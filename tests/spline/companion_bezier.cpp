// Bezier curves (seed 003 §2-4): de Casteljau against the Bernstein sum, splitting, the
// hodograph, the A-frame gluing conditions and the relaxed B-spline's Bezier pieces.
#include <catch2/catch.hpp>
#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/interp.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace splinefig;

namespace {

Points points2(std::initializer_list<std::pair<double, double>> ps) {
  Points p(2);
  for (auto [x, y] : ps) p.push_back(std::vector<double>{x, y});
  return p;
}

double binom(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// sum_k C(d,k) (1-t)^(d-k) t^k P_k, and its first derivative, straight from the definition.
std::vector<double> bernstein(const Points& P, double t, bool derivative = false) {
  const int d = static_cast<int>(P.size()) - 1;
  std::vector<double> out(static_cast<std::size_t>(P.dim), 0.0);
  for (int k = 0; k <= d; ++k) {
    double w;
    if (!derivative) {
      w = binom(d, k) * std::pow(1 - t, d - k) * std::pow(t, k);
    } else {  // d/dt of (1-t)^(d-k) t^k
      w = binom(d, k) * ((k > 0 ? k * std::pow(t, k - 1) * std::pow(1 - t, d - k) : 0) -
                         (d - k > 0 ? (d - k) * std::pow(1 - t, d - k - 1) * std::pow(t, k) : 0));
    }
    for (std::size_t c = 0; c < out.size(); ++c) out[c] += w * P[static_cast<std::size_t>(k)][c];
  }
  return out;
}

std::vector<double> casteljau(const Points& P, double t) {
  std::vector<double> out(static_cast<std::size_t>(P.dim));
  de_casteljau(P, t, out);
  return out;
}

Points random_points(std::size_t count, int dim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-5, 5);
  Points p(dim, count);
  for (double& x : p.coords) x = d(rng);
  return p;
}

}  // namespace

TEST_CASE("de Casteljau equals the Bernstein sum for degrees 1 to 6") {
  for (std::size_t count = 2; count <= 7; ++count) {
    const Points P = random_points(count, 3, static_cast<unsigned>(count));
    for (double t = 0; t <= 1; t += 1.0 / 16) {
      const auto a = casteljau(P, t), b = bernstein(P, t);
      for (std::size_t c = 0; c < 3; ++c) CHECK(a[c] == Approx(b[c]).margin(1e-13));
    }
    const auto p0 = casteljau(P, 0), p1 = casteljau(P, 1);
    for (std::size_t c = 0; c < 3; ++c) {
      CHECK(p0[c] == P[0][c]);
      CHECK(p1[c] == P[count - 1][c]);
    }
  }
}

TEST_CASE("Splitting at t gives two halves that trace the same curve") {
  const Points P = random_points(4, 2, 42);
  for (double t : {0.25, 0.5, 0.8}) {
    const auto [left, right] = split_bezier(P, t);
    for (double s = 0; s <= 1; s += 0.125) {
      const auto a = casteljau(left, s), b = bernstein(P, t * s);
      const auto c = casteljau(right, s), d = bernstein(P, t + (1 - t) * s);
      for (std::size_t k = 0; k < 2; ++k) {
        CHECK(a[k] == Approx(b[k]).margin(1e-13));
        CHECK(c[k] == Approx(d[k]).margin(1e-13));
      }
    }
  }
  // Halving (0,0),(0,1),(1,1),(1,0) at 1/2 by hand: left (0,0),(0,.5),(.25,.75),(.5,.75).
  const auto [l, r] = split_bezier(points2({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), 0.5);
  const double expect[4][2] = {{0, 0}, {0, 0.5}, {0.25, 0.75}, {0.5, 0.75}};
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t c = 0; c < 2; ++c) CHECK(l[k][c] == expect[k][c]);
  CHECK(r[3][0] == 1);
  CHECK(r[0][0] == 0.5);
}

TEST_CASE("The hodograph is the derivative: d (P_{k+1} - P_k)") {
  const Points P = random_points(5, 2, 9);
  const Points D = bezier_derivative(P);
  REQUIRE(D.size() == 4);
  for (double t = 0; t <= 1; t += 0.1) {
    const auto a = casteljau(D, t), b = bernstein(P, t, true);
    for (std::size_t c = 0; c < 2; ++c) CHECK(a[c] == Approx(b[c]).margin(1e-12));
  }
}

TEST_CASE("Seed 003 §2: P''(0) = 6(P0 - 2P1 + P2), zero when P1 is the midpoint of P0P2") {
  const Points relaxed = points2({{0, 0}, {1, 1}, {2, 2}, {3, 0}});  // docs/figures.md s003-fig03
  const Points bent = points2({{0, 0}, {1, 1}, {2.5, 1}, {3, 0}});
  const BezierSpline a{relaxed}, b{bent};
  std::vector<double> d2(2);
  evaluate(a, 0, 2, d2);
  CHECK(d2[0] == 0);
  CHECK(d2[1] == 0);
  evaluate(b, 0, 2, d2);
  CHECK(d2[0] == Approx(6 * (0 - 2 * 1 + 2.5)));
  CHECK(d2[1] == Approx(6 * (0 - 2 * 1 + 1)));
}

TEST_CASE("Relaxed B-spline pieces meet the A-frame conditions (DD-1 by hand, DD-20)") {
  // DD-1: control points (0,0),(1,0),(1,1),(0,1),(0,0): joints (5/6,1/6), (5/6,5/6), (1/6,5/6).
  const Points B = points2({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}});
  const BezierSpline s = relaxed_bspline_bezier(B);
  REQUIRE(s.pieces() == 4);
  const double joints[5][2] = {{0, 0}, {5.0 / 6, 1.0 / 6}, {5.0 / 6, 5.0 / 6}, {1.0 / 6, 5.0 / 6}, {0, 0}};
  for (std::size_t i = 0; i <= 4; ++i)
    for (std::size_t c = 0; c < 2; ++c) CHECK(s.points[3 * i][c] == Approx(joints[i][c]).epsilon(1e-15));
  CHECK(s.points[1][0] == Approx(1.0 / 3));  // division points at thirds of leg B_0B_1
  CHECK(s.points[2][0] == Approx(2.0 / 3));
  // A-frame at each interior joint: S the midpoint of P_2 Q_1, and both apexes at B_i.
  for (std::size_t i = 1; i < 4; ++i) {
    const auto P1 = s.points[3 * i - 2], P2 = s.points[3 * i - 1], S = s.points[3 * i];
    const auto Q1 = s.points[3 * i + 1], Q2 = s.points[3 * i + 2];
    for (std::size_t c = 0; c < 2; ++c) {
      CHECK(S[c] == Approx((P2[c] + Q1[c]) / 2));
      CHECK(2 * P2[c] - P1[c] == Approx(B[i][c]).margin(1e-15));  // right apex A+
      CHECK(2 * Q1[c] - Q2[c] == Approx(B[i][c]).margin(1e-15));  // left apex A-
    }
  }
  // DD-20: B'(i) = (B_{i+1} - B_{i-1})/2 and B''(i) = B_{i-1} - 2B_i + B_{i+1}; ends relaxed.
  const Points R = random_points(7, 2, 5);
  const BezierSpline r = relaxed_bspline_bezier(R);
  std::vector<double> v(2), w(2);
  for (std::size_t i = 1; i < 6; ++i) {
    evaluate(r, static_cast<double>(i), 1, v);
    evaluate(r, static_cast<double>(i), 2, w);
    for (std::size_t c = 0; c < 2; ++c) {
      CHECK(v[c] == Approx((R[i + 1][c] - R[i - 1][c]) / 2).margin(1e-13));
      CHECK(w[c] == Approx(R[i - 1][c] - 2 * R[i][c] + R[i + 1][c]).margin(1e-13));
    }
    // Continuity across the joint: the left piece at u = 1 against the right one at u = 0.
    evaluate(r, static_cast<double>(i) - 1e-300, 2, v);
    evaluate(r, std::nextafter(static_cast<double>(i), 0.0), 2, v);
    for (std::size_t c = 0; c < 2; ++c) CHECK(v[c] == Approx(w[c]).margin(1e-9));
  }
  evaluate(r, 0, 2, w);
  CHECK(w[0] == Approx(0).margin(1e-13));
  evaluate(r, 6, 2, w);
  CHECK(w[1] == Approx(0).margin(1e-13));
}
