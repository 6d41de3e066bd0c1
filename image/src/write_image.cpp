// Image writing: the conversion to the file's encoding, OpenImageIO encoding into memory, and
// an atomic publication of the bytes (see io.hpp).
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/version.hpp>

#include "one_line.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace splinefig {
namespace {

using detail::one_line;

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

[[noreturn]] void unwritable(const std::string& path, const std::string& why) {
  throw UnwritableImage(path + ": " + (why.empty() ? std::string("write failed") : why));
}

// Straight-alpha, sRGB-encoded integer values of `im`, clamped to [0, 1] (NaN as 0).
template <class T>
std::vector<T> integer_values(const Image& im) {
  constexpr float top = float(std::numeric_limits<T>::max());
  std::vector<T> out(im.pixels.size());
  const int C = im.channels, a = im.alpha_channel;
  const bool encode = im.encoding == Encoding::linear;
  const detail::Srgb8Encoder& enc = detail::srgb8_encoder();
  auto quantize = [&](float v) {
    if (!(v > 0.0f)) return T(0);
    if (v >= 1.0f) return T(top);  // also the common opaque alpha, without a rounding call
    return static_cast<T>(std::lround(v * top));
  };
  for (std::size_t p = 0; p < im.pixels.size(); p += std::size_t(C)) {
    const float* px = im.pixels.data() + p;
    T* o = out.data() + p;
    const float alpha = a >= 0 ? std::clamp(px[a], 0.0f, 1.0f) : 1.0f;
    for (int c = 0; c < C; ++c) {
      if (c == a) {
        o[c] = quantize(alpha);
        continue;
      }
      float v = px[c];
      if (a >= 0 && alpha != 1.0f) v = alpha > 0.0f ? v / alpha : 0.0f;
      if (!encode)
        o[c] = quantize(v);
      else if constexpr (sizeof(T) == 1)
        o[c] = detail::encode_srgb8(enc, v);
      else
        o[c] = quantize(v > 0.0f ? static_cast<float>(linear_to_srgb(std::min(static_cast<double>(v), 1.0))) : 0.0f);
    }
  }
  return out;
}

}  // namespace

void write_image(const std::string& path, const Image& im, const WriteOptions& options) {
  const std::string ext = lower_extension(path);
  const bool png = ext == ".png";
  const bool jpeg = ext == ".jpg" || ext == ".jpeg";
  const bool floats = ext == ".exr" || ext == ".tif" || ext == ".tiff";
  if (!png && !jpeg && !floats) unwritable(path, "unsupported image format '" + ext + "' (use .png, .jpg or .exr)");
  if (jpeg && options.bits != 8) unwritable(path, "JPEG holds 8 bits per channel, not " + std::to_string(options.bits));
  if (jpeg && im.channels != 1 && im.channels != 3)
    unwritable(path, "JPEG holds 1 or 3 channels (no alpha); this image has " + std::to_string(im.channels));
  if (im.width < 1 || im.height < 1 || im.channels < 1 ||
      im.pixels.size() != std::size_t(im.width) * std::size_t(im.height) * std::size_t(im.channels))
    unwritable(path, "image has no pixels or a wrong buffer size");
  if (png && im.channels > 4)
    unwritable(path, "PNG holds 1 to 4 channels; this image has " + std::to_string(im.channels));
  if (png && options.bits != 8 && options.bits != 16)
    unwritable(path, "PNG holds 8 or 16 bits per channel, not " + std::to_string(options.bits));

  const OIIO::TypeDesc type = floats ? OIIO::TypeDesc::FLOAT
                              : options.bits == 16 ? OIIO::TypeDesc::UINT16
                                                   : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(im.width, im.height, im.channels, type);
  spec.x = spec.full_x = im.x;
  spec.y = spec.full_y = im.y;
  if (int(im.channel_names.size()) == im.channels) spec.channelnames = im.channel_names;
  spec.alpha_channel = im.alpha_channel < im.channels ? im.alpha_channel : -1;
  spec.attribute("Software", options.software.empty() ? std::string("splinefig ") + SPLINEFIG_VERSION : options.software);
  if (!options.description.empty()) spec.attribute("ImageDescription", options.description);

  Image linear;
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint16_t> words;
  const void* data = nullptr;
  if (floats) {
    spec.attribute("oiio:ColorSpace", "Linear");
    if (ext == ".exr") spec.attribute("compression", "zip");
    if (im.encoding == Encoding::linear) {
      data = im.pixels.data();
    } else {
      linear = to_linear(im);
      data = linear.pixels.data();
    }
  } else {
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the values are straight already
    if (jpeg) spec.attribute("Compression", "jpeg:95");
    if (jpeg) spec.attribute("jpeg:subsampling", "4:4:4");  // no chroma halved at colour edges
    if (options.bits == 16) {
      words = integer_values<std::uint16_t>(im);
      data = words.data();
    } else {
      bytes = integer_values<std::uint8_t>(im);
      data = bytes.data();
    }
  }

  std::vector<unsigned char> file;
  OIIO::Filesystem::IOVecOutput memory(file);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) unwritable(path, one_line(OIIO::geterror()));
  if (!out->set_ioproxy(&memory)) unwritable(path, "cannot encode this format in memory");
  if (!out->open(path, spec)) unwritable(path, one_line(out->geterror()));
  const bool ok = out->write_image(type, data);
  const bool closed = out->close();
  if (!ok || !closed || out->has_error()) unwritable(path, one_line(out->geterror()));
  out.reset();
  try {
    write_file_atomically(path, file);
  } catch (const UnwritableFile& e) {
    throw UnwritableImage(e.what());
  }
}

}  // namespace splinefig
