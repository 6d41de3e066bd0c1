#pragma once
// Reading and writing the images `splinefig resample` works on: PNG (8- or 16-bit, sRGB) and
// OpenEXR (linear float), any channel count EXR allows, 1 to 4 for PNG.
//
// In memory every image is linear light with premultiplied alpha, which is what filtering
// needs: a PNG's colour channels are decoded from sRGB and multiplied by its (straight) alpha;
// on writing a PNG this is undone (divide by alpha, encode sRGB, round). EXR files are linear and
// premultiplied already and pass through unchanged.
#include <splinefig/resample/image.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace splinefig {

// An unreadable or unwritable file; the message is one line naming the file.
struct ImageIOError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ImageFormat {
  std::vector<std::string> channel_names;
  int alpha_channel = -1;
  bool srgb = false;  // integer PNG data, sRGB-encoded
  int bits = 32;      // 8 or 16 for PNG, 32 for float
};

struct LoadedImage {
  Image image;
  ImageFormat format;
};

double srgb_to_linear(double v);
double linear_to_srgb(double v);

LoadedImage read_image(const std::string& path);

// Writes `img` to `path` (.png or .exr, by its extension) through a temporary file in the same
// directory that is renamed into place, so a failure leaves no partial output. `like` gives the
// channel names, alpha channel and, for PNG, the bit depth (8 unless it says 16).
void write_image(const std::string& path, const Image& img, const ImageFormat& like);

}  // namespace splinefig
