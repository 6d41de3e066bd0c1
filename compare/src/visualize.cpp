// Difference image and triptych (see visualize.hpp).
#include <splinefig/compare/visualize.hpp>
#include <splinefig/image/srgb.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::compare {

Image difference_image(const Image& a, const Image& b, float scale) {
  if (a.alpha_channel < 0) {
    Image d = a;
    d.encoding = Encoding::srgb;
    for (std::size_t k = 0; k < d.pixels.size(); ++k) d.pixels[k] = std::fabs(a.pixels[k] - b.pixels[k]) * scale;
    return d;
  }
  // With an alpha channel the difference of the (associated) colour channels only: stored as
  // alpha, a difference that is 0 wherever the coverage agrees would hide every colour
  // difference. alpha_difference_image() shows the alpha channel's.
  int colour[3] = {-1, -1, -1}, n = 0;
  for (int c = 0; c < a.channels && n < 3; ++c)
    if (c != a.alpha_channel) colour[n++] = c;
  Image d = Image::zeros(a.width, a.height, std::max(n, 1), Encoding::srgb);
  d.x = a.x;
  d.y = a.y;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i)
      for (int k = 0; k < n; ++k) d.at(i, j, k) = std::fabs(a.at(i, j, colour[k]) - b.at(i, j, colour[k])) * scale;
  return d;
}

Image alpha_difference_image(const Image& a, const Image& b, float scale) {
  Image d = Image::zeros(a.width, a.height, 1, Encoding::srgb);
  d.x = a.x;
  d.y = a.y;
  if (a.alpha_channel < 0 || b.alpha_channel < 0) return d;
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i)
      d.at(i, j, 0) = std::fabs(a.at(i, j, a.alpha_channel) - b.at(i, j, b.alpha_channel)) * scale;
  return d;
}

void heat_colour(float t, float rgb[3]) {
  // matplotlib's magma at t = 0, 1/8, ..., 1 (sRGB).
  static constexpr float stops[9][3] = {
      {0.001462f, 0.000466f, 0.013866f}, {0.083446f, 0.056225f, 0.220755f}, {0.232077f, 0.059889f, 0.437695f},
      {0.390384f, 0.100379f, 0.501864f}, {0.550287f, 0.161158f, 0.505719f}, {0.716387f, 0.214982f, 0.475290f},
      {0.868793f, 0.287728f, 0.409303f}, {0.967671f, 0.439703f, 0.359810f}, {0.987053f, 0.991438f, 0.749504f}};
  if (!(t > 0.0f)) t = 0.0f;  // also NaN
  t = std::min(t, 1.0f) * 8.0f;
  const int i = std::min(int(t), 7);
  const float f = t - float(i);
  for (int c = 0; c < 3; ++c) rgb[c] = stops[i][c] + f * (stops[i + 1][c] - stops[i][c]);
}

namespace {

// Display colour (sRGB) of pixel p of `im` over a checkerboard.
void display_colour(const Image& im, int i, int j, float rgb[3]) {
  int ch[3] = {-1, -1, -1}, k = 0;
  for (int c = 0; c < im.channels && k < 3; ++c)
    if (c != im.alpha_channel) ch[k++] = c;
  const float alpha = im.alpha_channel >= 0 ? std::clamp(im.at(i, j, im.alpha_channel), 0.0f, 1.0f) : 1.0f;
  const float check = ((i / 8 + j / 8) % 2) ? 0.8f : 0.6f;
  for (int c = 0; c < 3; ++c) {
    float v = k == 3 ? im.at(i, j, ch[c]) : (k > 0 ? im.at(i, j, ch[0]) : 0.0f);
    if (!std::isfinite(v)) v = 0.0f;
    if (im.encoding == Encoding::linear)
      v = linear_to_srgb(std::clamp(v + (1.0f - alpha) * srgb_to_linear(check), 0.0f, 1.0f));
    else
      v = std::clamp(v + (1.0f - alpha) * check, 0.0f, 1.0f);
    rgb[c] = v;
  }
}

}  // namespace

Image triptych(const Image& expected, const Image& actual, float heat_scale) {
  const int w = expected.width, h = expected.height, gap = 2;
  Image out = Image::zeros(3 * w + 2 * gap, h, 3, Encoding::srgb);
  std::fill(out.pixels.begin(), out.pixels.end(), 1.0f);
  const int n = std::min(expected.channels, actual.channels);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      float rgb[3];
      display_colour(expected, i, j, rgb);
      for (int c = 0; c < 3; ++c) out.at(i, j, c) = rgb[c];
      display_colour(actual, i, j, rgb);
      for (int c = 0; c < 3; ++c) out.at(w + gap + i, j, c) = rgb[c];
      float m = 0.0f;
      for (int c = 0; c < std::max(expected.channels, actual.channels); ++c) {
        const float d = c < n ? std::fabs(expected.at(i, j, c) - actual.at(i, j, c))
                              : std::fabs(c < expected.channels ? expected.at(i, j, c) : actual.at(i, j, c));
        if (!(d <= m)) m = std::isnan(d) ? 1.0f / std::max(heat_scale, 1e-30f) : d;
      }
      heat_colour(m * heat_scale, rgb);
      for (int c = 0; c < 3; ++c) out.at(2 * (w + gap) + i, j, c) = rgb[c];
    }
  return out;
}

}  // namespace splinefig::compare
