#pragma once
// The sRGB transfer curve (IEC 61966-2-1: the piecewise curve, not a 2.2 power), the one
// place it is written. The float forms compute in double and round once to float.
//
// 8-bit encoding is a throughput path (every pixel of every PNG written): linear_to_srgb8()
// uses tables, and gives for every float exactly the code of the formula,
// lround(255 * linear_to_srgb(clamp(v, 0, 1))) in float arithmetic (NaN gives 0).
#include <splinefig/image/image.hpp>

#include <array>
#include <cstdint>

namespace splinefig {

double srgb_to_linear(double v);
double linear_to_srgb(double v);
float srgb_to_linear(float v);
float linear_to_srgb(float v);

// Linear value of each 8-bit code: float(srgb_to_linear(code / 255.0)).
const std::array<float, 256>& srgb8_decode_table();
inline float srgb8_to_linear(std::uint8_t code) { return srgb8_decode_table()[code]; }

// The 8-bit code of a linear value, by the formula (the reference) and by table (the same
// result, faster).
std::uint8_t linear_to_srgb8_formula(float v);
std::uint8_t linear_to_srgb8(float v);

// Linear-light form of an image: sRGB-encoded colour channels decoded (alpha kept
// associated: colour is unassociated, decoded and associated again); linear images unchanged.
Image to_linear(const Image& im);

namespace detail {
// The tables behind linear_to_srgb8: `first_code[b]` is the code of b / 4096, and
// `threshold[k]` the smallest float whose code is k (threshold[0] = 0).
struct Srgb8Encoder {
  static constexpr int kBuckets = 4096;
  std::array<std::uint8_t, kBuckets> first_code;
  std::array<float, 257> threshold;  // threshold[256] = +infinity, a sentinel
};
const Srgb8Encoder& srgb8_encoder();

inline std::uint8_t encode_srgb8(const Srgb8Encoder& e, float v) {
  if (!(v > 0.0f)) return 0;  // also NaN
  if (v >= 1.0f) return 255;
  // v * 4096 is exact (a power of two), so the bucket's lower edge is <= v.
  unsigned code = e.first_code[static_cast<unsigned>(v * float(Srgb8Encoder::kBuckets))];
  while (v >= e.threshold[code + 1]) ++code;
  return static_cast<std::uint8_t>(code);
}
}  // namespace detail

}  // namespace splinefig
