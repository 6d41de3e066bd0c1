// Windows, padding and alpha removal (see image.hpp).
#include <splinefig/compare/image.hpp>

#include <splinefig/image/io.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace splinefig::compare {

namespace {

std::string describe(const Window& w) {
  return "[" + std::to_string(w.x) + ", " + std::to_string(w.y) + ", " + std::to_string(w.width) + " x " +
         std::to_string(w.height) + "]";
}

}  // namespace

Window union_window(const Window& a, const Window& b) {
  if (a.width <= 0 || a.height <= 0) return b;
  if (b.width <= 0 || b.height <= 0) return a;
  // In 64 bits: an image's origin and size are ints, their sum and the span of two windows may
  // not be; the span is padded whole, so it is bounded as an image is (io.hpp).
  using W = std::int64_t;
  const W x0 = std::min<W>(a.x, b.x), y0 = std::min<W>(a.y, b.y);
  const W x1 = std::max(W{a.x} + a.width, W{b.x} + b.width), y1 = std::max(W{a.y} + a.height, W{b.y} + b.height);
  const W w = x1 - x0, h = y1 - y0;
  const W most = W{kMaxImagePixels};
  if (w > most || h > most || w * h > most || x1 > INT_MAX || y1 > INT_MAX)
    throw std::length_error("the data windows " + describe(a) + " and " + describe(b) + " span " + std::to_string(w) +
                            " x " + std::to_string(h) + " pixels, over the limit of 2^28 pixels compared");
  return {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(w), static_cast<int>(h)};
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
