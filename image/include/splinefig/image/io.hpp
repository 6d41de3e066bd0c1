#pragma once
// Image files through OpenImageIO: strict reading and atomic writing.
//
// Reading is strict: a file that is missing, not a regular file, not an image, or truncated or
// corrupt anywhere (header or pixel data) is an UnreadableImage, never an image of garbage.
// For PNG the chunk structure, every CRC and the complete zlib stream of the IDAT chunks are
// checked before decoding, because a PNG whose pixel data ends early can otherwise decode
// without an error. Subimage 0, MIP level 0 is read.
//
// Writing goes through write_file_atomically (atomic_file.hpp): checked, fsync'd, renamed.
#include <splinefig/image/atomic_file.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/image/image.hpp>

#include <cstdint>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

namespace splinefig {

// A file that cannot be read as an image. what() is one line naming the file and the reason.
struct UnreadableImage : ErrorOf<std::runtime_error, ErrorKind::unreadable> {
  using ErrorOf::ErrorOf;
};
// A file that cannot be written. what() is one line naming the file and the reason.
struct UnwritableImage : UnwritableFile {
  using UnwritableFile::UnwritableFile;
};

// The limits of an image read (kMaxImageValues, kMaxImagePixels, kMaxImageSide,
// kMaxImageOrigin) are in base/limits.hpp.

enum class ReadMode {
  // The values the file holds, converted to float the way OpenImageIO converts them (8-bit
  // v / 255, 16-bit v / 65535, half and float as is), alpha associated as OpenImageIO
  // delivers it; sRGB integer data stays sRGB-encoded. This is what idiff compares.
  as_stored,
  // Linear light, alpha associated: sRGB integer data is decoded (colour, not colour times
  // alpha, is what the curve applies to) and then multiplied by its alpha. Float data (EXR)
  // is linear and associated already. This is what resampling and drawing need.
  linear,
};

// What the file was, for writing a result like it.
struct FileFormat {
  std::string name;  // OpenImageIO's format name: "png", "openexr", ...
  int bits = 8;      // bits per stored value
};

Image read_image(const std::string& path, ReadMode mode = ReadMode::as_stored, FileFormat* format = nullptr);

// Every member has a default member initializer, so that a designated initializer naming some
// ({.bits = 16}) leaves the others at their defaults, and GCC does not warn of them
// (-Wmissing-field-initializers warns of a member without one).
struct WriteOptions {
  int bits = 8;              // 8 or 16 (PNG), 8 (JPEG), 8, 16 or 32 = float (TIFF); EXR is float32
  std::string software{};    // "splinefig <version>" when empty
  std::string description{}; // ImageDescription, e.g. the spec name; none when empty
  double dpi = 0;            // pixels per inch (PNG pHYs, EXR/TIFF XResolution); none when 0
  // The file's DateTime (EXR, TIFF) in seconds since 1970 UTC, e.g. SOURCE_DATE_EPOCH; none when
  // negative, so that the same image always gives the same bytes.
  long long date = -1;
};

// Writes `im` to `path`, the format chosen by the extension:
//   .png: 8 or 16 bits per channel, 1 to 4 channels, straight alpha, sRGB-encoded. Linear
//     images are encoded (8 bits: linear_to_srgb8, exact); sRGB images are stored as they are.
//     Values are clamped to [0, 1]; NaN is stored as 0.
//   .jpg, .jpeg: 8 bits, 1 or 3 channels (no alpha), sRGB-encoded as for PNG, quality 95.
//   .tif, .tiff: 8 or 16 bits as for PNG (zip-compressed, unassociated alpha), or with bits = 32
//     float32 as for EXR.
//   .exr: float32, linear, associated alpha; sRGB images are decoded first.
// Throws UnwritableImage (naming the path) for any other extension or any failure.
void write_image(const std::string& path, const Image& im, const WriteOptions& options = {});

// The 8-bit values write_image stores for `im` in a PNG (straight alpha, sRGB-encoded, clamped,
// NaN as 0; the image's channels, interleaved): what the animated WebP writer encodes too.
std::vector<std::uint8_t> srgb8_values(const Image& im);

// The formats write_image writes; the one a path's extension names (any case), if any.
enum class ImageFormat { png, jpeg, tiff, exr };
std::optional<ImageFormat> image_format_of(const std::string& path);
// As write_image, in `format` whatever the path's extension.
void write_image(const std::string& path, const Image& im, ImageFormat format, const WriteOptions& options = {});

// Loads the image I/O module (OpenImageIO, see docs/image.md) now rather than at the first read
// or write, e.g. on a thread that would otherwise wait while others render. Never throws: a
// module that cannot be loaded is reported by the first read or write.
void preload_image_io() noexcept;
// Reads only the header of the image file `path` and throws UnreadableImage if the image is
// over the limits above, or is not an image at all; cheap, so that every input of a command
// can be checked before any is decoded.
void check_image_header(const std::string& path);

// Throws UnreadableImage unless `path` is a structurally complete PNG (exposed for tests).
void check_png_structure(const std::string& path);

}  // namespace splinefig
