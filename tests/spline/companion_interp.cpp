// Interpolation through data by the 1-4-1 systems (seed 003 §5, §8, §9), pinned to the seed's
// worked answers and to an independent natural/clamped/periodic spline solver written here
// (second-derivative "moment" equations, dense Gaussian elimination with partial pivoting).
#include <catch2/catch.hpp>
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

std::vector<double> at(const Interpolant& s, double t, int derivative = 0) {
  std::vector<double> out(static_cast<std::size_t>(s.data.dim));
  evaluate(s, t, derivative, out);
  return out;
}

// Dense Gaussian elimination with partial pivoting: solves A x = b (A row-major, n x n).
std::vector<double> gauss(std::vector<double> A, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t piv = k;
    for (std::size_t r = k + 1; r < n; ++r)
      if (std::abs(A[r * n + k]) > std::abs(A[piv * n + k])) piv = r;
    for (std::size_t c = 0; c < n; ++c) std::swap(A[k * n + c], A[piv * n + c]);
    std::swap(b[k], b[piv]);
    for (std::size_t r = k + 1; r < n; ++r) {
      const double f = A[r * n + k] / A[k * n + k];
      for (std::size_t c = k; c < n; ++c) A[r * n + c] -= f * A[k * n + c];
      b[r] -= f * b[k];
    }
  }
  std::vector<double> x(n);
  for (std::size_t k = n; k-- > 0;) {
    double s = b[k];
    for (std::size_t c = k + 1; c < n; ++c) s -= A[k * n + c] * x[c];
    x[k] = s / A[k * n + k];
  }
  return x;
}

// The textbook cubic spline on knots 0..n with unit spacing, one coordinate y, in terms of its
// second derivatives M_i: on [i, i+1]
//   S(t) = M_i (i+1-t)^3/6 + M_{i+1} (t-i)^3/6 + (y_i - M_i/6)(i+1-t) + (y_{i+1} - M_{i+1}/6)(t-i),
// continuity of S' gives M_{i-1} + 4M_i + M_{i+1} = 6(y_{i+1} - 2y_i + y_{i-1}); the ends:
// natural M_0 = M_n = 0; clamped 2M_0 + M_1 = 6(y_1 - y_0 - v), M_{n-1} + 2M_n = 6(w - y_n + y_{n-1});
// periodic: the equations wrap around (y_n = y_0, M_n = M_0).
enum class Oracle { natural, clamped, periodic };
struct MomentSpline {
  std::vector<double> y, M;
  double operator()(double t) const {
    const std::size_t n = y.size() - 1;
    std::size_t i = std::min(static_cast<std::size_t>(std::max(0.0, std::floor(t))), n - 1);
    const double a = static_cast<double>(i) + 1 - t, b = t - static_cast<double>(i);
    return M[i] * a * a * a / 6 + M[i + 1] * b * b * b / 6 + (y[i] - M[i] / 6) * a + (y[i + 1] - M[i + 1] / 6) * b;
  }
};
MomentSpline moment_spline(const std::vector<double>& y, Oracle kind, double v = 0, double w = 0) {
  const std::size_t n = y.size() - 1;
  const std::size_t m = kind == Oracle::periodic ? n : n + 1;
  std::vector<double> A(m * m, 0.0), rhs(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    const bool first = i == 0, last = i == n;
    if (kind != Oracle::periodic && (first || last)) {
      if (kind == Oracle::natural) {
        A[i * m + i] = 1;
      } else if (first) {
        A[0] = 2, A[1] = 1, rhs[0] = 6 * (y[1] - y[0] - v);
      } else {
        A[i * m + i - 1] = 1, A[i * m + i] = 2, rhs[i] = 6 * (w - y[n] + y[n - 1]);
      }
      continue;
    }
    const bool cyc = kind == Oracle::periodic;
    const std::size_t im = cyc ? (i + n - 1) % n : i - 1, ip = cyc ? (i + 1) % n : i + 1;
    A[i * m + im] += 1, A[i * m + i] += 4, A[i * m + ip] += 1;
    const double ym = y[(i + n - 1) % n], yp = y[i + 1];
    rhs[i] = 6 * (yp - 2 * y[i] + (kind == Oracle::periodic ? ym : y[i - 1]));
  }
  std::vector<double> M = gauss(A, rhs);
  if (kind == Oracle::periodic) M.push_back(M[0]);
  return {y, M};
}

Points random_points(std::size_t count, int dim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-10, 10);
  Points p(dim, count);
  for (double& x : p.coords) x = d(rng);
  return p;
}

std::vector<double> coordinate(const Points& p, int c) {
  std::vector<double> y;
  for (std::size_t i = 0; i < p.size(); ++i) y.push_back(p[i][static_cast<std::size_t>(c)]);
  return y;
}

}  // namespace

