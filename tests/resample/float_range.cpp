// Values near the largest float: a weighted sum of taps is a float sum, so a filter whose
// weights reach past 1 in absolute sum (the negative lobes of Catmull-Rom) can carry finite
// values past FLT_MAX. Such a source is refused in one line before any work, where it gave
// infinities; values whose sums stay within range resample to finite values.
#include <catch2/catch.hpp>

#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <limits>

using namespace splinefig;

namespace {

// A w x h, one-channel checkerboard of +v and -v: the pattern a negative lobe amplifies most.
Image checkerboard(int w, int h, float v) {
  Image im(w, h, 1);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) im.pixels[std::size_t(j * w + i)] = (i + j) % 2 ? -v : v;
  return im;
}

bool finite(const Image& im) {
  for (const float v : im.pixels)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

TEST_CASE("a source whose values could overflow a float through the filter's weights is refused") {
  const float big = 3.3961514e38f;  // as an EXR the resample fuzzer made held it
  const Kernel cr = parse_kernel("catmull-rom");
  // Up by 2 on each axis the outputs sit at offsets 1/4 and 3/4, where Catmull-Rom's weights
  // are -9/128, 111/128, 29/128, -3/128 (or reversed): an absolute sum of 152/128 = 1.1875.
  CHECK_THROWS_WITH(resample(checkerboard(6, 4, big), 12, 8, cr, {}),
                    Catch::StartsWith("resample: source values up to 3.39615136e+38 would overflow a float") &&
                        Catch::Contains("(their absolute sums reach 1.1875 x 1.1875)"));
  CHECK_THROWS_AS(resample(checkerboard(6, 4, big), 12, 8, cr, {}), std::invalid_argument);
  // The B-spline's weights are positive and sum to 1: every output is a convex combination.
  const Image b = resample(checkerboard(6, 4, big), 12, 8, parse_kernel("bspline"), {});
  CHECK(finite(b));
  // Values whose weighted sums stay in range pass, and come out finite.
  const Image half = resample(checkerboard(6, 4, big / 2), 12, 8, cr, {});
  CHECK(finite(half));
  // Infinities and NaN in the source are not refused: they pass through as before.
  Image inf = checkerboard(6, 4, 1.0f);
  inf.pixels[3] = std::numeric_limits<float>::infinity();
  CHECK_FALSE(finite(resample(inf, 12, 8, cr, {})));
}

TEST_CASE("an interpolating prefilter that would overflow a float is refused") {
  ResampleOptions o;
  o.interpolating = true;
  // The cubic B-spline's prefilter multiplies an alternating row by 3.
  CHECK_THROWS_WITH(resample(checkerboard(8, 8, std::numeric_limits<float>::max() * 0.9f), 16, 16,
                             parse_kernel("bspline"), o),
                    Catch::StartsWith("resample: source values this large overflow a float in the interpolating prefilter"));
  CHECK(finite(resample(checkerboard(8, 8, 1e30f), 16, 16, parse_kernel("bspline"), o)));
}
