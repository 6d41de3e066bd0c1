// The canvas `filter` key: spline kernels become the renderer's pixel filters. A half-plane
// edge seen through the filter has the value of the kernel's tail integral, which the test
// computes from the spline core's kernel() by Simpson's rule (and, for the B-spline, by hand).
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/spline/basis.hpp>

#include <cmath>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

// Black rectangle x in [10, 30], y in [0, 40] on white, 40 x 40, through `filter`.
Image edge_image(const std::string& filter) {
  FigureSpec spec = parse_spec("[canvas]\nwidth = 40\nheight = 40\nfilter = \"" + filter +
                                   "\"\n[[polygon]]\npoints = [[10, -10], [30, -10], [30, 50], [10, 50]]\n"
                                   "color = \"#000000\"\n",
                               "filter.toml");
  return render_figure(spec, {1, 1}).image;
}

// integral of k over [a, b] by composite Simpson's rule on unit pieces (the kernel is a
// polynomial on each, so this is exact to rounding with 2 sub-steps).
double integral(const Basis& b, double a, double c) {
  double total = 0;
  const int n = 2000;
  const double h = (c - a) / n;
  for (int i = 0; i < n; ++i) {
    double x0 = a + i * h;
    total += h / 6 * (kernel(b, x0) + 4 * kernel(b, x0 + h / 2) + kernel(b, x0 + h));
  }
  return total;
}

}  // namespace

TEST_CASE("canvas filter bspline: an edge is the kernel's tail integral") {
  Image im = edge_image("bspline");
  // Pixel 9 (centre 9.5) sees the rectangle x >= 10 through k(9.5 - x): the part s <= -0.5,
  // integral_{0.5}^{2} k = 1/2 - integral_0^{0.5} (4 - 6 s^2 + 3 s^3)/6 = 1/2 - 1.796875/6.
  const double covered = 0.5 - 1.796875 / 6;
  CHECK(1.0 - im.pixel(9, 20)[0] == Approx(covered).margin(1e-4));
  CHECK(1.0 - im.pixel(10, 20)[0] == Approx(1 - covered).margin(1e-4));
  CHECK(im.pixel(20, 20)[0] == Approx(0).margin(1e-6));  // well inside: solid
  CHECK(im.pixel(5, 20)[0] == Approx(1).margin(1e-6));   // beyond the support: background
}

TEST_CASE("canvas filter with an asymmetric Beta-spline kernel keeps its orientation") {
  const Basis b = parse_basis("beta:b1=2,b2=0");
  Image im = edge_image("beta:b1=2,b2=0");
  // V(c) = integral over the shape of k(c - x): for x >= 10 that is integral_{-inf}^{c-10} k.
  for (int px : {8, 9, 10, 11, 28, 29, 30, 31}) {
    const double c = px + 0.5;
    const double expected = integral(b, c - 30, c - 10);  // shape x in [10, 30]
    INFO("pixel " << px);
    CHECK(1.0 - im.pixel(px, 20)[0] == Approx(expected).margin(2e-4));
  }
  // The kernel is lopsided, so the two edges differ.
  CHECK(std::abs(im.pixel(9, 20)[0] - im.pixel(30, 20)[0]) > 0.01);
}
