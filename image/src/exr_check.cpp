// OpenEXR file layout (openexr.com, "OpenEXR File Layout"): magic 76 2f 31 01, a 4-byte version
// field (bits 0-7 the version, 0x200 tiled, 0x400 long names, 0x800 deep, 0x1000 multi-part),
// then the header: attributes, each a name (NUL-terminated, at most 31 or 255 bytes), a type
// name likewise, a little-endian int32 size and that many bytes, ended by an empty name. A
// multi-part file has several headers, the list ended by one more empty name.
#include "exr_check.hpp"
#include "origin.hpp"

#include <splinefig/image/io.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace splinefig {
namespace {

[[noreturn]] void bad(const std::string& path, const std::string& why) { throw UnreadableImage(path + ": " + why); }

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 26;  // headers are a few KB in practice

}  // namespace

bool has_exr_signature(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[4] = {};
  in.read(reinterpret_cast<char*>(head), 4);
  return in.gcount() == 4 && std::memcmp(head, kMagic, 4) == 0;
}

void check_exr_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path, "cannot open file");
  in.seekg(0, std::ios::end);
  const std::uint64_t file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(file_size, kMaxHeaderBytes));
  std::vector<unsigned char> d(n);
  in.read(reinterpret_cast<char*>(d.data()), static_cast<std::streamsize>(n));
  if (n < 8 || std::memcmp(d.data(), kMagic, 4) != 0) bad(path, "not an OpenEXR file (bad magic number)");
  const std::uint32_t flags = d[4] | d[5] << 8 | d[6] << 16 | std::uint32_t(d[7]) << 24;
  const std::size_t max_name = (flags & 0x400) ? 255 : 31;
  const bool multipart = flags & 0x1000;
  std::size_t i = 8;
  auto name = [&](const char* what) {
    const std::size_t start = i;
    while (i < n && d[i] != 0) ++i;
    if (i >= n) bad(path, "truncated OpenEXR header (in an attribute " + std::string(what) + ")");
    if (i - start > max_name) bad(path, "corrupt OpenEXR header (an attribute " + std::string(what) + " over " + std::to_string(max_name) + " bytes)");
    ++i;
    return i - start - 1;
  };
  for (;;) {  // one header per pass
    for (;;) {
      if (i >= n) bad(path, "truncated OpenEXR header");
      if (d[i] == 0) {  // the empty name that ends this header
        ++i;
        break;
      }
      const std::size_t name_start = i;
      name("name");
      const std::size_t type_start = i;
      name("type");
      if (i + 4 > n) bad(path, "truncated OpenEXR header (an attribute size)");
      const std::int32_t size = static_cast<std::int32_t>(d[i] | d[i + 1] << 8 | d[i + 2] << 16 | std::uint32_t(d[i + 3]) << 24);
      i += 4;
      if (size < 0 || static_cast<std::uint64_t>(size) > file_size - i) {
        std::string attr(reinterpret_cast<const char*>(&d[name_start]));
        for (char& c : attr)
          if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
        bad(path, "corrupt OpenEXR header (attribute '" + attr + "' declares " + std::to_string(size) +
                      " bytes, more than the file holds)");
      }
      if (static_cast<std::uint64_t>(size) > n - i) bad(path, "OpenEXR header larger than 64 MiB");
      // The data window against the limits before OpenEXR sizes its buffers by it: a window
      // 16775427 px wide made it allocate 2 GB while opening the file.
      if (std::strcmp(reinterpret_cast<const char*>(&d[name_start]), "dataWindow") == 0 &&
          std::strcmp(reinterpret_cast<const char*>(&d[type_start]), "box2i") == 0 && size == 16) {
        std::int32_t box[4];
        for (int k = 0; k < 4; ++k)
          box[k] = static_cast<std::int32_t>(d[i + 4 * k] | d[i + 4 * k + 1] << 8 | d[i + 4 * k + 2] << 16 |
                                             std::uint32_t(d[i + 4 * k + 3]) << 24);
        const std::int64_t w = std::int64_t(box[2]) - box[0] + 1, h = std::int64_t(box[3]) - box[1] + 1;
        // The words of read_image's own check (read_image.cpp), which comes later for other formats.
        const std::string size_text = std::to_string(w) + " x " + std::to_string(h) + " pixels";
        if (w > 0 && h > 0 && (w > std::int64_t(kMaxImageSide) || h > std::int64_t(kMaxImageSide)))
          bad(path, "image too large (" + size_text + ", limit 65536 a side)");
        if (w > 0 && h > 0 && std::uint64_t(w * h) > kMaxImagePixels) bad(path, "image too large (" + size_text + ", limit 2^28 pixels)");
        if (std::string problem = detail::origin_problem(box[0], box[1]); !problem.empty()) bad(path, problem);
      }
      i += static_cast<std::size_t>(size);
    }
    if (!multipart) return;
    if (i >= n) bad(path, "truncated OpenEXR header (multi-part list)");
    if (d[i] == 0) return;  // the empty header that ends the list
  }
}

}  // namespace splinefig