TEST_CASE("Seed 003 worked problem: relaxed B-spline control points and Bezier points") {
  const Points S = points2({{1, -1}, {-1, 2}, {1, 4}, {4, 3}, {7, 5}});
  const Interpolant s = interpolate_relaxed(S);
  const double B[5][2] = {{1, -1}, {-2, 2}, {1, 5}, {4, 2}, {7, 5}};
  REQUIRE(s.control.size() == 5);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t c = 0; c < 2; ++c) CHECK(s.control[i][c] == Approx(B[i][c]).margin(1e-14));
  // The seed's four Bezier pieces.
  const double bez[4][4][2] = {{{1, -1}, {0, 0}, {-1, 1}, {-1, 2}},
                               {{-1, 2}, {-1, 3}, {0, 4}, {1, 4}},
                               {{1, 4}, {2, 4}, {3, 3}, {4, 3}},
                               {{4, 3}, {5, 3}, {6, 4}, {7, 5}}};
  const BezierSpline b = bezier_pieces(s);
  REQUIRE(b.pieces() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const Points piece = b.piece(i);
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t c = 0; c < 2; ++c) CHECK(piece[k][c] == Approx(bez[i][k][c]).margin(1e-14));
  }
  // Design view (seed 003 §4): the relaxed B-spline of those control points has the same pieces.
  const BezierSpline d = relaxed_bspline_bezier(s.control);
  for (std::size_t k = 0; k < d.points.coords.size(); ++k)
    CHECK(d.points.coords[k] == Approx(b.points.coords[k]).margin(1e-14));
}

TEST_CASE("DD-4(d): relaxed n = 2 gives P(1/2) = (13 S_0 + 22 S_1 - 3 S_2)/32") {
  Points S(3);
  S.push_back(std::vector<double>{5, 2, -1});
  S.push_back(std::vector<double>{3, 7, 4});
  S.push_back(std::vector<double>{9, 1, 0.5});
  const auto p = at(interpolate_relaxed(S), 0.5);
  for (std::size_t c = 0; c < 3; ++c)
    CHECK(p[c] == Approx((13 * S[0][c] + 22 * S[1][c] - 3 * S[2][c]) / 32).margin(1e-14));
  // DD-4(a): B_1 = (6S_1 - S_0 - S_2)/4.
  const Interpolant s = interpolate_relaxed(S);
  for (std::size_t c = 0; c < 3; ++c) CHECK(s.control[1][c] == Approx((6 * S[1][c] - S[0][c] - S[2][c]) / 4));
}

TEST_CASE("Relaxed interpolation is the natural cubic spline") {
  for (std::size_t count : {2u, 3u, 4u, 7u, 25u}) {
    const Points S = random_points(count, 3, 100 + static_cast<unsigned>(count));
    const Interpolant s = interpolate_relaxed(S);
    const double n = static_cast<double>(count - 1);
    for (int c = 0; c < 3; ++c) {
      const MomentSpline o = moment_spline(coordinate(S, c), Oracle::natural);
      for (double t = 0; t <= n; t += 0.0625) {
        INFO("count " << count << " coord " << c << " t " << t);
        CHECK(at(s, t)[static_cast<std::size_t>(c)] == Approx(o(t)).margin(1e-12));
      }
    }
    CHECK(at(s, 0, 2)[0] == Approx(0).margin(1e-12));  // relaxed: P'' = 0 at both ends
    CHECK(at(s, n, 2)[1] == Approx(0).margin(1e-12));
  }
}

TEST_CASE("Clamped interpolation matches the clamped cubic spline and its end velocities") {
  for (std::size_t count : {2u, 3u, 6u, 19u}) {
    const Points S = random_points(count, 2, 200 + static_cast<unsigned>(count));
    const std::vector<double> v{1.5, -2}, w{-0.25, 3};
    const Interpolant s = interpolate_clamped(S, v, w);
    const double n = static_cast<double>(count - 1);
    for (int c = 0; c < 2; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      const MomentSpline o = moment_spline(coordinate(S, c), Oracle::clamped, v[cc], w[cc]);
      for (double t = 0; t <= n; t += 0.125) CHECK(at(s, t)[cc] == Approx(o(t)).margin(1e-12));
      CHECK(at(s, 0, 1)[cc] == Approx(v[cc]).margin(1e-12));
      CHECK(at(s, n, 1)[cc] == Approx(w[cc]).margin(1e-12));
    }
  }
}

TEST_CASE("DD-13: clamped through (0,0),(1,1),(2,2) with P'(0) = P'(2) = (1,0), by the seed's inverse") {
  const Points S = points2({{0, 0}, {1, 1}, {2, 2}});
  const std::vector<double> v{1, 0}, w{1, 0};
  const Interpolant s = interpolate_clamped(S, v, w);
  const double inv[3][3] = {{7, -2, 1}, {-2, 4, -2}, {1, -2, 7}};  // times 1/12
  for (std::size_t c = 0; c < 2; ++c) {
    const double rhs[3] = {3 * S[0][c] + v[c], 6 * S[1][c], 3 * S[2][c] - w[c]};
    for (std::size_t i = 0; i < 3; ++i) {
      const double b = (inv[i][0] * rhs[0] + inv[i][1] * rhs[1] + inv[i][2] * rhs[2]) / 12;
      CHECK(s.control[i][c] == Approx(b).margin(1e-14));
    }
  }
}

