// SSIM (see perceptual.hpp), in double precision with a separable Gaussian window.
#include <splinefig/compare/perceptual.hpp>

#include <cmath>
#include <vector>

namespace splinefig::compare {

Image luminance(const Image& im) {
  Image y = Image::zeros(im.width, im.height, 1, im.encoding);
  y.x = im.x;
  y.y = im.y;
  y.alpha_channel = -1;
  int rgb[3] = {-1, -1, -1}, k = 0;
  for (int c = 0; c < im.channels && k < 3; ++c)
    if (c != im.alpha_channel) rgb[k++] = c;
  for (std::size_t p = 0; p < im.pixel_count(); ++p) {
    const float* px = im.pixels.data() + p * std::size_t(im.channels);
    if (k < 3)
      y.pixels[p] = px[rgb[0] >= 0 ? rgb[0] : 0];
    else
      y.pixels[p] = float(0.2126 * px[rgb[0]] + 0.7152 * px[rgb[1]] + 0.0722 * px[rgb[2]]);
  }
  return y;
}

namespace {

constexpr int window = 11;
constexpr int radius = window / 2;

// Valid-mode separable filtering of a w x h plane with the normalised 1-D Gaussian `g`.
std::vector<double> filter_valid(const std::vector<double>& in, int w, int h, const double* g) {
  const int ow = w - window + 1, oh = h - window + 1;
  std::vector<double> tmp(std::size_t(ow) * std::size_t(h)), out(std::size_t(ow) * std::size_t(oh));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < ow; ++i) {
      double s = 0.0;
      for (int k = 0; k < window; ++k) s += g[k] * in[std::size_t(j) * std::size_t(w) + std::size_t(i + k)];
      tmp[std::size_t(j) * std::size_t(ow) + std::size_t(i)] = s;
    }
  for (int j = 0; j < oh; ++j)
    for (int i = 0; i < ow; ++i) {
      double s = 0.0;
      for (int k = 0; k < window; ++k) s += g[k] * tmp[std::size_t(j + k) * std::size_t(ow) + std::size_t(i)];
      out[std::size_t(j) * std::size_t(ow) + std::size_t(i)] = s;
    }
  return out;
}

}  // namespace

std::optional<double> ssim(const Image& a, const Image& b) {
  if (a.width < window || a.height < window || a.width != b.width || a.height != b.height) return std::nullopt;
  const Image ya = luminance(a), yb = luminance(b);
  const int w = a.width, h = a.height;
  double g[window], sum = 0.0;
  for (int k = 0; k < window; ++k) {
    const double x = k - radius;
    g[k] = std::exp(-x * x / (2.0 * 1.5 * 1.5));
    sum += g[k];
  }
  for (double& v : g) v /= sum;

  const std::size_t n = std::size_t(w) * std::size_t(h);
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (std::size_t p = 0; p < n; ++p) {
    x[p] = ya.pixels[p];
    y[p] = yb.pixels[p];
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const auto mx = filter_valid(x, w, h, g), my = filter_valid(y, w, h, g);
  const auto sxx = filter_valid(xx, w, h, g), syy = filter_valid(yy, w, h, g), sxy = filter_valid(xy, w, h, g);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double total = 0.0;
  for (std::size_t p = 0; p < mx.size(); ++p) {
    const double vx = sxx[p] - mx[p] * mx[p], vy = syy[p] - my[p] * my[p], cxy = sxy[p] - mx[p] * my[p];
    total += ((2.0 * mx[p] * my[p] + c1) * (2.0 * cxy + c2)) /
             ((mx[p] * mx[p] + my[p] * my[p] + c1) * (vx + vy + c2));
  }
  return total / double(mx.size());
}

}  // namespace splinefig::compare
