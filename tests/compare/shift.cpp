// The shift tolerance: an anti-aliased edge moved by a fraction of a pixel passes, a missing
// line fails (in either image). Edges are rendered here by exact-enough supersampling of a
// half-plane, independently of the renderer.
#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/shift.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace splinefig;
using namespace splinefig::compare;

namespace {

// Coverage of the half-plane x cos t + y sin t < c in each pixel of a w x h grey image,
// 32 x 32 samples per pixel.
Image edge(int w, int h, double t, double c) {
  Image im = Image::zeros(w, h, 1);
  const int n = 32;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      int inside = 0;
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const double x = i + (sx + 0.5) / n, y = j + (sy + 0.5) / n;
          inside += x * std::cos(t) + y * std::sin(t) < c;
        }
      im.at(i, j, 0) = float(inside) / float(n * n);
    }
  return im;
}

Options with(float fail, int shift) {
  Options o;
  o.thresholds.fail = fail;
  o.thresholds.warn = fail;
  o.shift = shift;
  return o;
}

}  // namespace

TEST_CASE("the tolerated error is the distance to the other image's neighbourhood range") {
  Image a = Image::zeros(3, 1, 1), b = Image::zeros(3, 1, 1);
  a.pixels = {0.0f, 0.5f, 1.0f};
  b.pixels = {0.2f, 0.9f, 0.4f};
  // radius 1: B's ranges [0.2,0.9], [0.2,0.9], [0.4,0.9]; A's [0,0.5], [0,1], [0.5,1].
  const Image e = shift_tolerant_error(a, b, 1);
  CHECK(e.pixels[0] == Approx(std::max(0.2f, 0.0f)));   // A 0 below [0.2,0.9]; B 0.2 in [0,0.5]
  CHECK(e.pixels[1] == Approx(0.0f));                    // 0.5 in [0.2,0.9]; 0.9 in [0,1]
  CHECK(e.pixels[2] == Approx(std::max(0.1f, 0.1f)));   // A 1 above 0.9; B 0.4 below [0.5,1]
  const Image e0 = shift_tolerant_error(a, b, 0);
  CHECK(e0.pixels[1] == Approx(0.4f));
}

TEST_CASE("an anti-aliased edge translated by 0.3 px fails plainly and passes with --shift 1") {
  const double t = 0.35;  // a slanted edge
  const Image a = edge(40, 32, t, 20.0), b = edge(40, 32, t, 20.3);
  const Comparison plain = compare_images(a, b, with(0.02f, 0));
  CHECK(plain.verdict == Verdict::failure);
  CHECK(plain.metrics.max_error > 0.25f);
  const Comparison shifted = compare_images(a, b, with(0.02f, 1));
  CHECK(shifted.metrics.nfail == 0);
  CHECK(shifted.verdict == Verdict::match);
  // A vertical edge moved by 0.3 px: coverage 0.3 against 0 and 1 against 0.7, tolerated exactly.
  const Comparison vertical = compare_images(edge(16, 8, 0.0, 8.0), edge(16, 8, 0.0, 8.3), with(1e-6f, 1));
  CHECK(vertical.metrics.max_error == 0.0f);
}

TEST_CASE("a missing line fails even with --shift, in either image") {
  Image with_line = edge(32, 24, 0.0, 100.0), without = with_line;  // all covered: 1
  for (float& v : without.pixels) v = 0.0f;
  for (float& v : with_line.pixels) v = 0.0f;
  for (int i = 0; i < 32; ++i) with_line.at(i, 12, 0) = 1.0f;  // a 1-px line on row 12
  for (int shift : {1, 2, 3}) {
    const Comparison c = compare_images(without, with_line, with(0.1f, shift));
    CHECK(c.verdict == Verdict::failure);
    CHECK(c.metrics.nfail == 32);
    CHECK(c.metrics.max_error == 1.0f);
    const Comparison r = compare_images(with_line, without, with(0.1f, shift));
    CHECK(r.verdict == Verdict::failure);
    CHECK(r.metrics.nfail == 32);
  }
}

TEST_CASE("a translation by more than the shift radius fails") {
  const Image a = edge(40, 32, 0.35, 18.0), b = edge(40, 32, 0.35, 21.5);
  CHECK(compare_images(a, b, with(0.02f, 1)).verdict == Verdict::failure);
  CHECK(compare_images(a, b, with(0.02f, 4)).verdict == Verdict::match);
}
