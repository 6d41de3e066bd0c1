// SSIM and LDR-FLIP pinned to values that do not come from compare/src: closed forms, and
// numbers printed by tests/compare/oracle/perceptual_oracle.py (scikit-image 0.19.3's
// structural_similarity for SSIM; a direct numpy transcription of the FLIP paper with full
// 2-D kernels for FLIP), run during development on the same analytic patterns as below.
#include <splinefig/compare/perceptual.hpp>
#include <splinefig/image/srgb.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace splinefig;
using namespace splinefig::compare;

namespace {

// The oracle's pattern('ref') and pattern('test'): 48 x 40 sRGB-encoded RGB.
Image pattern(bool test) {
  Image im = Image::zeros(48, 40, 3, Encoding::srgb);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x)
      for (int c = 0; c < 3; ++c) {
        double v = 0.5 + 0.35 * std::sin(0.21 * x + 0.9 * c) * std::cos(0.17 * y - 0.4 * c);
        if (test) v += 0.12 * std::sin(0.37 * x + 0.23 * y + 1.3 * c);
        if (test && y >= 10 && y < 18 && x >= 30 && x < 38) v = 0.95;
        im.at(x, y, c) = float(v);
      }
  return im;
}

Image constant(int w, int h, int channels, float v, Encoding e = Encoding::srgb) {
  Image im = Image::zeros(w, h, channels, e);
  std::fill(im.pixels.begin(), im.pixels.end(), v);
  return im;
}

}  // namespace

TEST_CASE("SSIM of an image with itself is 1") {
  const Image a = pattern(false);
  REQUIRE(ssim(a, a).has_value());
  CHECK(*ssim(a, a) == Approx(1.0).margin(1e-12));
}

TEST_CASE("SSIM of constant images is (2 m1 m2 + C1) / (m1^2 + m2^2 + C1)") {
  // Variances vanish, so the structure term is C2 / C2 = 1; C1 = (0.01 * 1)^2.
  const double expected = (2 * 0.5 * 0.25 + 1e-4) / (0.25 + 0.0625 + 1e-4);
  CHECK(*ssim(constant(16, 16, 1, 0.5f), constant(16, 16, 1, 0.25f)) == Approx(expected).epsilon(1e-7));
  CHECK(expected == Approx(0.8000639795).epsilon(1e-9));  // scikit-image's value (oracle script)
}

TEST_CASE("SSIM of the oracle's pattern pair matches scikit-image") {
  CHECK(*ssim(pattern(false), pattern(true)) == Approx(0.6645294472).epsilon(1e-6));
}

TEST_CASE("SSIM is symmetric and undefined below 11 x 11") {
  const Image a = pattern(false), b = pattern(true);
  CHECK(*ssim(a, b) == Approx(*ssim(b, a)).epsilon(1e-12));
  CHECK_FALSE(ssim(constant(10, 30, 3, 0.5f), constant(10, 30, 3, 0.5f)).has_value());
}

TEST_CASE("SSIM uses Rec. 709 luminance: a chroma change of equal luminance keeps SSIM 1") {
  Image a = constant(12, 12, 3, 0.0f), b = constant(12, 12, 3, 0.0f);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) {
      a.at(x, y, 0) = 0.7152f;  // Y = 0.2126 * 0.7152
      b.at(x, y, 1) = 0.2126f;  // Y = 0.7152 * 0.2126
    }
  CHECK(*ssim(a, b) == Approx(1.0).margin(1e-9));
}

TEST_CASE("FLIP of an image with itself is 0") {
  const Image a = pattern(false);
  const FlipResult f = flip(a, a);
  CHECK(f.mean == 0.0);
  CHECK(f.max == 0.0);
}

TEST_CASE("FLIP of the oracle's pattern pair matches the numpy transcription") {
  const FlipResult f = flip(pattern(false), pattern(true));
  CHECK(f.mean == Approx(0.4449870553).epsilon(2e-5));
  CHECK(f.max == Approx(0.9836899774).epsilon(2e-5));
  CHECK(f.map.at(5, 7, 0) == Approx(0.5166271188).epsilon(2e-5));
}

TEST_CASE("FLIP of flat colours is the redistributed HyAB colour difference") {
  // No features on flat images, so FLIP = dE_c; the numpy oracle gives these.
  const FlipResult bw = flip(constant(16, 16, 3, 0.0f), constant(16, 16, 3, 1.0f));
  CHECK(bw.mean == Approx(0.9673797628).epsilon(1e-5));
  CHECK(bw.max == Approx(0.9673797628).epsilon(1e-5));
  const FlipResult bg = flip(constant(16, 16, 3, 0.0f), constant(16, 16, 3, 0.5f));
  CHECK(bg.mean == Approx(0.9314960894).epsilon(1e-5));
}

TEST_CASE("FLIP reads linear images as linear and grey images as grey") {
  // sRGB 0.5 is linear 0.2140; a linear image holding that value is the same colour.
  const float lin = srgb_to_linear(0.5f);
  CHECK(lin == Approx(0.21404114).epsilon(1e-6));
  const FlipResult a = flip(constant(16, 16, 3, 0.0f), constant(16, 16, 3, lin, Encoding::linear));
  CHECK(a.mean == Approx(0.9314960894).epsilon(1e-5));
  const FlipResult g = flip(constant(16, 16, 1, 0.0f), constant(16, 16, 1, 0.5f));
  CHECK(g.mean == Approx(0.9314960894).epsilon(1e-5));
}
