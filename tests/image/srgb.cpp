// The sRGB curve and its 8-bit tables against the IEC 61966-2-1 formula.
#include <splinefig/image/srgb.hpp>

#include <OpenImageIO/color.h>
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

using namespace splinefig;

namespace {

// The formula, written out here independently of the library: the code splinefig has always
// stored for a linear value (float arithmetic, as the renderer's PNGs were written).
int reference_code(float v) {
  if (!(v > 0.0f)) return 0;
  v = std::min(v, 1.0f);
  const float s = v <= 0.0031308f ? 12.92f * v
                                  : static_cast<float>(1.055 * std::pow(static_cast<double>(v), 1.0 / 2.4) - 0.055);
  return static_cast<int>(std::lround(s * 255.0f));
}

}  // namespace

TEST_CASE("the sRGB curve: known values, both branches, inverse pair") {
  CHECK(linear_to_srgb(0.5) == Approx(0.7353569830524495).epsilon(1e-14));  // 1.055 * 0.5^(1/2.4) - 0.055
  CHECK(srgb_to_linear(0.5) == Approx(0.21404114048223255).epsilon(1e-14));  // ((0.5 + 0.055) / 1.055)^2.4
  CHECK(srgb_to_linear(0.04045f) == Approx(0.04045 / 12.92));
  CHECK(linear_to_srgb(0.5f) == Approx(0.735356983).epsilon(1e-6));
  CHECK(linear_to_srgb(0.001) == Approx(0.01292));
  for (int i = 0; i <= 255; ++i) CHECK(linear_to_srgb(srgb_to_linear(i / 255.0)) == Approx(i / 255.0).margin(1e-12));
}

TEST_CASE("the 8-bit decode table holds the curve at every code") {
  for (int i = 0; i <= 255; ++i) {
    const double v = i / 255.0;
    const double expected = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    CHECK(srgb8_to_linear(static_cast<std::uint8_t>(i)) == static_cast<float>(expected));
  }
}

