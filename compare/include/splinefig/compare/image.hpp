#pragma once
// What comparison adds to splinefig::Image (image/image.hpp): windows (EXR data windows need
// not start at 0,0, and idiff compares over the union of two), padding to a window, dropping
// alpha.
#include <splinefig/base/error.hpp>
#include <splinefig/image/image.hpp>

namespace splinefig::compare {

// A comparison that cannot be made as asked: a mask of another size than the compared window,
// an inner loop this build or CPU lacks.
struct CompareError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

// A window: origin and size, in absolute pixel coordinates.
struct Window {
  int x = 0, y = 0, width = 0, height = 0;
  friend bool operator==(const Window&, const Window&) = default;
};
inline Window window_of(const Image& im) { return {im.x, im.y, im.width, im.height}; }
// The smallest window holding both; std::length_error if it would end past INT_MAX or hold more
// than kMaxImagePixels (io.hpp), since comparing pads both images to it.
Window union_window(const Window& a, const Window& b);

// `im` placed on window `w` with `channels` channels; pixels and channels it lacks are 0.
Image pad_to(const Image& im, const Window& w, int channels);

// The same image without its alpha channel (unchanged when it has none).
Image without_alpha(const Image& im);

}  // namespace splinefig::compare
