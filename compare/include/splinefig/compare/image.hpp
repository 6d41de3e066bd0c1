#pragma once
// A float image as the comparison layer sees it: any channel count, interleaved, row-major,
// with the data window's origin (EXR data windows need not start at 0,0) and the channel names
// that idiff's report prints. Values are what the file holds, converted to float the way
// OpenImageIO converts them (8-bit v/255, 16-bit v/65535, half and float as is), with alpha
// associated (premultiplied), again as OpenImageIO delivers PNGs.
//
// `encoding` says whether colour values are sRGB-encoded (integer PNG data) or linear (EXR,
// float data, or a PNG decoded with LoadOptions::linear); SSIM, FLIP and the triptych use it.
#include <cstddef>
#include <string>
#include <vector>

namespace splinefig::compare {

enum class Encoding { srgb, linear };

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  int x = 0;  // data window origin, in pixels
  int y = 0;
  std::vector<std::string> channel_names;
  int alpha_channel = -1;  // index of the alpha channel, -1 if none
  Encoding encoding = Encoding::linear;
  std::vector<float> pixels;  // width * height * channels values

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
  float* row(int j) { return pixels.data() + std::size_t(j) * std::size_t(width) * std::size_t(channels); }
  const float* row(int j) const {
    return pixels.data() + std::size_t(j) * std::size_t(width) * std::size_t(channels);
  }
  // Value at window-relative pixel (i, j), channel c.
  float& at(int i, int j, int c) {
    return pixels[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * std::size_t(channels) + std::size_t(c)];
  }
  float at(int i, int j, int c) const {
    return pixels[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * std::size_t(channels) + std::size_t(c)];
  }
  // Value at absolute pixel (px, py), channel c; 0 outside the window or past the channel count
  // (idiff's "missing pixels and channels are black").
  float value_or_zero(int px, int py, int c) const {
    const int i = px - x, j = py - y;
    if (i < 0 || j < 0 || i >= width || j >= height || c < 0 || c >= channels) return 0.0f;
    return at(i, j, c);
  }

  // A zero image with the usual names for `channels` (R,G,B,A; Y; Y,A; or channel N).
  static Image zeros(int width, int height, int channels, Encoding encoding = Encoding::linear);
  // The renderer's pixels: premultiplied linear-light RGBA floats, row-major, top row first.
  static Image from_linear_rgba(int width, int height, const float* rgba);
};

// Standard channel names for a channel count, as OpenImageIO names a PNG's channels.
std::vector<std::string> default_channel_names(int channels);

// A window: origin and size, in absolute pixel coordinates.
struct Window {
  int x = 0, y = 0, width = 0, height = 0;
  friend bool operator==(const Window&, const Window&) = default;
};
inline Window window_of(const Image& im) { return {im.x, im.y, im.width, im.height}; }
Window union_window(const Window& a, const Window& b);

// `im` placed on window `w` with `channels` channels; pixels and channels it lacks are 0.
Image pad_to(const Image& im, const Window& w, int channels);

// The same image without its alpha channel (unchanged when it has none).
Image without_alpha(const Image& im);

// sRGB transfer functions (IEC 61966-2-1), on one value.
float srgb_to_linear(float v);
float linear_to_srgb(float v);

// Linear-light colour of an image: sRGB-encoded colour channels decoded (alpha kept
// premultiplied: colour is unpremultiplied, decoded and premultiplied again).
Image to_linear(const Image& im);

}  // namespace splinefig::compare
