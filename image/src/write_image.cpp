// Image writing: the conversion to the file's encoding, encoding into memory by the codec module
// (codec.hpp), and an atomic publication of the bytes (see io.hpp).
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>
#include <splinefig/base/extension.hpp>
#include <splinefig/version.hpp>

#include "one_line.hpp"

#include "codec.hpp"
#include "png_encode.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <string>

namespace splinefig {
namespace {

using detail::one_line;

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
    // Figures are mostly runs of one colour: a pixel equal to the one before (bit for bit)
    // gets the same values.
    if (p != 0 && (C == 4 ? std::memcmp(px, px - 4, 16) == 0 : std::memcmp(px, px - C, sizeof(float) * std::size_t(C)) == 0)) {
      std::memcpy(o, o - C, sizeof(T) * std::size_t(C));
      continue;
    }
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

// "YYYY:MM:DD HH:MM:SS" (TIFF and EXIF's form, in UTC) for seconds since 1970; "" when negative
// or past year 9999.
std::string exif_date(long long seconds) {
  if (seconds < 0 || seconds > 253402300799LL) return "";
  const std::time_t t = static_cast<std::time_t>(seconds);
  std::tm tm{};
  if (!gmtime_r(&t, &tm)) return "";
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y:%m:%d %H:%M:%S", &tm);
  return buf;
}

}  // namespace

std::optional<ImageFormat> image_format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == "png") return ImageFormat::png;
  if (ext == "jpg" || ext == "jpeg") return ImageFormat::jpeg;
  if (ext == "tif" || ext == "tiff") return ImageFormat::tiff;
  if (ext == "exr") return ImageFormat::exr;
  return std::nullopt;
}

std::vector<std::uint8_t> srgb8_values(const Image& im) { return integer_values<std::uint8_t>(im); }

void write_image(const std::string& path, const Image& im, const WriteOptions& options) {
  const auto format = image_format_of(path);
  if (!format)
    unwritable(path, "unsupported image format '." + lower_extension(path) + "' (use .png, .jpg, .tif or .exr)");
  write_image(path, im, *format, options);
}

void write_image(const std::string& path, const Image& im, ImageFormat format, const WriteOptions& options) {
  const bool png = format == ImageFormat::png;
  const bool jpeg = format == ImageFormat::jpeg;
  const bool tiff = format == ImageFormat::tiff;
  const bool exr = format == ImageFormat::exr;
  const bool floats = exr || (tiff && options.bits == 32);
  if (tiff && options.bits != 8 && options.bits != 16 && options.bits != 32)
    unwritable(path, "TIFF is written with 8 or 16 bits per channel or as float (32), not " + std::to_string(options.bits));
  if (jpeg && options.bits != 8) unwritable(path, "JPEG holds 8 bits per channel, not " + std::to_string(options.bits));
  if (jpeg && im.channels != 1 && im.channels != 3)
    unwritable(path, "JPEG holds 1 or 3 channels (no alpha); this image has " + std::to_string(im.channels));
  if (im.width < 1 || im.height < 1 || im.channels < 1 ||
      im.pixels.size() != std::size_t(im.width) * std::size_t(im.height) * std::size_t(im.channels))
    unwritable(path, "image has no pixels or a wrong buffer size");
  if (im.alpha_channel < -1 || im.alpha_channel >= im.channels)
    unwritable(path, "alpha channel " + std::to_string(im.alpha_channel) + " is not one of the image's " +
                         std::to_string(im.channels) + " channels (or -1 for none)");
  if (png && im.channels > 4)
    unwritable(path, "PNG holds 1 to 4 channels; this image has " + std::to_string(im.channels));
  if (png && options.bits != 8 && options.bits != 16)
    unwritable(path, "PNG holds 8 or 16 bits per channel, not " + std::to_string(options.bits));

  detail::CodecImage spec;
  spec.width = im.width;
  spec.height = im.height;
  spec.channels = im.channels;
  spec.x = im.x;
  spec.y = im.y;
  if (int(im.channel_names.size()) == im.channels) spec.channel_names = im.channel_names;
  spec.alpha_channel = im.alpha_channel;
  spec.type = floats ? detail::CodecType::f32 : options.bits == 16 ? detail::CodecType::u16 : detail::CodecType::u8;
  auto& text = spec.string_attributes;
  text.emplace_back("Software", options.software.empty() ? std::string("splinefig ") + SPLINEFIG_VERSION : options.software);
  if (!options.description.empty()) text.emplace_back("ImageDescription", options.description);
  // OpenImageIO stamps EXR and TIFF files with the current time unless DateTime is given; an
  // empty one writes none.
  text.emplace_back("DateTime", exif_date(options.date));
  if (options.dpi > 0) {  // PNG pHYs, EXR and TIFF resolution attributes
    spec.float_attributes.emplace_back("XResolution", static_cast<float>(options.dpi));
    spec.float_attributes.emplace_back("YResolution", static_cast<float>(options.dpi));
    text.emplace_back("ResolutionUnit", "in");
  }

  Image linear;
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint16_t> words;
  if (floats) {
    text.emplace_back("oiio:ColorSpace", "Linear");
    if (exr) text.emplace_back("compression", "zip");
    if (im.encoding == Encoding::linear) {
      spec.data = im.pixels.data();
    } else {
      linear = to_linear(im);
      spec.data = linear.pixels.data();
    }
  } else {
    text.emplace_back("oiio:ColorSpace", "sRGB");
    spec.int_attributes.emplace_back("oiio:UnassociatedAlpha", 1);  // the values are straight already
    // zlib level 4 without row filters: for figures (flat colour, sharp edges) as small as
    // libpng's default (level 6, adaptive filters; +3% over the built-in figures) and twice
    // as fast to encode.
    spec.int_attributes.emplace_back("png:compressionLevel", 4);
    spec.int_attributes.emplace_back("png:filter", 8);  // PNG_FILTER_NONE
    if (tiff) text.emplace_back("compression", "zip");
    if (jpeg) text.emplace_back("Compression", "jpeg:95");
    if (jpeg) text.emplace_back("jpeg:subsampling", "4:4:4");  // no chroma halved at colour edges
    if (options.bits == 16) {
      words = integer_values<std::uint16_t>(im);
      spec.data = words.data();
    } else {
      bytes = integer_values<std::uint8_t>(im);
      spec.data = bytes.data();
    }
  }

  std::vector<unsigned char> file;
  std::string error;
  if (png) {
    // libpng directly: writing a PNG does not load the image I/O module.
    if (!detail::encode_png(spec, file, error)) unwritable(path, one_line(error));
  } else {
    const detail::ImageCodec* codec = nullptr;
    try {
      codec = &detail::image_codec();
    } catch (const std::exception& e) {
      unwritable(path, e.what());
    }
    const char* name = exr ? "openexr" : tiff ? "tiff" : "jpeg";
    if (!codec->encode(name, spec, file, error)) unwritable(path, one_line(error));
  }
  try {
    write_file_atomically(path, file);
  } catch (const UnwritableFile& e) {
    throw UnwritableImage(e.what());
  }
}

}  // namespace splinefig
