// Arc length against an oracle written here: the curve evaluated from the memo's matrices
// entered by hand, measured as a fine polyline with Richardson extrapolation
// (chord error is c h^2 + O(h^4), so (4 L(h/2) - L(h)) / 3 removes the h^2 term).
#include <catch2/catch.hpp>
#include <splinefig/spline/arclength.hpp>

#include <array>
#include <cmath>
#include <vector>

using namespace splinefig;

namespace {

using Mat = std::array<std::array<double, 4>, 4>;
const Mat CR = {{{-0.5, 1.5, -1.5, 0.5}, {1, -2.5, 2, -0.5}, {-0.5, 0, 0.5, 0}, {0, 1, 0, 0}}};
const Mat BS = {{{-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}, {3 / 6.0, -1, 3 / 6.0, 0}, {-3 / 6.0, 0, 3 / 6.0, 0},
                 {1 / 6.0, 4 / 6.0, 1 / 6.0, 0}}};

// Open-ended cubic through 2-D control points: piece i uses p[i..i+3].
struct Oracle {
  Mat m;
  std::vector<std::array<double, 2>> p;

  std::array<double, 2> at(double t) const {
    const size_t pieces = p.size() - 3;
    size_t i = std::min(static_cast<size_t>(std::floor(t)), pieces - 1);
    const double u = t - static_cast<double>(i);
    const double U[4] = {u * u * u, u * u, u, 1};
    std::array<double, 2> x{0, 0};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 2; ++d) x[d] += U[r] * m[r][c] * p[i + c][d];
    return x;
  }
};

// s(t) from polylines on the grids t = j/n and j/(2n) (n steps per piece, so no chord
// straddles a joint), each ending in a partial chord to t, Richardson-combined.
struct OracleLength {
  const Oracle& o;
  int n;
  std::vector<double> coarse, fine;  // cumulative lengths at the grid points

  static std::vector<double> cumulative(const Oracle& o, size_t points, double h) {
    std::vector<double> cum(points, 0.0);
    auto prev = o.at(0);
    for (size_t j = 1; j < points; ++j) {
      const auto q = o.at(static_cast<double>(j) * h);
      cum[j] = cum[j - 1] + std::hypot(q[0] - prev[0], q[1] - prev[1]);
      prev = q;
    }
    return cum;
  }
  OracleLength(const Oracle& o, int steps_per_piece) : o(o), n(steps_per_piece) {
    const size_t pieces = o.p.size() - 3;
    coarse = cumulative(o, pieces * n + 1, 1.0 / n);
    fine = cumulative(o, pieces * 2 * n + 1, 0.5 / n);
  }
  double on(const std::vector<double>& cum, double steps, double t) const {
    const size_t j = std::min(static_cast<size_t>(std::floor(t * steps)), cum.size() - 1);
    const auto a = o.at(static_cast<double>(j) / steps), b = o.at(t);
    return cum[j] + std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  double operator()(double t) const { return (4 * on(fine, 2.0 * n, t) - on(coarse, n, t)) / 3; }
};

Curve curve_of(const Oracle& o, const Basis& b) {
  Points k(2);
  for (const auto& q : o.p) k.push_back(std::vector<double>{q[0], q[1]});
  return make_curve(b, k, Ends::open);
}

// The largest |s(t_k) - k L/(count-1)| / L over the evenly spaced parameters.
double spacing_error(const Oracle& o, const Curve& c, size_t count, int steps) {
  const std::vector<double> t = evenly_spaced_parameters(c, count);
  const OracleLength s(o, steps);
  const double L = s(static_cast<double>(c.segments()));
  double worst = 0;
  for (size_t k = 0; k < count; ++k) {
    const double target = L * static_cast<double>(k) / static_cast<double>(count - 1);
    worst = std::max(worst, std::abs(s(t[k]) - target) / L);
  }
  return worst;
}

}  // namespace

TEST_CASE("Arc length: Catmull-Rom through the arclength figure's knots, spacing to 1e-9") {
  const Oracle o{CR, {{0, 0}, {1, 3}, {2, 3.2}, {6, 0}, {7, 1}}};
  const Curve c = curve_of(o, catmull_rom());
  const ArcLength a = arc_length(c);
  const double L = OracleLength(o, 1 << 14)(2);
  CHECK(std::abs(a.total() - L) / L < 1e-11);
  CHECK(spacing_error(o, c, 40, 1 << 14) < 1e-9);
}

