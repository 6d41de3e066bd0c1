// Shift-tolerant error (see shift.hpp): separable running min and max over the square
// neighbourhood, clipped at the image border.
#include <splinefig/compare/shift.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::compare {
namespace {

// Per-channel min and max of `im` over the (2r+1)^2 neighbourhood of each pixel.
void neighbourhood_range(const Image& im, int r, std::vector<float>& lo, std::vector<float>& hi) {
  const int w = im.width, h = im.height, n = im.channels;
  std::vector<float> rlo(im.pixels.size()), rhi(im.pixels.size());
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < n; ++c) {
        float mn = im.at(i, j, c), mx = mn;
        for (int k = std::max(0, i - r); k <= std::min(w - 1, i + r); ++k) {
          mn = std::min(mn, im.at(k, j, c));
          mx = std::max(mx, im.at(k, j, c));
        }
        const std::size_t idx = (std::size_t(j) * std::size_t(w) + std::size_t(i)) * std::size_t(n) + std::size_t(c);
        rlo[idx] = mn;
        rhi[idx] = mx;
      }
  lo.assign(im.pixels.size(), 0.0f);
  hi.assign(im.pixels.size(), 0.0f);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < n; ++c) {
        const std::size_t idx = (std::size_t(j) * std::size_t(w) + std::size_t(i)) * std::size_t(n) + std::size_t(c);
        float mn = rlo[idx], mx = rhi[idx];
        for (int k = std::max(0, j - r); k <= std::min(h - 1, j + r); ++k) {
          const std::size_t kdx = (std::size_t(k) * std::size_t(w) + std::size_t(i)) * std::size_t(n) + std::size_t(c);
          mn = std::min(mn, rlo[kdx]);
          mx = std::max(mx, rhi[kdx]);
        }
        lo[idx] = mn;
        hi[idx] = mx;
      }
}

float distance_to_range(float v, float lo, float hi) {
  if (v < lo) return lo - v;
  if (v > hi) return v - hi;
  return 0.0f;
}

}  // namespace

Image shift_tolerant_error(const Image& a, const Image& b, int radius) {
  Image e = a;
  e.encoding = Encoding::linear;
  if (radius <= 0) {
    for (std::size_t k = 0; k < e.pixels.size(); ++k) e.pixels[k] = std::fabs(a.pixels[k] - b.pixels[k]);
    return e;
  }
  std::vector<float> alo, ahi, blo, bhi;
  neighbourhood_range(a, radius, alo, ahi);
  neighbourhood_range(b, radius, blo, bhi);
  for (std::size_t k = 0; k < e.pixels.size(); ++k)
    e.pixels[k] = std::max(distance_to_range(a.pixels[k], blo[k], bhi[k]), distance_to_range(b.pixels[k], alo[k], ahi[k]));
  return e;
}

}  // namespace splinefig::compare
