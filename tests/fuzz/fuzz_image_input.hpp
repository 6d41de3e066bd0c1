#pragma once
// Shared by the image harnesses: fuzzer bytes written to a private temporary file named by
// the format their first bytes announce (PNG, OpenEXR; others as .img), since the image
// reader takes paths, as the command line does. A PNG's chunk CRCs are rewritten first, so
// that mutated chunks (png.dict) reach the decoder rather than stop at the CRC check.
#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

namespace splinefig::fuzz {

inline std::string image_file(const char* tag, const std::uint8_t* data, std::size_t size) {
  static const unsigned char png[4] = {0x89, 'P', 'N', 'G'}, exr[4] = {0x76, 0x2f, 0x31, 0x01};
  const char* ext = ".img";
  if (size >= 4 && std::memcmp(data, png, 4) == 0) ext = ".png";
  if (size >= 4 && std::memcmp(data, exr, 4) == 0) ext = ".exr";
  std::string bytes(reinterpret_cast<const char*>(data), size);
  if (std::strcmp(ext, ".png") == 0) {
    auto be32 = [&](std::size_t at) {
      std::uint32_t v = 0;
      for (int i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
      return v;
    };
    for (std::size_t pos = 8; pos + 12 <= bytes.size();) {
      const std::size_t length = be32(pos);
      if (length > bytes.size() - pos - 12) break;
      const auto crc = std::uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(bytes.data() + pos + 4), uInt(length + 4)));
      for (int i = 0; i < 4; ++i) bytes[pos + 8 + length + std::size_t(i)] = char(crc >> (24 - 8 * i));
      pos += 12 + length;
    }
  }
  const std::string path = "/tmp/splinefig-fuzz-" + std::to_string(::getpid()) + "-" + tag + ext;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

// An UnreadableImage message must be one line, and a PNG decoding error must have been caught
// by the reader's own check (png_check.cpp) before libpng met it: libpng also prints its errors
// on stderr, a second line besides the message ("PNG read error" is OpenImageIO's wording of one).
// Only a file with the PNG signature (named .png above) reaches libpng's decoder; in any other
// file's message those words can only be quoted from the file, as in an OpenEXR attribute name.
inline const char* bad_message(const std::string& m) {
  if (m.find('\n') != std::string::npos) return "a message of more than one line";
  const std::size_t colon = m.find(": ");
  const bool png_file = colon != std::string::npos && colon >= 4 && m.compare(colon - 4, 4, ".png") == 0;
  if (png_file && (m.find("PNG read error") != std::string::npos || m.find("PNG library error") != std::string::npos))
    return "a libpng error that the PNG check let through";
  return nullptr;
}

// Splits the input at a 2-byte big-endian length prefix: the first image, then the second.
inline bool split_pair(const std::uint8_t* data, std::size_t size, std::size_t& first) {
  if (size < 2) return false;
  first = (std::size_t(data[0]) << 8 | data[1]);
  return first <= size - 2;
}

}  // namespace splinefig::fuzz
