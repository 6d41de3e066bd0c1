// Windows, padding and alpha removal (see image.hpp).
#include <splinefig/compare/image.hpp>

#include <algorithm>
#include <cmath>

namespace splinefig::compare {

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

}  // namespace splinefig::compare
