// Structural check of a PNG file (ISO/IEC 15948, W3C PNG 2nd edition): signature, chunk
// lengths and CRCs, IHDR, and the IDAT zlib stream inflated to its end, whose size must be the
// exact filtered-scanline size that IHDR implies (section 7.2 for the row layout, 8.2 for the
// Adam7 passes). libpng treats "not enough image data" as a benign error, so a PNG cut inside
// its pixel data can decode to garbage rows without failing: this check is what catches it.
// It also refuses what libpng would stop at with an error of its own (chunk types that are not
// letters, an unknown critical chunk, a second IHDR or PLTE, a palette image without a valid
// PLTE before its pixels, a row filter type over 4): libpng prints those on stderr besides
// failing, a second line next to ours, so they must not reach it.
#include "png_check.hpp"
#include "origin.hpp"

#include <splinefig/image/io.hpp>

#include <zlib.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

namespace splinefig {
namespace {

std::uint32_t be32(const unsigned char* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | std::uint32_t(p[3]);
}

int png_channels(int colour_type) {
  switch (colour_type) {
    case 0: return 1;  // greyscale
    case 2: return 3;  // truecolour
    case 3: return 1;  // indexed
    case 4: return 2;  // greyscale + alpha
    case 6: return 4;  // truecolour + alpha
    default: return 0;
  }
}

bool valid_depth(int colour_type, int depth) {
  switch (colour_type) {
    case 0: return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
    case 3: return depth == 1 || depth == 2 || depth == 4 || depth == 8;
    case 2: case 4: case 6: return depth == 8 || depth == 16;
    default: return false;
  }
}

// The passes of the image's filtered scanlines (one, or Adam7's seven less the empty ones):
// bytes per row (the filter byte included) and rows.
struct Pass {
  std::uint64_t row_bytes, rows;
};

std::vector<Pass> scanline_passes(std::uint32_t width, std::uint32_t height, int bits_per_pixel, bool adam7) {
  std::vector<Pass> passes;
  auto add = [&](std::uint64_t w, std::uint64_t h) {
    if (w > 0 && h > 0) passes.push_back({1 + (w * std::uint64_t(bits_per_pixel) + 7) / 8, h});
  };
  if (!adam7) {
    add(width, height);
    return passes;
  }
  // Adam7 passes: starting column/row and step of each of the seven passes.
  static constexpr int xs[7] = {0, 4, 0, 2, 0, 1, 0}, ys[7] = {0, 0, 4, 0, 2, 0, 1};
  static constexpr int dx[7] = {8, 8, 4, 4, 2, 2, 1}, dy[7] = {8, 8, 8, 4, 4, 2, 2};
  for (int p = 0; p < 7; ++p)
    add(width > std::uint32_t(xs[p]) ? (width - xs[p] + dx[p] - 1) / dx[p] : 0,
        height > std::uint32_t(ys[p]) ? (height - ys[p] + dy[p] - 1) / dy[p] : 0);
  return passes;
}

std::uint64_t expected_image_bytes(const std::vector<Pass>& passes) {
  std::uint64_t total = 0;
  for (const Pass& p : passes) total += p.row_bytes * p.rows;
  return total;
}

// The stream offset of each row's filter byte, in order.
class RowStarts {
 public:
  explicit RowStarts(std::vector<Pass> passes) : passes_(std::move(passes)) {}
  bool done() const { return pass_ >= passes_.size(); }
  std::uint64_t next() const { return offset_; }
  void advance() {
    offset_ += passes_[pass_].row_bytes;
    if (++row_ == passes_[pass_].rows) {
      row_ = 0;
      ++pass_;
    }
  }

