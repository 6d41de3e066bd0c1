#pragma once
// Shared by the image harnesses: fuzzer bytes written to a private temporary file named by
// the format their first bytes announce (PNG, OpenEXR; others as .img), since the image
// reader takes paths, as the command line does.
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
  const std::string path = "/tmp/splinefig-fuzz-" + std::to_string(::getpid()) + "-" + tag + ext;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

// Splits the input at a 2-byte big-endian length prefix: the first image, then the second.
inline bool split_pair(const std::uint8_t* data, std::size_t size, std::size_t& first) {
  if (size < 2) return false;
  first = (std::size_t(data[0]) << 8 | data[1]);
  return first <= size - 2;
}

}  // namespace splinefig::fuzz
