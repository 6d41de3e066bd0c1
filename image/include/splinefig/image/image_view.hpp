#pragma once
// A read-only look at pixels someone else owns (a numpy array, a buffer of another library):
// float values, channels interleaved, rows top to bottom, `row_stride` floats from the start of
// one row to the start of the next (width * channels when the rows are packed). It holds only
// what reading the values needs; the channel names, alpha channel, encoding and origin stay
// with whoever owns the pixels. The owner must keep them alive and unchanged while the view is
// used.
#include <cstddef>

namespace splinefig {

struct ImageView {
  const float* data = nullptr;
  int width = 0, height = 0, channels = 0;
  std::size_t row_stride = 0;  // in floats, at least width * channels

  // The floats of one row's values: width * channels.
  std::size_t row_length() const { return std::size_t(width) * std::size_t(channels); }
  const float* row(int j) const { return data + std::size_t(j) * row_stride; }
};

}  // namespace splinefig
