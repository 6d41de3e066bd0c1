// The kernel type: evaluation on half-open unit pieces, exact piece choice at the knots, the
// comparison filters, derivatives and integrals, against values derived here and against the
// spline core's own evaluation of the basis matrices.
#include <catch2/catch.hpp>

#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/kernel.hpp>

#include <cmath>
#include <limits>

using namespace splinefig;

namespace {

constexpr double pi = 3.14159265358979323846;

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

TEST_CASE("basis kernels are the matrix columns of the kernel convention, bit for bit") {
  // k(s) = c_col(s - (h - col)) with col = h - floor(s), h = (n-1)/2, c_i(u) = [u^n .. 1] M column i
  // (basis_segment): the memo's convention, evaluated column by column.
  for (const char* spec : {"catmull-rom", "bspline", "cardinal:a=0.25", "tensioned-bspline:a=0.5", "beta:b1=2,b2=1",
                           "uniform-bspline:degree=2", "uniform-bspline:degree=5", "mitchell-netravali"}) {
    INFO(spec);
    const Basis b = parse_basis(spec);
    const Kernel k = parse_kernel(spec);
    const int n = b.degree, h = (n - 1) / 2;
    CHECK(k.name() == b.spec);
    CHECK(k.support().lo == h - n);
    CHECK(k.support().hi == h + 1);
    CHECK(k.degree() == n);
    for (double s = h - n; s < h + 1; s += 1.0 / 64) {
      const int col = h - static_cast<int>(std::floor(s));
      INFO("s = " << s);
      CHECK(k(s) == basis_segment(b, col, s - (h - col)));
    }
    CHECK(k(h - n - 1.0 / 64) == 0);
    CHECK(k(h + 1) == 0);
  }
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
