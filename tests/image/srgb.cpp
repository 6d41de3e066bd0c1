// The sRGB curve and its 8-bit tables against the IEC 61966-2-1 formula.
#include <splinefig/image/srgb.hpp>

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
