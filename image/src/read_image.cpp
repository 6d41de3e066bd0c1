// Strict image reading: checks here, decoding by the codec module (codec.hpp; see io.hpp).
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>

#include "one_line.hpp"
#include "origin.hpp"
#include "exr_check.hpp"
#include "png_check.hpp"

#include "codec.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <system_error>

namespace splinefig {
namespace {

namespace fs = std::filesystem;
using detail::one_line;

// The PNG checks apply from the signature's first four bytes: libpng (which OpenImageIO also
// tries on files of other names) takes a file starting "\x89PNG" for a damaged PNG and prints
// "libpng error: PNG file corrupted by ASCII conversion" on stderr; check_png_header refuses it.
bool has_png_signature(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[4] = {};
  in.read(reinterpret_cast<char*>(head), 4);
  static constexpr unsigned char signature[4] = {0x89, 'P', 'N', 'G'};
  return in.gcount() == 4 && std::memcmp(head, signature, 4) == 0;
}

bool iequals(const std::string& a, const std::string& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

[[noreturn]] void unreadable(const std::string& path, const std::string& why) {
  throw UnreadableImage(path + ": " + (why.empty() ? std::string("unknown error") : why));
}

// A path that does not exist, or that cannot be followed (a symlink loop, a directory on the way
// that cannot be searched): said as such, not as missing.
void check_exists(const std::string& path, const fs::file_status& st, const std::error_code& ec) {
  if (fs::exists(st)) return;
  if (ec && st.type() != fs::file_type::not_found) unreadable(path, "cannot open the file (" + ec.message() + ")");
  unreadable(path, "no such file");
}

// An existing regular file this process may open, else why not (no such file, a directory,
// the system's reason such as Permission denied): the same words for read_image and the header
// check, before OpenImageIO, whose message would not say why.
void check_readable_file(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  check_exists(path, st, ec);
  if (fs::is_directory(st)) unreadable(path, "is a directory");
  if (!fs::is_regular_file(st)) unreadable(path, "not a regular file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) unreadable(path, std::string("cannot open file (") + std::strerror(errno) + ")");
}

// Colour channels of straight (unassociated) values: sRGB-decoded when `srgb`, then
// multiplied by alpha when `associate`.
void to_linear_associated(Image& im, bool srgb, bool associate, int bits) {
  const auto& table = srgb8_decode_table();
  const int C = im.channels, a = im.alpha_channel;
  for (std::size_t p = 0; p < im.pixels.size(); p += std::size_t(C)) {
    float* px = im.pixels.data() + p;
    const float alpha = (associate && a >= 0) ? px[a] : 1.0f;
    for (int c = 0; c < C; ++c) {
      if (c == a) continue;
      float v = px[c];
      if (srgb)
        v = bits == 8 ? table[std::size_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f))]
                      : static_cast<float>(srgb_to_linear(static_cast<double>(v)));
      px[c] = v * alpha;
    }
  }
}

const detail::ImageCodec& load_codec(const std::string& path) {
  try {
    return detail::image_codec();
  } catch (const std::exception& e) {
    unreadable(path, e.what());
  }
}

// The header's size against the limits (io.hpp); the number of values.
std::uint64_t check_size(const std::string& path, const detail::CodecHeader& spec) {
  const std::uint64_t pixels = std::uint64_t(spec.width) * std::uint64_t(spec.height);
  const std::uint64_t values = pixels * std::uint64_t(spec.channels);
  if (values > kMaxImageValues || pixels > kMaxImagePixels)
    unreadable(path, "image too large (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                         std::to_string(spec.channels) + " values, limit 2^28 pixels and 2^30 values)");
  if (std::uint64_t(spec.width) > kMaxImageSide || std::uint64_t(spec.height) > kMaxImageSide)
    unreadable(path, "image too large (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                         " pixels, limit 65536 a side)");
  if (std::string problem = detail::origin_problem(spec.x, spec.y); !problem.empty()) unreadable(path, problem);
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (!ec && values > std::uint64_t(bytes) * kMaxImageValuesPerByte)
    unreadable(path, "the header declares " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                         std::to_string(spec.channels) + " values, more than a file of " + std::to_string(bytes) +
                         " bytes can hold (truncated or corrupt)");
  return values;
}

}  // namespace

void check_image_header(const std::string& path) {
  check_readable_file(path);
  if (has_png_signature(path)) {
    check_png_header(path);
    return;
  }
  if (has_exr_signature(path)) check_exr_header(path);
  const detail::ImageCodec& codec = load_codec(path);
  detail::CodecHeader spec;
  std::string error;
  std::unique_ptr<void, void (*)(void*)> in(codec.open(path.c_str(), false, spec, error), codec.close);
  if (!in) unreadable(path, one_line(error));
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0) unreadable(path, "empty image");
  check_size(path, spec);
}

Image read_image(const std::string& path, ReadMode mode, FileFormat* format) {
  check_readable_file(path);
  if (has_png_signature(path)) {
    check_png_header(path);  // the declared size first: nothing is inflated for an oversized image
    check_png_structure(path);
  }
  if (has_exr_signature(path)) check_exr_header(path);  // no attribute larger than the file

  const detail::ImageCodec& codec = load_codec(path);
  detail::CodecHeader spec;
  std::string error;
  // Linear reading associates alpha itself, after decoding the straight values.
  std::unique_ptr<void, void (*)(void*)> in(codec.open(path.c_str(), mode == ReadMode::linear, spec, error), codec.close);
  if (!in) unreadable(path, one_line(error));
  try {
    if (spec.deep) unreadable(path, "deep images are not supported");
    if (spec.depth > 1) unreadable(path, "volume images are not supported");
    if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0)
      unreadable(path, "empty image (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) + ", " +
                           std::to_string(spec.channels) + " channels)");
    const std::uint64_t values = check_size(path, spec);
    Image im;
    im.width = spec.width;
    im.height = spec.height;
    im.channels = spec.channels;
    im.x = spec.x;
    im.y = spec.y;
    im.channel_names = spec.channel_names;
    im.channel_names.resize(std::size_t(im.channels));
    const auto defaults = default_channel_names(im.channels);
    for (int c = 0; c < im.channels; ++c)
      if (im.channel_names[std::size_t(c)].empty()) im.channel_names[std::size_t(c)] = defaults[std::size_t(c)];
    im.alpha_channel = spec.alpha_channel < im.channels ? spec.alpha_channel : -1;
    const bool integer = !spec.floating;
    const bool srgb = integer && !iequals(spec.color_space, "linear");
    im.encoding = srgb ? Encoding::srgb : Encoding::linear;
    const int bits = spec.bits;
    if (format) *format = FileFormat{spec.format_name, bits};
    try {
      im.pixels.resize(std::size_t(values));
    } catch (const std::bad_alloc&) {
      unreadable(path, "image too large to hold in memory");
    }
    bool straight = false;
    if (!codec.read(in.get(), im.pixels.data(), straight, error))
      unreadable(path, one_line(error.empty() ? "cannot read pixel data" : error));
    in.reset();
    if (mode == ReadMode::linear && (srgb || straight)) {
      to_linear_associated(im, srgb, straight, bits);
      im.encoding = Encoding::linear;
    }
    return im;
  } catch (const UnreadableImage&) {
    throw;
  } catch (const std::bad_alloc&) {
    unreadable(path, "image too large to hold in memory");
  } catch (const std::exception& e) {
    unreadable(path, one_line(e.what()));
  }
}

}  // namespace splinefig
