// Continuously shaped Beta-splines (Barsky and Beatty 1983): equal per-knot values give the
// uniform Beta-spline of the core (the memo's matrix); varying values stay G2 at every joint;
// the exact u-derivatives agree with difference quotients; locality; validation.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/local_beta.hpp>

#include <cmath>
#include <vector>

using namespace splinefig;

namespace {

Points zigzag() {  // docs/figures.md's bias/tension polygon
  Points p(2);
  for (double x = 0; x <= 6; ++x) p.push_back(std::vector<double>{x, std::fmod(x, 2) == 1 ? 2.0 : 0.0});
  return p;
}

std::vector<double> at(const Points& k, const std::vector<ShapeParameters>& b, std::size_t i, double u, int d) {
  std::vector<double> out(static_cast<std::size_t>(k.dim));
  local_beta_point(k, b, i, u, d, out);
  return out;
}

double norm(const std::vector<double>& v) { return std::hypot(v[0], v[1]); }

}  // namespace

TEST_CASE("Equal per-knot values give the uniform Beta-spline B_{b1,b2}") {
  const Points k = zigzag();
  for (auto [b1, b2] : {std::pair{1.0, 0.0}, {2.0, 0.0}, {0.5, 10.0}, {3.0, 150.0}}) {
    const std::vector<ShapeParameters> betas(k.size(), ShapeParameters{b1, b2});
    const Curve c = make_curve(beta(b1, b2), k, Ends::open);
    for (int d = 0; d <= 2; ++d) {
      const Points a = local_beta_curve(k, betas, 8, d), b = sample(c, 8, d);
      REQUIRE(a.size() == b.size());
      INFO("b1 " << b1 << " b2 " << b2 << " derivative " << d);
      for (std::size_t i = 0; i < a.coords.size(); ++i) CHECK(a.coords[i] == Approx(b.coords[i]).margin(1e-11));
    }
  }
}

TEST_CASE("Varying bias and tension stay G2: unit tangent and curvature vector continuous") {
  const Points k = zigzag();
  // docs/figures.md local-betas: bias 5 and 10 at the 3rd and 4th vertex; tension 25 and -5.
  std::vector<ShapeParameters> bias(k.size()), tension(k.size());
  bias[2].b1 = 5, bias[3].b1 = 10;
  tension[2].b2 = 25, tension[3].b2 = -5;
  for (const auto& betas : {bias, tension}) {
    for (std::size_t i = 1; i + 3 < k.size(); ++i) {
      const auto p0 = at(k, betas, i, 1, 0), p1 = at(k, betas, i + 1, 0, 0);
      const auto v0 = at(k, betas, i, 1, 1), v1 = at(k, betas, i + 1, 0, 1);
      const auto a0 = at(k, betas, i, 1, 2), a1 = at(k, betas, i + 1, 0, 2);
      // Position, unit tangent, and curvature vector (a - (a.T)T)/|v|^2 on both sides.
      std::vector<double> t0{v0[0] / norm(v0), v0[1] / norm(v0)}, t1{v1[0] / norm(v1), v1[1] / norm(v1)};
      auto kappa = [](const std::vector<double>& v, const std::vector<double>& a, const std::vector<double>& t) {
        const double at = a[0] * t[0] + a[1] * t[1], s2 = v[0] * v[0] + v[1] * v[1];
        return std::vector<double>{(a[0] - at * t[0]) / s2, (a[1] - at * t[1]) / s2};
      };
      const auto k0 = kappa(v0, a0, t0), k1 = kappa(v1, a1, t1);
      INFO("joint " << i + 1);
      for (std::size_t c = 0; c < 2; ++c) {
        CHECK(p0[c] == Approx(p1[c]).margin(1e-13));
        CHECK(t0[c] == Approx(t1[c]).margin(1e-12));
        CHECK(k0[c] == Approx(k1[c]).margin(1e-11));
      }
      // The Beta-constraints with the joint's own values: v1 = b1 v0, a1 = b1^2 a0 + b2 v0.
      const ShapeParameters s = betas[i + 1];
      for (std::size_t c = 0; c < 2; ++c) {
        CHECK(v1[c] == Approx(s.b1 * v0[c]).margin(1e-12));
        CHECK(a1[c] == Approx(s.b1 * s.b1 * a0[c] + s.b2 * v0[c]).margin(1e-10));
      }
    }
  }
  // Not C1 at the joint with bias 5: the parametric velocity jumps (by the factor b1).
  const auto v0 = at(k, bias, 1, 1, 1), v1 = at(k, bias, 2, 0, 1);
  CHECK(norm(v1) == Approx(5 * norm(v0)));
}

TEST_CASE("Exact u-derivatives agree with difference quotients inside a piece") {
  const Points k = zigzag();
  std::vector<ShapeParameters> betas(k.size());
  betas[2] = {5, 25}, betas[3] = {0.3, -2};
  const double h = 1e-4;
  for (std::size_t i = 1; i <= 3; ++i)
    for (double u = 0.1; u < 0.95; u += 0.2) {
      const auto lo = at(k, betas, i, u - h, 0), mid = at(k, betas, i, u, 0), hi = at(k, betas, i, u + h, 0);
      const auto d1 = at(k, betas, i, u, 1), d2 = at(k, betas, i, u, 2);
      for (std::size_t c = 0; c < 2; ++c) {
        CHECK(d1[c] == Approx((hi[c] - lo[c]) / (2 * h)).epsilon(1e-6).margin(1e-6));
        CHECK(d2[c] == Approx((hi[c] - 2 * mid[c] + lo[c]) / (h * h)).epsilon(1e-4).margin(1e-4));
      }
    }
}

TEST_CASE("Changing the values at one knot changes only the two pieces that meet there") {
  const Points k = zigzag();
  std::vector<ShapeParameters> base(k.size()), changed(k.size());
  changed[3] = {4, 30};
  for (std::size_t i = 1; i + 2 < k.size(); ++i)
    for (double u = 0; u <= 1; u += 0.25) {
      const auto a = at(k, base, i, u, 0), b = at(k, changed, i, u, 0);
      const bool touched = i == 2 || i == 3;
      const bool differs = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) > 1e-12;
      INFO("piece " << i << " u " << u);
      if (!touched) CHECK_FALSE(differs);
      if (touched && u > 0 && u < 1) CHECK(differs);
    }
}

TEST_CASE("Local betas follow make_curve's end modes, bad values are refused with their knots") {
  const Points k = zigzag();
  std::vector<ShapeParameters> betas(k.size());
  betas[1] = {2, 3};
  for (Ends e : {Ends::open, Ends::doubled, Ends::closed}) {
    const Curve c = make_curve(beta(1, 0), k, e);
    CHECK(sample_local_betas(c, betas, 4).size() == sample(c, 4).size());
  }
  const Curve c = make_curve(beta(1, 0), k, Ends::open);
  CHECK_THROWS_WITH(sample_local_betas(c, std::vector<ShapeParameters>(3), 4), Catch::Contains("3 (b1, b2) pairs for 7"));
  betas[4] = {-1, 0};  // d = 0 at b1 = -1, b2 = 0
  CHECK_THROWS_WITH(sample_local_betas(c, betas, 4), Catch::Contains("between knots 3 and 4"));
  betas[4] = {1, std::nan("")};
  CHECK_THROWS_WITH(sample_local_betas(c, betas, 4), Catch::Contains("knot 4"));
  CHECK(quintic_blend(0.5) == 0.5);
  CHECK(quintic_blend(0, 1) == 0);
  CHECK(quintic_blend(1, 2) == 0);
}
