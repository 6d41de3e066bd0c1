#pragma once
// Reading and writing images through OpenImageIO, strictly: a file that is missing, not an
// image, or truncated or corrupt anywhere (header or pixel data) is an UnreadableImage, never
// an image of garbage. For PNG the chunk structure, every CRC and the complete zlib stream of
// the IDAT chunks are checked before decoding, because a PNG whose pixel data ends early can
// otherwise decode without an error.
#include <splinefig/compare/image.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace splinefig::compare {

// A file that cannot be read as an image. what() is one line naming the file and the reason.
struct UnreadableImage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A file that cannot be written. what() is one line naming the file and the reason.
struct UnwritableImage : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct LoadOptions {
  // Decode sRGB-encoded integer data (PNG) to linear light after reading; linear data is kept.
  bool linear = false;
};

// Largest image accepted, in float values (width * height * channels): 2^30, 4 GiB.
inline constexpr std::uint64_t max_image_values = std::uint64_t(1) << 30;

// Subimage 0, MIP level 0 of the file, as floats (see image.hpp for the conversion).
Image load_image(const std::string& path, const LoadOptions& options = {});

// Writes `im` to `path` (format from the extension), through a temporary file in the same
// directory renamed into place, so a failed write leaves no partial file.
//   PNG (and other 8-bit formats): 8 bits per channel, straight alpha. Linear images are
//     sRGB-encoded first; sRGB images are stored as they are (diff images use this).
//   EXR: 32-bit float; sRGB images are decoded to linear first.
void write_image(const std::string& path, const Image& im);

// Throws UnreadableImage unless `path` is a structurally complete PNG (exposed for tests).
void check_png_structure(const std::string& path);

}  // namespace splinefig::compare
