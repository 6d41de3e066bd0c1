// The kernel type: evaluation on half-open unit pieces, exact piece choice at the knots, the
// comparison filters, derivatives and integrals, against values derived here (closed forms,
// hand-entered and exactly derived matrices), never against the spline core's own evaluation.
#include <catch2/catch.hpp>

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <numbers>
#include <functional>
#include <limits>

using namespace splinefig;

namespace {

constexpr double pi = std::numbers::pi;

double below(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

}  // namespace

TEST_CASE("box and tent: values, half-open support, integrals") {
  const Kernel box = Kernel::box(), tent = Kernel::tent();
  CHECK(box.name() == "box");
  CHECK(box.support().lo == -0.5);
  CHECK(box.support().hi == 0.5);
  CHECK(box(-0.5) == 1);
  CHECK(box(below(0.5)) == 1);
  CHECK(box(0.5) == 0);
  CHECK(box(below(-0.5)) == 0);
  CHECK(box.integral() == 1);
  CHECK(tent(0) == 1);
  CHECK(tent(0.25) == 0.75);
  CHECK(tent(-0.25) == 0.75);
  CHECK(tent(1) == 0);
  CHECK(tent(-1) == 0);
  CHECK(tent.integral() == 1);
  CHECK(tent.degree() == 1);
  CHECK(Kernel().name() == "box");  // the default
}

TEST_CASE("a piecewise kernel picks its piece by exact comparison at every knot") {
  // Pieces with distinct constants: the value says which piece was used.
  const Kernel k = Kernel::piecewise("steps", -2, {{10}, {20}, {30}, {40}});
  CHECK(k.support().hi == 2);
  for (int p = 0; p < 4; ++p) {
    const double knot = -2 + p;
    CHECK(k(knot) == 10.0 * (p + 1));
    CHECK(k(below(knot)) == (p == 0 ? 0.0 : 10.0 * p));
  }
  CHECK(k(below(2.0)) == 40);
  CHECK(k(2.0) == 0);
  // Just below 1, s - lo rounds up to 3 in double, but the piece is still [0, 1).
  CHECK(below(1.0) - -2.0 == 3.0);
  CHECK(k(below(1.0)) == 30);
  CHECK(k(std::nan("")) == 0);
  // A half-integer lo (the box family) works the same way.
  const Kernel h = Kernel::piecewise("half", -1.5, {{1}, {2}, {3}});
  CHECK(h(-0.5) == 2);
  CHECK(h(below(-0.5)) == 1);
  CHECK(h(0.5) == 3);
}

TEST_CASE("basis kernels against closed forms and hand-entered matrices at every 1/64") {
  // Each kernel against values computed here without the spline library: the published
  // piecewise formulas (Keys' form of the cardinal family, Mitchell and Netravali 1988), the
  // memo's B_a written out, the uniform B-spline as truncated powers in integers, and the
  // Beta-spline matrix for b1 = 2, b2 = 1 derived from Barsky's joint conditions in exact
  // fractions (tests/spline/beta_derivation.py) read through the kernel convention:
  // k(s) = c_3(s + 2) on [-2, -1), c_2(s + 1) on [-1, 0), c_1(s) on [0, 1), c_0(s - 1) on [1, 2],
  // with c_i(u) = [u^3 u^2 u 1] M column i. That kernel is asymmetric, so a mirrored or shifted
  // column order shows.
  const auto cardinal_form = [](double a) {
    return [a](double s) {
      const double x = std::abs(s);
      return x < 1 ? (2 - a) * x * x * x - (3 - a) * x * x + 1 : x < 2 ? -a * x * x * x + 5 * a * x * x - 8 * a * x + 4 * a : 0.0;
    };
  };
  const auto tensioned_form = [](double a) {  // the memo's B_a, columns 1 and 0
    return [a](double s) {
      const double x = std::abs(s);
      return x < 1 ? ((12 - 9 * a) * x * x * x + (12 * a - 18) * x * x + 6 - 2 * a) / 6
                   : x < 2 ? a * (2 - x) * (2 - x) * (2 - x) / 6 : 0.0;
    };
  };
  const auto mitchell_form = [](double B, double C) {
    return [B, C](double s) {
      const double x = std::abs(s);
      if (x < 1) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6;
      if (x < 2)
        return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6;
      return 0.0;
    };
  };
  // N_n(x) = 1/n! sum_{k=0}^{n+1} (-1)^k C(n+1, k) (x - k)_+^n on [0, n + 1], for x = m/64
  // summed exactly in integers (scaled by 64^n) and divided once. The kernel of degree n is
  // N_n(s + n - h), h = (n - 1)/2 (its support is [h - n, h + 1]).
  const auto uniform_form = [](int n) {
    return [n](double s) {
      const int h = (n - 1) / 2;
      const long long m = std::llround((s + n - h) * 64);
      long long sum = 0, binom = 1, fact = 1, scale = 1;
      for (int k = 0; k <= n + 1; ++k) {
        const long long t = m - 64LL * k;
        if (t > 0) {
          long long p = 1;
          for (int e = 0; e < n; ++e) p *= t;
          sum += (k % 2 ? -1 : 1) * binom * p;
        }
        binom = binom * (n + 1 - k) / (k + 1);
      }
      for (int t = 2; t <= n; ++t) fact *= t;
      for (int e = 0; e < n; ++e) scale *= 64;
      return m <= 0 || m >= 64LL * (n + 1) ? 0.0 : double(sum) / (double(fact) * double(scale));
    };
  };
  const double beta21[4][4] = {{-16.0 / 43, 30.0 / 43, -16.0 / 43, 2.0 / 43},
                               {48.0 / 43, -75.0 / 43, 27.0 / 43, 0},
                               {-48.0 / 43, 36.0 / 43, 12.0 / 43, 0},
                               {16.0 / 43, 25.0 / 43, 2.0 / 43, 0}};
  const auto beta_form = [&beta21](double s) {
    if (s < -2 || s >= 2) return 0.0;
    const int col = 1 - static_cast<int>(std::floor(s));  // [-2, -1) -> 3, ..., [1, 2) -> 0
    const double u = s - (1 - col);
    double v = 0;
    for (int r = 0; r < 4; ++r) v = v * u + beta21[r][col];
    return v;
  };
  struct Case {
    const char* spec;
    std::function<double(double)> form;
    const char* name = nullptr;  // the canonical spec, when not `spec` itself
  };
  const Case cases[] = {{"catmull-rom", cardinal_form(0.5)},
                        {"cardinal:a=0.25", cardinal_form(0.25)},
                        {"bspline", tensioned_form(1.0)},
                        {"tensioned-bspline:a=0.5", tensioned_form(0.5)},
                        {"mitchell-netravali", mitchell_form(1.0 / 3, 1.0 / 3),
                         "mitchell-netravali:b=0.3333333333333333,c=0.3333333333333333"},
                        {"beta:b1=2,b2=1", beta_form},
                        {"uniform-bspline:degree=2", uniform_form(2)},
                        {"uniform-bspline:degree=3", uniform_form(3)},
                        {"uniform-bspline:degree=5", uniform_form(5)}};
  for (const Case& c : cases) {
    INFO(c.spec);
    const Kernel k = parse_kernel(c.spec);
    const int n = k.degree(), h = (n - 1) / 2;
    CHECK(k.name() == (c.name ? c.name : c.spec));
    CHECK(k.support().lo == h - n);
    CHECK(k.support().hi == h + 1);
    double worst = 0;
    for (double s = h - n - 1; s <= h + 2; s += 1.0 / 64) {
      INFO("s = " << s);
      CHECK(k(s) == Approx(c.form(s)).margin(2e-15));
      worst = std::max(worst, std::abs(k(s) - c.form(s)));
    }
    INFO("largest difference " << worst);
    CHECK(worst <= 2e-15);
  }
  // The B-spline kernel's knot values by hand: 1/6, 2/3, 1/6.
  const Kernel b = parse_kernel("bspline");
  CHECK(b(-1) == Approx(1.0 / 6).epsilon(1e-15));
  CHECK(b(0) == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(b(1) == Approx(1.0 / 6).epsilon(1e-15));
  // Beta b1 = 2, b2 = 1 at its knots: the constant row, 2/43, 25/43, 16/43 at s = -1, 0, 1.
  const Kernel beta = parse_kernel("beta:b1=2,b2=1");
  CHECK(beta(-1) == Approx(2.0 / 43).epsilon(1e-15));
  CHECK(beta(0) == Approx(25.0 / 43).epsilon(1e-15));
  CHECK(beta(1) == Approx(16.0 / 43).epsilon(1e-15));
}

TEST_CASE("derivatives of a kernel: the right-hand piece at a knot, 0 outside") {
  // Tent: k' = 1 on [-1, 0), -1 on [0, 1).
  const Kernel t = Kernel::tent();
  CHECK(t.derivative(-0.5, 1) == 1);
  CHECK(t.derivative(0, 1) == -1);
  CHECK(t.derivative(0.5, 2) == 0);
  CHECK(t.derivative(3, 1) == 0);
  // B-spline: k(s) = (3|s|^3 - 6s^2 + 4)/6 on |s| < 1, so k''(1/2) = (18/2 - 12)/6 = -1/2.
  CHECK(parse_kernel("bspline").derivative(0.5, 2) == Approx(-0.5).epsilon(1e-15));
  CHECK_THROWS_AS(Kernel::lanczos(3).derivative(0.5, 1), std::logic_error);
}

TEST_CASE("lanczos3 is sinc(s) sinc(s/3) on (-3, 3), even, C1, not a polynomial") {
  const Kernel l = Kernel::lanczos(3);
  CHECK(l.name() == "lanczos3");
  CHECK_FALSE(l.polynomial());
  CHECK(l.pieces().empty());
  CHECK(l.degree() == -1);
  CHECK(l(0) == 1);
  // sinc(1/2) sinc(1/6) = (2/pi) * (sin(pi/6) / (pi/6)) = (2/pi)(3/pi) = 6/pi^2.
  CHECK(l(0.5) == Approx(6 / (pi * pi)).epsilon(1e-15));
  CHECK(l(-0.5) == l(0.5));
  CHECK(std::abs(l(1)) < 1e-16);
  CHECK(l(3) == 0);
  CHECK(l(-3.5) == 0);
  CHECK(continuity(l) == 1);
  CHECK_THROWS_AS(Kernel::lanczos(0), std::invalid_argument);
}

TEST_CASE("bad piecewise kernels are refused with a message naming them") {
  CHECK_THROWS_WITH(Kernel::piecewise("k1", 0, {}), Catch::Contains("kernel 'k1': no pieces"));
  CHECK_THROWS_WITH(Kernel::piecewise("k2", 0, {{1}, {}}), Catch::Contains("kernel 'k2': a piece without coefficients"));
  CHECK_THROWS_WITH(Kernel::piecewise("k3", INFINITY, {{1}}), Catch::Contains("kernel 'k3': lo is not finite"));
  CHECK_THROWS_WITH(Kernel::piecewise("k4", 0, {{1, NAN}}), Catch::Contains("kernel 'k4': a coefficient is not finite"));
}

TEST_CASE("continuity: one tolerance, relative to the derivative's size at the knots") {
  // A tent scaled by 1e-30 is still C0 (the tolerance is relative), and a jump of 1e-6 of the
  // value counts, while a rounding-sized one (1e-15 of it) does not.
  CHECK(continuity(Kernel::piecewise("tiny", -1, {{0, 1e-30}, {1e-30, -1e-30}})) == 0);
  CHECK(continuity(Kernel::piecewise("jump", -1, {{0, 1}, {1 + 1e-6, -1 - 1e-6}})) == -1);
  CHECK(continuity(Kernel::piecewise("round", -1, {{0, 1}, {1 + 1e-15, -1 - 1e-15}})) == 0);
  // Jumps at the knots: the box jumps by +1 at -1/2 and -1 at 1/2.
  const auto j = jumps(Kernel::box(), 0);
  REQUIRE(j.size() == 2);
  CHECK(j[0] == 1);
  CHECK(j[1] == -1);
}
