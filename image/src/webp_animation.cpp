// Animated WebP through libwebp's WebPAnimEncoder (see webp_animation.hpp).
#include <splinefig/image/webp_animation.hpp>
#include <splinefig/image/atomic_file.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/base/limits.hpp>

#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace splinefig {

namespace {

const char* picture_error(WebPEncodingError e) {
  switch (e) {
    case VP8_ENC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case VP8_ENC_ERROR_BITSTREAM_OUT_OF_MEMORY: return "out of memory for the bitstream";
    case VP8_ENC_ERROR_BAD_DIMENSION: return "bad dimension";
    case VP8_ENC_ERROR_PARTITION0_OVERFLOW: case VP8_ENC_ERROR_PARTITION_OVERFLOW: return "partition overflow";
    case VP8_ENC_ERROR_BAD_WRITE: return "bad write";
    case VP8_ENC_ERROR_FILE_TOO_BIG: return "file too big";
    default: return "encoding failed";
  }
}

}  // namespace

struct WebpAnimation::State {
  int width = 0, height = 0;
  int frames = 0;
  int timestamp = 0;  // of the next frame, ms
  bool finished = false;
  WebPAnimEncoder* encoder = nullptr;
  WebPConfig config{};
  ~State() {
    if (encoder) WebPAnimEncoderDelete(encoder);
  }
};

WebpAnimation::WebpAnimation(int width, int height, int loops) : state_(std::make_unique<State>()) {
  if (width < 1 || height < 1 || width > kMaxAnimationSide || height > kMaxAnimationSide)
    throw AnimationError("animation of " + std::to_string(width) + " x " + std::to_string(height) +
                                " px: each side must be 1 to " + std::to_string(kMaxAnimationSide) + " px (WebP's limit)");
  if (loops < 0 || loops > 65535) throw AnimationError("animation loop count " + std::to_string(loops) + " is outside [0, 65535]");
  State& s = *state_;
  s.width = width;
  s.height = height;
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("libwebp: version mismatch of the animation encoder");
  options.anim_params.loop_count = loops;
  options.anim_params.bgcolor = 0xffffffff;  // white, opaque (a hint to players; frames cover the canvas)
  options.minimize_size = 0;
  options.allow_mixed = 0;  // every frame lossless
  options.verbose = 0;
  s.encoder = WebPAnimEncoderNew(width, height, &options);
  if (!s.encoder) throw std::runtime_error("libwebp: cannot create the animation encoder (out of memory)");
  if (!WebPConfigInit(&s.config)) throw std::runtime_error("libwebp: version mismatch of the encoder");
  s.config.lossless = 1;
  s.config.exact = 1;         // keep the colour under transparent pixels: the decoded values are the given ones
  s.config.quality = 75;      // with lossless: the effort, libwebp's default
  s.config.method = 4;
  s.config.thread_level = 0;  // one thread: the same bytes on every machine
  if (!WebPValidateConfig(&s.config)) throw std::runtime_error("libwebp: invalid encoder configuration");
}

WebpAnimation::~WebpAnimation() = default;

int WebpAnimation::frames() const { return state_->frames; }

void WebpAnimation::add(const Image& frame, int delay_ms) {
  State& s = *state_;
  if (s.finished) throw std::logic_error("animation: a frame added after finish()");
  if (frame.width != s.width || frame.height != s.height)
    throw AnimationError("animation frame of " + std::to_string(frame.width) + " x " + std::to_string(frame.height) +
                                " px in an animation of " + std::to_string(s.width) + " x " + std::to_string(s.height) + " px");
  if (frame.channels != 3 && frame.channels != 4)
    throw AnimationError("animation frame of " + std::to_string(frame.channels) + " channels (3 or 4 needed)");
  if (delay_ms < kMinFrameDelayMs || delay_ms > kMaxFrameDelayMs)
    throw AnimationError("frame delay " + std::to_string(delay_ms) + " ms is outside [" + std::to_string(kMinFrameDelayMs) +
                                ", " + std::to_string(kMaxFrameDelayMs) + "] ms");
  if (static_cast<std::uint64_t>(s.timestamp) + static_cast<std::uint64_t>(delay_ms) > 0x7fffffffu)
    throw AnimationError("animation longer than 2^31 ms");
  const std::vector<std::uint8_t> values = srgb8_values(frame);
  WebPPicture picture;
  if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp: version mismatch of the picture");
  picture.use_argb = 1;
  picture.width = s.width;
  picture.height = s.height;
  const int ok = frame.channels == 4 ? WebPPictureImportRGBA(&picture, values.data(), 4 * s.width)
                                     : WebPPictureImportRGB(&picture, values.data(), 3 * s.width);
  if (!ok) {
    WebPPictureFree(&picture);
    throw std::runtime_error("libwebp: cannot import an animation frame (out of memory)");
  }
  const int added = WebPAnimEncoderAdd(s.encoder, &picture, s.timestamp, &s.config);
  const WebPEncodingError code = picture.error_code;
  WebPPictureFree(&picture);
  if (!added) {
    const char* why = WebPAnimEncoderGetError(s.encoder);
    throw std::runtime_error(std::string("libwebp: cannot encode animation frame ") + std::to_string(s.frames + 1) + " (" +
                             (why && *why ? why : picture_error(code)) + ")");
  }
  s.timestamp += delay_ms;
  ++s.frames;
}

std::vector<unsigned char> WebpAnimation::finish() {
  State& s = *state_;
  if (s.finished) throw std::logic_error("animation: finish() called twice");
  if (s.frames == 0) throw std::logic_error("animation: no frames");
  s.finished = true;
  // The end time gives the last frame its duration.
  if (!WebPAnimEncoderAdd(s.encoder, nullptr, s.timestamp, nullptr))
    throw std::runtime_error(std::string("libwebp: cannot end the animation (") + WebPAnimEncoderGetError(s.encoder) + ")");
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAssemble(s.encoder, &data)) {
    WebPDataClear(&data);
    throw std::runtime_error(std::string("libwebp: cannot assemble the animation (") + WebPAnimEncoderGetError(s.encoder) + ")");
  }
  std::vector<unsigned char> bytes(data.bytes, data.bytes + data.size);
  WebPDataClear(&data);
  WebPAnimEncoderDelete(s.encoder);
  s.encoder = nullptr;
  return bytes;
}

void WebpAnimation::write(const std::string& path) {
  std::vector<unsigned char> bytes;
  try {
    bytes = finish();
  } catch (const std::runtime_error& e) {
    throw UnwritableFile(path + ": " + e.what());
  }
  write_file_atomically(path, bytes);
}

}  // namespace splinefig
