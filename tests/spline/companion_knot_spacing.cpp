// Catmull-Rom with uniform, chordal and centripetal knot spacing, against Barry and Goldman's
// pyramid written here, the core's uniform matrix, and the no-cusp / no-self-intersection
// property of centripetal pieces (Yuksel, Schaefer, Keyser 2011) on seeded adversarial data.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/knot_spacing.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace splinefig;

namespace {

using P2 = std::array<double, 2>;

Points from(const std::vector<P2>& ps) {
  Points p(2);
  for (const auto& q : ps) p.push_back(q);
  return p;
}

P2 lerp(P2 a, P2 b, double ta, double tb, double t) {
  const double w = (t - ta) / (tb - ta);
  return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1])};
}

// Barry-Goldman: three levels of linear interpolation over t0..t3, evaluated at t in [t1, t2].
P2 pyramid(const std::array<P2, 4>& p, const std::array<double, 4>& t, double x) {
  const P2 a1 = lerp(p[0], p[1], t[0], t[1], x), a2 = lerp(p[1], p[2], t[1], t[2], x),
           a3 = lerp(p[2], p[3], t[2], t[3], x);
  const P2 b1 = lerp(a1, a2, t[0], t[2], x), b2 = lerp(a2, a3, t[1], t[3], x);
  return lerp(b1, b2, t[1], t[2], x);
}

std::array<double, 4> params(const std::array<P2, 4>& p, double alpha) {
  std::array<double, 4> t{0, 0, 0, 0};
  for (int j = 1; j < 4; ++j)
    t[j] = t[j - 1] + std::pow(std::hypot(p[j][0] - p[j - 1][0], p[j][1] - p[j - 1][1]), alpha);
  return t;
}

P2 piece(const std::array<P2, 4>& p, double alpha, double u, int derivative = 0) {
  const Points k = from({p[0], p[1], p[2], p[3]});
  const std::vector<double> tau = knot_parameters(k, alpha);
  P2 out{};
  spaced_catmull_rom(k, tau, 1, u, derivative, out);
  return out;
}

// Does the polyline through q cross itself (non-adjacent segments properly intersecting)?
bool self_intersects(const std::vector<P2>& q) {
  auto orient = [](P2 a, P2 b, P2 c) { return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]); };
  for (std::size_t i = 0; i + 1 < q.size(); ++i)
    for (std::size_t j = i + 2; j + 1 < q.size(); ++j) {
      const double d1 = orient(q[i], q[i + 1], q[j]), d2 = orient(q[i], q[i + 1], q[j + 1]);
      const double d3 = orient(q[j], q[j + 1], q[i]), d4 = orient(q[j], q[j + 1], q[i + 1]);
      if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    }
  return false;
}

// A cusp reverses the direction of motion: consecutive velocities point against each other.
bool has_reversal(const std::array<P2, 4>& p, double alpha, int samples) {
  P2 prev = piece(p, alpha, 0, 1);
  for (int k = 1; k <= samples; ++k) {
    const P2 v = piece(p, alpha, static_cast<double>(k) / samples, 1);
    if (v[0] * prev[0] + v[1] * prev[1] < 0) return true;
    prev = v;
  }
  return false;
}

// Adversarial pieces: a short middle chord between far-away outer knots pointing every way,
// the configuration that makes uniform Catmull-Rom loop or cusp.
std::array<P2, 4> adversarial(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), logscale(-3, 1), far(1, 10);
  const double a = angle(rng), r = std::pow(10.0, logscale(rng));
  const double b = angle(rng), c = angle(rng);
  return {P2{far(rng) * std::cos(b), far(rng) * std::sin(b)}, P2{0, 0}, P2{r * std::cos(a), r * std::sin(a)},
          P2{r * std::cos(a) + far(rng) * std::cos(c), r * std::sin(a) + far(rng) * std::sin(c)}};
}

}  // namespace

TEST_CASE("Uniform spacing (alpha = 0) is the memo's Catmull-Rom matrix") {
  const Points k = from({{0, 0}, {1, 3}, {2, 3.2}, {6, 0}, {7, 1}, {9, -2}});
  for (int d = 0; d <= 2; ++d) {
    const Points a = spaced_catmull_rom_curve(k, 0.0, 8, d);
    const Points b = sample(make_curve(catmull_rom(), k, Ends::open), 8, d);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.coords.size(); ++i) CHECK(a.coords[i] == Approx(b.coords[i]).margin(1e-12));
  }
}