 private:
  std::vector<Pass> passes_;
  std::size_t pass_ = 0;
  std::uint64_t row_ = 0, offset_ = 0;
};

[[noreturn]] void bad(const std::string& path, const std::string& why) {
  throw UnreadableImage(path + ": " + why);
}

// The declared size against the limits (io.hpp), before any pixel data is inflated.
void check_png_size(const std::string& path, std::uint64_t width, std::uint64_t height, int colour_type) {
  // An indexed image is read as RGB or RGBA.
  const int channels = colour_type == 3 ? 4 : png_channels(colour_type);
  const std::uint64_t pixels = width * height, values = pixels * std::uint64_t(channels);
  if (pixels > kMaxImagePixels || values > kMaxImageValues)
    bad(path, "image too large (" + std::to_string(width) + " x " + std::to_string(height) +
                  " pixels declared in the header, limit 2^28 pixels)");
  if (width > kMaxImageSide || height > kMaxImageSide)
    bad(path, "image too large (" + std::to_string(width) + " x " + std::to_string(height) +
                  " pixels declared in the header, limit 65536 a side)");
}

}  // namespace

void check_png_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[29] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  if (in.gcount() != sizeof head || std::memcmp(head, signature, 8) != 0 || std::memcmp(head + 12, "IHDR", 4) != 0)
    bad(path, "not a PNG file (bad signature or no IHDR chunk)");
  const std::uint32_t w = be32(head + 16), h = be32(head + 20);
  if (w == 0 || h == 0) bad(path, "corrupt PNG (image size " + std::to_string(w) + " x " + std::to_string(h) + ")");
  check_png_size(path, w, h, head[25]);
  // The data window's origin (an oFFs chunk, which comes before the first IDAT) against its
  // limit, as read_image checks it, so that a spec's image is refused at load.
  in.seekg(8 + 12 + 13);
  for (int chunks = 0; chunks < 256 && in; ++chunks) {
    unsigned char ch[8];
    if (!in.read(reinterpret_cast<char*>(ch), sizeof ch)) break;
    const std::uint32_t length = be32(ch);
    if (std::memcmp(ch + 4, "IDAT", 4) == 0 || std::memcmp(ch + 4, "IEND", 4) == 0) break;
    if (std::memcmp(ch + 4, "oFFs", 4) == 0 && length == 9) {
      unsigned char o[8];
      if (!in.read(reinterpret_cast<char*>(o), sizeof o)) break;
      const auto x = static_cast<std::int32_t>(be32(o)), y = static_cast<std::int32_t>(be32(o + 4));
      if (std::string problem = detail::origin_problem(x, y); !problem.empty()) bad(path, problem);
      break;
    }
    in.seekg(std::streamoff(length) + 4, std::ios::cur);
  }
}

