// The sRGB curve and its 8-bit tables (see srgb.hpp).
#include <splinefig/image/srgb.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace splinefig {

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

float srgb_to_linear(float v) {
  if (v <= 0.04045f) return v / 12.92f;
  return static_cast<float>(std::pow((static_cast<double>(v) + 0.055) / 1.055, 2.4));
}

float linear_to_srgb(float v) {
  if (v <= 0.0031308f) return 12.92f * v;
  return static_cast<float>(1.055 * std::pow(static_cast<double>(v), 1.0 / 2.4) - 0.055);
}

const std::array<float, 256>& srgb8_decode_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[std::size_t(i)] = static_cast<float>(srgb_to_linear(i / 255.0));
    return t;
  }();
  return table;
}

std::uint8_t linear_to_srgb8_formula(float v) {
  if (!(v > 0.0f)) return 0;  // also NaN
  v = std::min(v, 1.0f);
  return static_cast<std::uint8_t>(std::lround(linear_to_srgb(v) * 255.0f));
}

Image to_linear(const Image& im) {
  if (im.encoding == Encoding::linear) return im;
  Image out = im;
  out.encoding = Encoding::linear;
  const int a = im.alpha_channel;
  for (std::size_t p = 0; p < im.pixel_count(); ++p) {
    float* px = out.pixels.data() + p * std::size_t(im.channels);
    const float alpha = a >= 0 ? px[a] : 1.0f;
    for (int c = 0; c < im.channels; ++c) {
      if (c == a) continue;
      if (alpha > 0.0f && alpha != 1.0f)
        px[c] = srgb_to_linear(px[c] / alpha) * alpha;
      else
        px[c] = srgb_to_linear(px[c]);
    }
  }
  return out;
}

namespace detail {

const Srgb8Encoder& srgb8_encoder() {
  static const Srgb8Encoder enc = [] {
    Srgb8Encoder e{};
    // The code is non-decreasing in v (the tests check every float), so the smallest float
    // of each code is found by bisection over the bit patterns of [0, 1], which are ordered.
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    e.threshold[0] = 0.0f;
    for (int k = 1; k <= 255; ++k) {
      std::uint32_t lo = 0, hi = one;  // code(lo) < k <= code(hi)
      while (hi - lo > 1) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (linear_to_srgb8_formula(std::bit_cast<float>(mid)) >= k)
          hi = mid;
        else
          lo = mid;
      }
      e.threshold[std::size_t(k)] = std::bit_cast<float>(hi);
    }
    e.threshold[256] = std::numeric_limits<float>::infinity();
    for (int b = 0; b < Srgb8Encoder::kBuckets; ++b)
      e.first_code[std::size_t(b)] = linear_to_srgb8_formula(static_cast<float>(b) / Srgb8Encoder::kBuckets);
    return e;
  }();
  return enc;
}

}  // namespace detail

std::uint8_t linear_to_srgb8(float v) { return detail::encode_srgb8(detail::srgb8_encoder(), v); }

}  // namespace splinefig
