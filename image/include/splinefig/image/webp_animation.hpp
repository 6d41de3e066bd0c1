#pragma once
// Animated WebP files, encoded by libwebp's WebPAnimEncoder (libwebpmux): lossless, so that each
// frame decodes to exactly the 8-bit values a PNG of the same image stores (srgb8_values, io.hpp),
// single-threaded and with no options that depend on the machine, so the same frames always give
// the same bytes. Frames are added one at a time (the encoder keeps the previous canvas, not
// every frame), and the file is published atomically (write_file_atomically): a failed or
// interrupted write leaves no partial file.
#include <splinefig/base/error.hpp>
#include <splinefig/image/image.hpp>

#include <memory>
#include <string>
#include <vector>

namespace splinefig {

// An animation or frame that WebP cannot hold (a side, loop count, frame delay or length out of
// range, a frame of another size or channel count).
struct AnimationError : ErrorOf<std::invalid_argument, ErrorKind::bad_input> {
  using ErrorOf::ErrorOf;
};

class WebpAnimation {
 public:
  // An animation of width x height pixels (each side 1 .. kMaxAnimationSide, base/limits.hpp),
  // played `loops` times (0: for ever). Throws AnimationError for a size out of range.
  WebpAnimation(int width, int height, int loops = 0);
  ~WebpAnimation();
  WebpAnimation(const WebpAnimation&) = delete;
  WebpAnimation& operator=(const WebpAnimation&) = delete;

  // Appends a frame shown for `delay_ms` milliseconds (kMinFrameDelayMs .. kMaxFrameDelayMs):
  // an image of the animation's size, 3 or 4 channels (RGB, RGBA), in either encoding. Throws
  // AnimationError for a frame of another size or a delay out of range,
  // std::runtime_error with libwebp's reason when it cannot encode it.
  void add(const Image& frame, int delay_ms);
  int frames() const;

  // The file's bytes (at least one frame added); the animation takes no more frames after.
  std::vector<unsigned char> finish();
  // finish(), written to `path` atomically. Throws UnwritableFile naming the path.
  void write(const std::string& path);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace splinefig
