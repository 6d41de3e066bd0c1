#pragma once
// splinefig's one image type: float values, channels interleaved, rows top to bottom, any
// channel count, with the channel names, the alpha channel and the data window's origin that
// image files carry.
//
// The convention, stated once for the whole tree:
// - alpha, when there is an alpha channel, is associated (premultiplied) in memory, always;
// - `encoding` says what the colour values are: linear light (what the renderer draws, what
//   resampling filters and what EXR stores) or sRGB-encoded values exactly as an integer file
//   holds them (v / 255 for 8 bits), which is how idiff compares PNGs.
// The renderer's images are linear RGBA (4 channels, alpha 3). read_image() (io.hpp) gives
// either the file's values as stored or the decoded linear form; write_image() converts from
// whichever encoding the image is in.
#include <splinefig/image/image_view.hpp>

#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace splinefig {

enum class Encoding { linear, srgb };

// std::allocator whose resize() leaves new elements unwritten: an output image is written
// exactly once, so zero-filling it first would double the memory traffic of a resample or a
// render. Elements of a trivially copyable and destructible type (float, an aggregate of doubles
// even with member initializers: implicit-lifetime types) are not constructed at all; others
// are default-initialized.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) != 0)
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    else if constexpr (!(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>))
      ::new (static_cast<void*>(p)) U;
  }
};

// Standard channel names for a channel count, as OpenImageIO names a PNG's channels
// (R,G,B,A; Y; Y,A; otherwise channel0, channel1, ...).
std::vector<std::string> default_channel_names(int channels);
// The alpha channel those names imply: the last of 2 or 4 channels, else none (-1).
int default_alpha_channel(int channels);

struct Image {
  int width = 0, height = 0, channels = 0;
  int x = 0, y = 0;  // data window origin, in pixels (EXR data windows need not start at 0,0)
  std::vector<std::string> channel_names;
  int alpha_channel = -1;  // index of the alpha channel, -1 if none
  Encoding encoding = Encoding::linear;
  std::vector<float, UninitializedAllocator<float>> pixels;  // width * height * channels

  Image() = default;
  // Uninitialised values; default channel names and alpha channel for the count.
  Image(int width, int height, int channels, Encoding encoding = Encoding::linear);
  // All values 0.
  static Image zeros(int width, int height, int channels, Encoding encoding = Encoding::linear);

  std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
  std::size_t row_stride() const { return std::size_t(width) * std::size_t(channels); }
  float* row(int j) { return pixels.data() + std::size_t(j) * row_stride(); }
  const float* row(int j) const { return pixels.data() + std::size_t(j) * row_stride(); }
  // The values of window-relative pixel (i, j).
  float* pixel(int i, int j) { return row(j) + std::size_t(i) * std::size_t(channels); }
  const float* pixel(int i, int j) const { return row(j) + std::size_t(i) * std::size_t(channels); }
  float& at(int i, int j, int c) { return pixel(i, j)[c]; }
  float at(int i, int j, int c) const { return pixel(i, j)[c]; }
  // Value at absolute pixel (px, py), channel c; 0 outside the window or past the channel count
  // (idiff's "missing pixels and channels are black").
  float value_or_zero(int px, int py, int c) const {
    const int i = px - x, j = py - y;
    if (i < 0 || j < 0 || i >= width || j >= height || c < 0 || c >= channels) return 0.0f;
    return at(i, j, c);
  }
  // The pixels, read-only, as a view (valid while the image lives and keeps its size).
  ImageView view() const { return {pixels.data(), width, height, channels, row_stride()}; }
  // Names, alpha channel, encoding and origin of `other`, for an image derived from it.
  void copy_metadata_from(const Image& other);
};

}  // namespace splinefig