void check_png_structure(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path, "cannot open file");
  std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static constexpr unsigned char signature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  if (data.size() < 8 || std::memcmp(data.data(), signature, 8) != 0) bad(path, "not a PNG file (bad signature)");

  std::size_t pos = 8;
  bool have_ihdr = false, have_iend = false, idat_done = false, idat_seen = false;
  std::uint32_t width = 0, height = 0;
  int bits_per_pixel = 0;
  bool adam7 = false;
  int colour_type = 0;
  std::uint64_t expected = 0, produced = 0;
  bool stream_end = false, have_plte = false;
  RowStarts rows({});

  z_stream zs{};
  if (inflateInit(&zs) != Z_OK) bad(path, "zlib initialisation failed");
  struct Guard { z_stream* z; ~Guard() { inflateEnd(z); } } guard{&zs};
  std::array<unsigned char, 1 << 16> sink{};

  while (pos < data.size()) {
    if (data.size() - pos < 12) bad(path, "truncated PNG (incomplete chunk header at byte " + std::to_string(pos) + ")");
    const std::uint32_t length = be32(&data[pos]);
    const unsigned char* type = &data[pos + 4];
    // The chunk type as printable text: a corrupt file's type bytes may be anything.
    std::string tname;
    for (int i = 0; i < 4; ++i) {
      const unsigned char c = type[i];
      if (c >= 0x21 && c < 0x7f) {
        tname.push_back(char(c));
      } else {
        char hex[5];
        std::snprintf(hex, sizeof hex, "\\x%02x", c);
        tname += hex;
      }
    }
    if (length > 0x7fffffffu) bad(path, "corrupt PNG (chunk length out of range at byte " + std::to_string(pos) + ")");
    if (data.size() - pos - 12 < length)
      bad(path, "truncated PNG (chunk " + tname + " at byte " + std::to_string(pos) + " ends past the end of the file)");
    const unsigned char* body = &data[pos + 8];
    for (int i = 0; i < 4; ++i)
      if (!std::isalpha(type[i]) || type[i] >= 0x80)
        bad(path, "corrupt PNG (chunk type " + tname + " at byte " + std::to_string(pos) + " is not four letters)");
    const std::uint32_t crc_stored = be32(body + length);
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, type, 4);
    crc = crc32(crc, body, length);
    if (std::uint32_t(crc) != crc_stored) bad(path, "corrupt PNG (CRC mismatch in chunk " + tname + ")");

    if (!have_ihdr) {
      if (tname != "IHDR" || length != 13) bad(path, "corrupt PNG (first chunk is not IHDR)");
      width = be32(body);
      height = be32(body + 4);
      const int depth = body[8];
      colour_type = body[9];
      if (width == 0 || height == 0 || width > 0x7fffffffu || height > 0x7fffffffu)
        bad(path, "corrupt PNG (image size " + std::to_string(width) + " x " + std::to_string(height) + ")");
      if (!valid_depth(colour_type, depth)) bad(path, "corrupt PNG (invalid bit depth or colour type)");
      check_png_size(path, width, height, colour_type);
      if (body[10] != 0 || body[11] != 0 || body[12] > 1) bad(path, "corrupt PNG (unknown compression, filter or interlace method)");
      bits_per_pixel = png_channels(colour_type) * depth;
      adam7 = body[12] == 1;
      const std::vector<Pass> passes = scanline_passes(width, height, bits_per_pixel, adam7);
      expected = expected_image_bytes(passes);
      rows = RowStarts(passes);
      have_ihdr = true;
    } else if (tname == "IHDR") {
      bad(path, "corrupt PNG (a second IHDR chunk)");
    } else if (tname == "PLTE") {
      if (have_plte) bad(path, "corrupt PNG (a second PLTE chunk)");
      if (!idat_seen && (length == 0 || length % 3 != 0 || length > 3 * 256))
        bad(path, "corrupt PNG (PLTE of " + std::to_string(length) + " bytes: not 1 to 256 three-byte entries)");
      have_plte = true;
    } else if (tname == "IDAT") {
      if (idat_done) bad(path, "corrupt PNG (IDAT chunks are not consecutive)");
      if (colour_type == 3 && !have_plte) bad(path, "corrupt PNG (a palette image with no PLTE chunk before its pixel data)");
      idat_seen = true;
      zs.next_in = const_cast<unsigned char*>(body);
      zs.avail_in = length;
      while (zs.avail_in > 0 && !stream_end) {
        zs.next_out = sink.data();
        zs.avail_out = unsigned(sink.size());
        const int rc = inflate(&zs, Z_NO_FLUSH);
        const std::uint64_t from = produced;
        produced += sink.size() - zs.avail_out;
        // Each row's filter type, 0 (none) to 4 (Paeth).
        for (; !rows.done() && rows.next() < produced; rows.advance())
          if (const unsigned filter = sink[std::size_t(rows.next() - from)]; filter > 4)
            bad(path, "corrupt PNG (row filter type " + std::to_string(filter) + " at byte " + std::to_string(rows.next()) +
                          " of the pixel data, not 0 to 4)");
        if (rc == Z_STREAM_END) {
          stream_end = true;
        } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
          bad(path, std::string("corrupt PNG (bad compressed pixel data: ") + (zs.msg ? zs.msg : "zlib error") + ")");
        }
        if (produced > expected) bad(path, "corrupt PNG (more pixel data than the header implies)");
      }
    } else {
      if (idat_seen) idat_done = true;
      // A critical chunk (first letter upper case) this decoder does not know cannot be skipped.
      if (std::isupper(type[0]) && tname != "IEND")
        bad(path, "corrupt PNG (unknown critical chunk " + tname + ")");
      if (tname == "IEND") {
        have_iend = true;
        break;
      }
    }
    pos += 12 + std::size_t(length);
  }

  if (!have_ihdr) bad(path, "truncated PNG (no IHDR chunk)");
  if (!idat_seen) bad(path, "truncated PNG (no pixel data)");
  if (!stream_end || produced != expected)
    bad(path, "truncated PNG (pixel data ends after " + std::to_string(produced) + " of " + std::to_string(expected) +
                  " bytes)");
  if (!have_iend) bad(path, "truncated PNG (no IEND chunk)");
}

}  // namespace splinefig