TEST_CASE("Periodic interpolation matches the periodic cubic spline and closes C2") {
  for (std::size_t distinct : {2u, 3u, 5u, 12u}) {
    Points S = random_points(distinct, 2, 300 + static_cast<unsigned>(distinct));
    S.push_back(std::vector<double>{S[0][0], S[0][1]});
    const Interpolant s = interpolate_periodic(S);
    const double n = static_cast<double>(distinct);
    for (int c = 0; c < 2; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      const MomentSpline o = moment_spline(coordinate(S, c), Oracle::periodic);
      for (double t = 0; t <= n; t += 0.125) CHECK(at(s, t)[cc] == Approx(o(t)).margin(1e-12));
      for (int d = 1; d <= 2; ++d) CHECK(at(s, 0, d)[cc] == Approx(at(s, n, d)[cc]).margin(1e-12));
    }
    CHECK(s.control[0][0] == s.control[distinct][0]);  // B_n = B_0
  }
}

TEST_CASE("Periodic interpolation of DD-10's box joints gives back the box corners") {
  // DD-10: the closed B-spline of the corners (1,1), (-1,1), (-1,-1), (1,-1) has joints
  // S_i = (B_{i-1} + 4B_i + B_{i+1})/6 = 2/3 B_i.
  const double k = 2.0 / 3;
  const Points S = points2({{k, k}, {-k, k}, {-k, -k}, {k, -k}, {k, k}});
  const Interpolant s = interpolate_periodic(S);
  const double B[5][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}, {1, 1}};
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t c = 0; c < 2; ++c) CHECK(s.control[i][c] == Approx(B[i][c]).margin(1e-14));
}

TEST_CASE("The 1-4-1 solve is accurate for long inputs (residual of every equation)") {
  const std::size_t count = 50001;
  const Points S = random_points(count, 3, 7);
  const Interpolant s = interpolate_relaxed(S);
  double worst = 0;
  for (std::size_t i = 1; i + 1 < count; ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const double joint = (s.control[i - 1][c] + 4 * s.control[i][c] + s.control[i + 1][c]) / 6;
      worst = std::max(worst, std::abs(joint - S[i][c]));
    }
  CHECK(worst < 1e-13);
  const Points P = sample(s, 4);
  CHECK(P.size() == (count - 1) * 4 + 1);
  for (std::size_t i = 0; i < count; i += 9973)
    for (std::size_t c = 0; c < 3; ++c) CHECK(P[4 * i][c] == S[i][c]);
}

TEST_CASE("Seed 003 §8: relaxed basis functions are 1 at their knot, 0 at the others, DD-5") {
  const Interpolant f = relaxed_basis(4);
  REQUIRE(f.data.dim == 5);
  for (int j = 0; j <= 4; ++j) {
    const auto v = at(f, j);
    for (std::size_t k = 0; k < 5; ++k) CHECK(v[k] == Approx(k == static_cast<std::size_t>(j) ? 1 : 0).margin(1e-15));
  }
  // They reproduce any relaxed interpolant: P(t) = sum f_k(t) S_k.
  const Points S = random_points(5, 2, 11);
  const Interpolant s = interpolate_relaxed(S);
  for (double t = 0; t <= 4; t += 0.1) {
    const auto fk = at(f, t);
    const auto p = at(s, t);
    for (std::size_t c = 0; c < 2; ++c) {
      double sum = 0;
      for (std::size_t k = 0; k < 5; ++k) sum += fk[k] * S[k][c];
      CHECK(p[c] == Approx(sum).margin(1e-12));
    }
  }
  // DD-5 (from DD-4(d)): for n = 2, (f_0, f_1, f_2)(1/2) = (13, 22, -3)/32.
  const auto h = at(relaxed_basis(2), 0.5);
  CHECK(h[0] == Approx(13.0 / 32).margin(1e-15));
  CHECK(h[1] == Approx(22.0 / 32).margin(1e-15));
  CHECK(h[2] == Approx(-3.0 / 32).margin(1e-15));
}

TEST_CASE("Interpolation rejects too few points and an open periodic polygon") {
  const Points one = points2({{1, 2}});
  CHECK_THROWS_WITH(interpolate_relaxed(one), Catch::Contains("at least 2"));
  const std::vector<double> v{0, 0};
  CHECK_THROWS_WITH(interpolate_clamped(one, v, v), Catch::Contains("at least 2"));
  CHECK_THROWS_WITH(interpolate_periodic(points2({{1, 2}, {1, 2}})), Catch::Contains("at least 3"));
  CHECK_THROWS_WITH(interpolate_periodic(points2({{1, 2}, {3, 4}, {5, 6}})), Catch::Contains("repeat the first"));
  CHECK_THROWS_WITH(interpolate_clamped(points2({{1, 2}, {3, 4}}), std::vector<double>{1}, v),
                    Catch::Contains("2 coordinates"));
  // Two points: the straight segment.
  const Interpolant line = interpolate_relaxed(points2({{0, 0}, {3, 6}}));
  CHECK(at(line, 0.5)[0] == Approx(1.5));
  CHECK(at(line, 0.5)[1] == Approx(3));
}
