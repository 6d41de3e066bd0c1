#pragma once
// A float image in memory: interleaved channels, rows top to bottom, any channel count.
// Resampling works in this form (linear light; alpha, when present, premultiplied).
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace splinefig {

// std::allocator that leaves new floats uninitialised: an output image is written exactly once,
// so zero-filling it first would double the memory traffic of a resample.
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
    if constexpr (sizeof...(Args) == 0)
      ::new (static_cast<void*>(p)) U;
    else
      ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float, UninitializedAllocator<float>> pixels;  // width*height*channels

  Image() = default;
  Image(int w, int h, int c) : width(w), height(h), channels(c) {
    pixels.resize(static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(c));
  }
  size_t row_stride() const { return static_cast<size_t>(width) * static_cast<size_t>(channels); }
  float* row(int y) { return pixels.data() + static_cast<size_t>(y) * row_stride(); }
  const float* row(int y) const { return pixels.data() + static_cast<size_t>(y) * row_stride(); }
  float& at(int x, int y, int c) { return row(y)[static_cast<size_t>(x) * channels + c]; }
  float at(int x, int y, int c) const { return row(y)[static_cast<size_t>(x) * channels + c]; }
};

}  // namespace splinefig
