// Strict image loading and atomic image writing through OpenImageIO (see io.hpp).
#include <splinefig/compare/io.hpp>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace splinefig::compare {
namespace {

namespace fs = std::filesystem;

// OpenImageIO error text can span lines; the CLI wants one line.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  for (auto& ch : s)
    if (ch == '\n' || ch == '\t') ch = ' ';
  return s.empty() ? std::string("unknown error") : s;
}

bool has_png_signature(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[8] = {};
  in.read(reinterpret_cast<char*>(head), 8);
  static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  return in.gcount() == 8 && std::memcmp(head, signature, 8) == 0;
}

bool iequals(const std::string& a, const std::string& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

// Reads subimage 0 as float; `straight_alpha` asks OpenImageIO not to premultiply PNG alpha.
Image read_float(const std::string& path, bool straight_alpha, OIIO::TypeDesc* native_format) {
  OIIO::ImageSpec config;
  if (straight_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw UnreadableImage(path + ": " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.deep) throw UnreadableImage(path + ": deep images are not supported");
  if (spec.depth > 1) throw UnreadableImage(path + ": volume images are not supported");
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw UnreadableImage(path + ": empty image (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                          ", " + std::to_string(spec.nchannels) + " channels)");
  const std::uint64_t values = std::uint64_t(spec.width) * std::uint64_t(spec.height) * std::uint64_t(spec.nchannels);
  if (values > max_image_values)
    throw UnreadableImage(path + ": image too large (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                          " x " + std::to_string(spec.nchannels) + " values, limit 2^30)");
  Image im;
  im.width = spec.width;
  im.height = spec.height;
  im.channels = spec.nchannels;
  im.x = spec.x;
  im.y = spec.y;
  im.channel_names = spec.channelnames;
  im.channel_names.resize(std::size_t(im.channels));
  const auto defaults = default_channel_names(im.channels);
  for (int c = 0; c < im.channels; ++c)
    if (im.channel_names[c].empty()) im.channel_names[c] = defaults[c];
  im.alpha_channel = spec.alpha_channel;
  const bool integer = !spec.format.is_floating_point();
  const std::string colorspace = spec.get_string_attribute("oiio:ColorSpace");
  im.encoding = (integer && !iequals(colorspace, "linear")) ? Encoding::srgb : Encoding::linear;
  if (native_format) *native_format = spec.format;
  try {
    im.pixels.resize(std::size_t(values));
  } catch (const std::bad_alloc&) {
    throw UnreadableImage(path + ": image too large to hold in memory");
  }
  const bool ok = in->read_image(0, 0, 0, im.channels, OIIO::TypeFloat, im.pixels.data());
  const bool err = in->has_error();
  const std::string msg = err ? in->geterror() : std::string();
  if (!ok || err) throw UnreadableImage(path + ": " + one_line(msg.empty() ? "cannot read pixel data" : msg));
  in->close();
  return im;
}

}  // namespace

Image load_image(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw UnreadableImage(path + ": no such file");
  if (fs::is_directory(path, ec)) throw UnreadableImage(path + ": is a directory");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw UnreadableImage(path + ": cannot open file (" + std::strerror(errno) + ")");
  }
  if (has_png_signature(path)) check_png_structure(path);
  try {
    OIIO::TypeDesc format;
    Image im = read_float(path, false, &format);
    if (options.linear && im.encoding == Encoding::srgb) {
      // Decode straight (unassociated) values, then associate: sRGB applies to colour, not
      // to colour times alpha.
      Image straight = read_float(path, true, nullptr);
      straight.encoding = Encoding::srgb;
      const int a = straight.alpha_channel;
      for (std::size_t p = 0; p < straight.pixel_count(); ++p) {
        float* px = straight.pixels.data() + p * std::size_t(straight.channels);
        const float alpha = a >= 0 ? px[a] : 1.0f;
        for (int c = 0; c < straight.channels; ++c)
          if (c != a) px[c] = srgb_to_linear(px[c]) * alpha;
      }
      straight.encoding = Encoding::linear;
      return straight;
    }
    return im;
  } catch (const UnreadableImage&) {
    throw;
  } catch (const std::exception& e) {
    throw UnreadableImage(path + ": " + one_line(e.what()));
  }
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (auto& ch : ext) ch = char(std::tolower(ch));
  return ext;
}

// A unique name beside `path` for the temporary file.
std::string temp_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path p(path);
  const std::string stem = p.stem().string();
  const std::string name = "." + stem + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                           p.extension().string();
  return (p.parent_path() / name).string();
}

}  // namespace

void write_image(const std::string& path, const Image& im) {
  if (im.width <= 0 || im.height <= 0 || im.channels <= 0) throw UnwritableImage(path + ": empty image");
  const std::string ext = lower_extension(path);
  const bool is_float_format = ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff";
  OIIO::ImageSpec spec(im.width, im.height, im.channels, is_float_format ? OIIO::TypeFloat : OIIO::TypeUInt8);
  spec.x = im.x;
  spec.y = im.y;
  spec.full_x = im.x;
  spec.full_y = im.y;
  spec.channelnames = im.channel_names;
  spec.channelnames.resize(std::size_t(im.channels));
  spec.alpha_channel = im.alpha_channel;
  // Every conversion is done here; OpenImageIO must not (un)premultiply again.
  spec.attribute("oiio:UnassociatedAlpha", 1);

  std::vector<float> floats;
  std::vector<unsigned char> bytes;
  const void* data = nullptr;
  const int a = im.alpha_channel;
  if (is_float_format) {
    const Image lin = to_linear(im);
    floats = lin.pixels;
    spec.attribute("oiio:ColorSpace", "Linear");
    if (ext == ".exr") spec.attribute("compression", "zip");
    data = floats.data();
  } else {
    bytes.resize(im.pixels.size());
    for (std::size_t p = 0; p < im.pixel_count(); ++p) {
      const float* px = im.pixels.data() + p * std::size_t(im.channels);
      unsigned char* out = bytes.data() + p * std::size_t(im.channels);
      const float alpha = a >= 0 ? px[a] : 1.0f;
      for (int c = 0; c < im.channels; ++c) {
        float v = px[c];
        if (c != a) {
          if (a >= 0) v = alpha > 0.0f ? v / alpha : 0.0f;
          if (im.encoding == Encoding::linear) v = linear_to_srgb(std::clamp(v, 0.0f, 1.0f));
        }
        if (!(v >= 0.0f)) v = 0.0f;  // NaN and negatives
        out[c] = static_cast<unsigned char>(std::lround(std::min(v, 1.0f) * 255.0f));
      }
    }
    spec.attribute("oiio:ColorSpace", "sRGB");
    data = bytes.data();
  }

  const std::string tmp = temp_name(path);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw UnwritableImage(path + ": " + one_line(OIIO::geterror()));
  if (!out->open(tmp, spec)) {
    const std::string msg = out->geterror();
    throw UnwritableImage(path + ": " + one_line(msg.empty() ? std::string("cannot open for writing") : msg));
  }
  const bool ok = out->write_image(is_float_format ? OIIO::TypeFloat : OIIO::TypeUInt8, data);
  const bool closed = out->close();
  if (!ok || !closed || out->has_error()) {
    const std::string msg = out->geterror();
    std::error_code ec;
    fs::remove(tmp, ec);
    throw UnwritableImage(path + ": " + one_line(msg.empty() ? std::string("write failed") : msg));
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw UnwritableImage(path + ": cannot rename temporary file into place");
  }
}

}  // namespace splinefig::compare