TEST_CASE("the 8-bit encode table gives the formula's code for every float that can matter") {
  // Every float from 2^-14 to 1 (117 million), each compared with the formula. Below 2^-14
  // the formula gives 0 (12.92 * 255 * 2^-14 < 0.21); a sample there, and the edges.
  const std::uint32_t lo = std::bit_cast<std::uint32_t>(std::ldexp(1.0f, -14));
  const std::uint32_t hi = std::bit_cast<std::uint32_t>(1.0f);
  std::uint64_t mismatches = 0;
  float first_bad = 0.0f;
  for (std::uint32_t b = lo; b <= hi; ++b) {
    const float v = std::bit_cast<float>(b);
    if (linear_to_srgb8(v) != reference_code(v)) {
      if (mismatches++ == 0) first_bad = v;
    }
  }
  INFO("first mismatch at " << first_bad);
  CHECK(mismatches == 0);
  for (std::uint32_t b = 0; b < lo; b += 4099) {
    const float v = std::bit_cast<float>(b);
    CHECK(linear_to_srgb8(v) == reference_code(v));
    CHECK(linear_to_srgb8(v) == 0);
  }
  CHECK(linear_to_srgb8(0.0f) == 0);
  CHECK(linear_to_srgb8(-0.0f) == 0);
  CHECK(linear_to_srgb8(-1.0f) == 0);
  CHECK(linear_to_srgb8(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(linear_to_srgb8(std::nextafter(1.0f, 2.0f)) == 255);
  CHECK(linear_to_srgb8(1e30f) == 255);
  CHECK(linear_to_srgb8(std::numeric_limits<float>::infinity()) == 255);
  CHECK(linear_to_srgb8(0.5f) == 188);
  CHECK(linear_to_srgb8_formula(0.5f) == 188);
}

// ---------------------------------------------------------------------------------------------
// The curve pinned where its pieces meet. The IEC 61966-2-1 formula, written out here in double:
//   decode(v) = v / 12.92 for v <= 0.04045, ((v + 0.055) / 1.055)^2.4 above;
//   encode(v) = 12.92 v for v <= 0.0031308, 1.055 v^(1/2.4) - 0.055 above.
// The pieces do not quite meet: at 0.04045 the decode's differ by 2.33e-9 (ten float steps of
// 2.3e-10 at 0.00313), at 0.0031308 the encode's by 2.85e-8 (eight float steps at 0.04), and
// their slopes differ by 1.7%, so a threshold moved from 0.04045 to 0.04 changes decoded values
// by up to 4.8e-7 (2000 float steps), which a default Approx (relative 1.2e-5) does not see.

namespace {

double iec_decode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double iec_encode(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

// Within one float step of the exact value (the float forms round once, or twice for
// the linear piece's float division).
bool within_a_float_step(float got, double exact) {
  const float e = static_cast<float>(exact);
  const double step = double(std::nextafter(std::fabs(e), std::numeric_limits<float>::infinity())) - std::fabs(e);
  return std::fabs(double(got) - exact) <= step;
}

}  // namespace

TEST_CASE("the sRGB decode at every 16-bit code around 0.04045 against the IEC formula in double") {
  // Codes 2400 to 2900 are 0.0366 to 0.0443; 2651 (0.040452) is the first above the threshold,
  // and 2622 to 2650 lie in (0.04, 0.04045].
  CHECK(2650 / 65535.0 <= 0.04045);
  CHECK(2651 / 65535.0 > 0.04045);
  int linear_piece = 0;
  for (int k = 2400; k <= 2900; ++k) {
    const double v = k / 65535.0;
    INFO("code " << k);
    CHECK(srgb_to_linear(v) == Approx(iec_decode(v)).epsilon(1e-15).margin(0));
    const float vf = static_cast<float>(v);  // what OpenImageIO hands over for a 16-bit code
    CHECK(within_a_float_step(srgb_to_linear(vf), iec_decode(double(vf))));
    // OpenImageIO's own curve (float arithmetic: a few steps of rounding) as a second oracle.
    CHECK(std::fabs(double(srgb_to_linear(vf)) - double(OIIO::sRGB_to_linear(vf))) <= 4e-7 * iec_decode(double(vf)));
    linear_piece += v <= 0.04045;
  }
  CHECK(linear_piece == 251);
}

TEST_CASE("the sRGB decode at the floats and doubles next to 0.04045") {
  // The threshold itself belongs to the linear piece; the next double takes the power piece,
  // 2.33e-9 away (thousands of double steps).
  CHECK(srgb_to_linear(0.04045) == 0.04045 / 12.92);
  const double above = std::nextafter(0.04045, 1.0);
  CHECK(srgb_to_linear(above) == Approx(std::pow((above + 0.055) / 1.055, 2.4)).epsilon(1e-15).margin(0));
  CHECK(std::fabs(srgb_to_linear(above) - above / 12.92) > 2e-9);
  // float(0.04045) is 0.040449999272..., below the threshold: the linear piece.
  REQUIRE(double(0.04045f) < 0.04045);
  // 2^17 floats on either side (0.03996 to 0.04094), each within a float step of the formula.
  std::uint64_t bad = 0;
  float first_bad = 0.0f;
  float v = 0.04045f;
  for (int i = 0; i < (1 << 17); ++i) v = std::nextafter(v, 0.0f);
  for (int i = 0; i < (1 << 18); ++i, v = std::nextafter(v, 1.0f))
    if (!within_a_float_step(srgb_to_linear(v), iec_decode(double(v))) && bad++ == 0) first_bad = v;
  INFO("first mismatch at " << first_bad);
  CHECK(bad == 0);
  CHECK(within_a_float_step(srgb_to_linear(0.04f), 0.04f / 12.92));
  CHECK(within_a_float_step(srgb_to_linear(0.0403f), double(0.0403f) / 12.92));
}

TEST_CASE("the sRGB encode at the floats and doubles next to 0.0031308") {
  CHECK(linear_to_srgb(0.0031308) == 12.92 * 0.0031308);
  const double above = std::nextafter(0.0031308, 1.0);
  CHECK(linear_to_srgb(above) == Approx(1.055 * std::pow(above, 1.0 / 2.4) - 0.055).epsilon(1e-15).margin(0));
  CHECK(std::fabs(linear_to_srgb(above) - 12.92 * above) > 2.8e-8);
  // float(0.0031308) is 0.00313080009..., 9.1e-11 above the threshold; the float form compares
  // with that float, so it alone takes the linear piece where the formula takes the power
  // piece (8 float steps apart). Every other float of 2^17 on either side (0.00310 to 0.00316)
  // follows the formula.
  const float t = 0.0031308f;
  REQUIRE(double(t) > 0.0031308);
  CHECK(within_a_float_step(linear_to_srgb(t), 12.92 * double(t)));
  std::uint64_t bad = 0;
  float first_bad = 0.0f;
  float v = t;
  for (int i = 0; i < (1 << 17); ++i) v = std::nextafter(v, 0.0f);
  for (int i = 0; i < (1 << 18); ++i, v = std::nextafter(v, 1.0f))
    if (v != t && !within_a_float_step(linear_to_srgb(v), iec_encode(double(v))) && bad++ == 0) first_bad = v;
  INFO("first mismatch at " << first_bad);
  CHECK(bad == 0);
}

TEST_CASE("the 8-bit decode table against OpenImageIO's sRGB curve") {
  // OpenImageIO computes in float (x * (1/12.92f), powf): within 4e-7 relative of ours.
  for (int i = 0; i <= 255; ++i) {
    INFO("code " << i);
    const float ours = srgb8_to_linear(static_cast<std::uint8_t>(i));
    const float theirs = OIIO::sRGB_to_linear(float(i) / 255.0f);
    CHECK(std::fabs(double(ours) - double(theirs)) <= 4e-7 * double(theirs));
  }
}