TEST_CASE("Arc length: a triple knot (zero speed at the joint) and an interior cusp") {
  // B-spline with the knot (9,3) three times: a cusp where the velocity vanishes, at t = 2.
  const Oracle triple{BS, {{0, 0}, {3, 6}, {9, 3}, {9, 3}, {9, 3}, {15, 0}, {18, 6}}};
  CHECK(spacing_error(triple, curve_of(triple, bspline()), 25, 1 << 14) < 1e-9);
  // P0 = (-5,0), P1 = (1,1), P2 = (-1,1), P3 = (5,0): by symmetry y'(1/2) = 0 and
  // x'(1/2) = (-P0x - 5P1x + 5P2x + P3x)/8 = 0: the speed vanishes inside the piece.
  const Oracle cusp{BS, {{-5, 0}, {1, 1}, {-1, 1}, {5, 0}}};
  const Curve cc = curve_of(cusp, bspline());
  std::vector<double> v(2);
  evaluate(cc, 0.5, 1, v);
  REQUIRE(std::hypot(v[0], v[1]) < 1e-15);
  CHECK(spacing_error(cusp, cc, 21, 1 << 16) < 1e-9);
}

TEST_CASE("Arc length: an almost-cusp (speed 1e-7 at its minimum) is still spaced to 1e-9") {
  const Oracle o{BS, {{-5 + 1e-6, 0}, {1, 1}, {-1, 1}, {5, 0}, {7, 3}}};
  const Curve c = curve_of(o, bspline());
  std::vector<double> v(2);
  evaluate(c, 0.5, 1, v);
  REQUIRE(std::hypot(v[0], v[1]) < 1e-6);
  // Chords of 2^-20 cut the sharp turn by about h^2 |X''| ~ 1e-12 of the length.
  CHECK(spacing_error(o, c, 17, 1 << 20) < 1e-9);
}

TEST_CASE("Arc length: length_at and parameter_at_length invert each other") {
  const Oracle o{CR, {{0, 0}, {1, 3}, {2, 3.2}, {6, 0}, {7, 1}, {9, -2}}};
  const Curve c = curve_of(o, catmull_rom());
  const ArcLength a = arc_length(c);
  const OracleLength s(o, 1 << 13);
  for (double t : {0.0, 0.1, 0.5, 1.0, 1.75, 2.5, 3.0}) {
    INFO("t = " << t);
    CHECK(parameter_at_length(c, a, length_at(c, a, t)) == Approx(t).margin(1e-12));
    CHECK(length_at(c, a, t) == Approx(s(t)).margin(1e-11 * s(3.0)));
  }
}

TEST_CASE("The memo's polygon method: its spacing error falls as 1/grain^2") {
  const Oracle o{CR, {{0, 0}, {1, 3}, {2, 3.2}, {6, 0}, {7, 1}}};
  const Curve c = curve_of(o, catmull_rom());
  const OracleLength s(o, 1 << 12);
  const double L = s(2);
  auto error = [&](int grain) {
    const std::vector<double> t = polygon_evenly_spaced_parameters(c, grain, 40);
    double worst = 0;
    for (size_t k = 0; k < t.size(); ++k) worst = std::max(worst, std::abs(s(t[k]) - L * k / 39.0) / L);
    return worst;
  };
  const double e8 = error(8), e32 = error(32);
  CHECK(e8 < 1e-2);
  CHECK(e8 > 1e-6);  // a real approximation, unlike the accurate method
  CHECK(e32 < e8 / 8);
  CHECK(polygon_length(c, 1024) == Approx(L).epsilon(1e-5));
  CHECK(polygon_length(c, 1024) < L);  // a chord is never longer than its arc
}

TEST_CASE("Evenly spaced points: first and last are the curve's ends, closed curves close") {
  Points k(3);
  for (auto p : {std::array<double, 3>{0, 0, 0}, {4, 0, 1}, {4, 3, 2}, {0, 3, 1}, {-1, 1, 0}})
    k.push_back(std::vector<double>(p.begin(), p.end()));
  const Curve c = make_curve(beta(1.5, 2.0), k, Ends::closed);
  const std::vector<double> t = evenly_spaced_parameters(c, 11);
  REQUIRE(t.size() == 11);
  CHECK(t.front() == 0);
  CHECK(t.back() == 5);
  const Points p = evaluate_at(c, t);
  for (int d = 0; d < 3; ++d) CHECK(p[10][d] == p[0][d]);
  for (size_t j = 1; j < t.size(); ++j) CHECK(t[j] > t[j - 1]);
}
