// Image value type helpers: windows, padding, alpha removal, sRGB transfer functions.
#include <splinefig/compare/image.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::compare {

std::vector<std::string> default_channel_names(int channels) {
  switch (channels) {
    case 1: return {"Y"};
    case 2: return {"Y", "A"};
    case 3: return {"R", "G", "B"};
    case 4: return {"R", "G", "B", "A"};
    default: break;
  }
  std::vector<std::string> names;
  for (int c = 0; c < channels; ++c) names.push_back("channel" + std::to_string(c));
  return names;
}

Image Image::zeros(int width, int height, int channels, Encoding encoding) {
  Image im;
  im.width = width;
  im.height = height;
  im.channels = channels;
  im.channel_names = default_channel_names(channels);
  im.alpha_channel = (channels == 2 || channels == 4) ? channels - 1 : -1;
  im.encoding = encoding;
  im.pixels.assign(std::size_t(width) * std::size_t(height) * std::size_t(channels), 0.0f);
  return im;
}

Image Image::from_linear_rgba(int width, int height, const float* rgba) {
  Image im = zeros(width, height, 4, Encoding::linear);
  std::copy(rgba, rgba + im.pixels.size(), im.pixels.begin());
  return im;
}

Window union_window(const Window& a, const Window& b) {
  if (a.width <= 0 || a.height <= 0) return b;
  if (b.width <= 0 || b.height <= 0) return a;
  const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
  const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
  return {x0, y0, x1 - x0, y1 - y0};
}

Image pad_to(const Image& im, const Window& w, int channels) {
  Image out = Image::zeros(w.width, w.height, channels, im.encoding);
  out.x = w.x;
  out.y = w.y;
  for (int c = 0; c < channels && c < im.channels; ++c)
    if (c < int(im.channel_names.size())) out.channel_names[c] = im.channel_names[c];
  out.alpha_channel = im.alpha_channel < channels ? im.alpha_channel : -1;
  const int nc = std::min(channels, im.channels);
  for (int j = 0; j < im.height; ++j) {
    const int oj = im.y + j - w.y;
    if (oj < 0 || oj >= w.height) continue;
    for (int i = 0; i < im.width; ++i) {
      const int oi = im.x + i - w.x;
      if (oi < 0 || oi >= w.width) continue;
      for (int c = 0; c < nc; ++c) out.at(oi, oj, c) = im.at(i, j, c);
    }
  }
  return out;
}

Image without_alpha(const Image& im) {
  if (im.alpha_channel < 0) return im;
  Image out = im;
  out.channels = im.channels - 1;
  out.channel_names.erase(out.channel_names.begin() + im.alpha_channel);
  out.alpha_channel = -1;
  out.pixels.resize(im.pixel_count() * std::size_t(out.channels));
  std::size_t k = 0;
  for (std::size_t p = 0; p < im.pixel_count(); ++p)
    for (int c = 0; c < im.channels; ++c)
      if (c != im.alpha_channel) out.pixels[k++] = im.pixels[p * std::size_t(im.channels) + std::size_t(c)];
  return out;
}

float srgb_to_linear(float v) {
  if (v <= 0.04045f) return v / 12.92f;
  return float(std::pow((double(v) + 0.055) / 1.055, 2.4));
}

float linear_to_srgb(float v) {
  if (v <= 0.0031308f) return v * 12.92f;
  return float(1.055 * std::pow(double(v), 1.0 / 2.4) - 0.055);
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

}  // namespace splinefig::compare