TEST_CASE("Chordal and centripetal pieces equal Barry and Goldman's pyramid") {
  std::mt19937 rng(1983);
  std::uniform_real_distribution<double> d(-5, 5);
  for (int trial = 0; trial < 50; ++trial) {
    const std::array<P2, 4> p{P2{d(rng), d(rng)}, P2{d(rng), d(rng)}, P2{d(rng), d(rng)}, P2{d(rng), d(rng)}};
    for (double alpha : {0.0, 0.5, 1.0}) {
      const auto t = params(p, alpha);
      for (double u = 0; u <= 1; u += 0.125) {
        const P2 a = piece(p, alpha, u), b = pyramid(p, t, t[1] + u * (t[2] - t[1]));
        CHECK(a[0] == Approx(b[0]).margin(1e-12));
        CHECK(a[1] == Approx(b[1]).margin(1e-12));
        // dX/dtau against a central difference of the pyramid.
        const double h = 1e-5 * (t[2] - t[1]), x = t[1] + (0.05 + 0.9 * u) * (t[2] - t[1]);
        const P2 v = piece(p, alpha, 0.05 + 0.9 * u, 1), lo = pyramid(p, t, x - h), hi = pyramid(p, t, x + h);
        CHECK(v[0] == Approx((hi[0] - lo[0]) / (2 * h)).epsilon(1e-5).margin(1e-6));
        CHECK(v[1] == Approx((hi[1] - lo[1]) / (2 * h)).epsilon(1e-5).margin(1e-6));
      }
    }
  }
}

TEST_CASE("Spaced curves interpolate the knots and are C1 in the spaced parameter") {
  const Points k = from({{0, 0}, {0.1, 2}, {0.2, 2.05}, {6, 0}, {7, 1}, {7.5, 4}, {2, 5}});
  for (KnotSpacing s : {KnotSpacing::uniform, KnotSpacing::chordal, KnotSpacing::centripetal}) {
    const double alpha = spacing_exponent(s);
    const auto tau = knot_parameters(k, alpha);
    for (std::size_t i = 1; i + 3 < k.size(); ++i) {
      P2 end{}, start{}, v_end{}, v_start{};
      spaced_catmull_rom(k, tau, i, 1.0, 0, end);
      spaced_catmull_rom(k, tau, i + 1, 0.0, 0, start);
      spaced_catmull_rom(k, tau, i, 1.0, 1, v_end);
      spaced_catmull_rom(k, tau, i + 1, 0.0, 1, v_start);
      for (std::size_t c = 0; c < 2; ++c) {
        CHECK(end[c] == Approx(k[i + 1][c]).margin(1e-14));
        CHECK(start[c] == Approx(k[i + 1][c]).margin(1e-14));
        CHECK(v_end[c] == Approx(v_start[c]).margin(1e-12));
      }
    }
  }
  CHECK(parse_knot_spacing("centripetal") == KnotSpacing::centripetal);
  CHECK(!parse_knot_spacing("Chordal"));
}

TEST_CASE("Centripetal pieces never cusp or cross themselves, uniform ones do on the same data") {
  std::mt19937 rng(20110401);
  int uniform_bad = 0, chordal_bad = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto p = adversarial(rng);
    auto polyline = [&](double alpha) {
      std::vector<P2> q;
      for (int k = 0; k <= 120; ++k) q.push_back(piece(p, alpha, k / 120.0));
      return q;
    };
    INFO("trial " << trial);
    CHECK_FALSE(self_intersects(polyline(0.5)));
    CHECK_FALSE(has_reversal(p, 0.5, 400));
    uniform_bad += self_intersects(polyline(0.0)) || has_reversal(p, 0.0, 400);
    chordal_bad += self_intersects(polyline(1.0)) || has_reversal(p, 1.0, 400);
  }
  // The data is adversarial indeed: uniform pieces loop or cusp on it (54 of the 300 here;
  // chordal ones none).
  INFO("uniform pieces with a loop or cusp: " << uniform_bad << " of 300, chordal: " << chordal_bad);
  CHECK(uniform_bad > 25);
}

TEST_CASE("Coincident knots give repeated parameters, not NaN") {
  const Points k = from({{0, 0}, {0, 0}, {1, 1}, {1, 1}, {2, 0}, {2, 0}});
  for (double alpha : {0.5, 1.0}) {
    const Points a = spaced_catmull_rom_curve(k, alpha, 4, 0);
    for (double x : a.coords) CHECK(std::isfinite(x));
    CHECK(a[0][0] == 0);                 // piece 1 starts at the doubled first knot
    CHECK(a[4][0] == 1);                 // piece 2 (between the doubled (1,1)) stays there
    CHECK(a[6][0] == 1);
    const Points v = spaced_catmull_rom_curve(k, alpha, 4, 1);
    CHECK(v[0][0] == 0);  // doubled end knot: zero end velocity
  }
}

TEST_CASE("sample_spaced follows make_curve's end modes and refuses other bases") {
  const Points k = from({{0, 0}, {1, 2}, {3, 2.5}, {4, 0.5}, {6, 1}, {7, 3}});
  for (Ends e : {Ends::open, Ends::doubled, Ends::closed}) {
    const Curve c = make_curve(catmull_rom(), k, e);
    const Points s = sample_spaced(c, 0.5, 5);
    CHECK(s.size() == sample(c, 5).size());
    if (e == Ends::closed) {
      CHECK(s[0][0] == s[s.size() - 1][0]);
      CHECK(s[0][1] == s[s.size() - 1][1]);
    }
  }
  CHECK_THROWS_WITH(sample_spaced(make_curve(bspline(), k, Ends::open), 0.5, 4), Catch::Contains("Catmull-Rom"));
}
