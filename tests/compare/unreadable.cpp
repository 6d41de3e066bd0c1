// Missing, junk, truncated and corrupt files are unreadable: a one-line message naming the
// file, exit code 4, never a comparison of garbage and never a crash.
#include "support.hpp"

#include <splinefig/image/io.hpp>

#include <catch2/catch.hpp>
#include <zlib.h>

using namespace splinefig;
using namespace test_support;

namespace {

std::string q(const std::string& p) { return "'" + p + "'"; }

std::string chunk(const std::string& type, const std::string& body) {
  std::string s;
  const auto be = [&](std::uint32_t v) {
    for (int k = 3; k >= 0; --k) s += char((v >> (8 * k)) & 0xff);
  };
  be(std::uint32_t(body.size()));
  s += type + body;
  uLong crc = crc32(0L, Z_NULL, 0);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(type.data()), 4);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()));
  be(std::uint32_t(crc));
  return s;
}

// An 8 x 8 8-bit greyscale PNG whose IDAT holds `rows` complete filtered rows (8 is valid).
std::string grey_png(int rows) {
  std::string ihdr = {0, 0, 0, 8, 0, 0, 0, 8, 8, 0, 0, 0, 0};
  std::string raw;
  for (int y = 0; y < rows; ++y) {
    raw += char(0);  // filter type None
    for (int x = 0; x < 8; ++x) raw += char(x * 32);
  }
  uLongf size = compressBound(uLong(raw.size()));
  std::string z(size, '\0');
  compress(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
  z.resize(size);
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", z) + chunk("IEND", "");
}

// Exit code 4, one line on stderr that names `file`, nothing on stdout but "Comparing" lines.
void check_unreadable(const std::string& good, const std::string& bad) {
  const Run r = run_splinefig("diff " + q(good) + " " + q(bad));
  INFO(r.err);
  CHECK(r.code == 4);
  CHECK(r.err.find(bad) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.out.find("PASS") == std::string::npos);
  CHECK_THROWS_AS(read_image(bad), UnreadableImage);
}

}  // namespace

TEST_CASE("a complete hand-made PNG loads with OpenImageIO's values") {
  const std::string good = scratch("hand_good.png");
  write_bytes(good, grey_png(8));
  const Image im = read_image(good);
  CHECK(im.width == 8);
  CHECK(im.channels == 1);
  CHECK(im.at(3, 5, 0) == Approx(96.0 / 255.0).epsilon(1e-7));
}

TEST_CASE("missing files and junk are unreadable") {
  const std::string good = scratch("hand_good.png");
  write_bytes(good, grey_png(8));
  check_unreadable(good, scratch("does_not_exist.png"));
  const std::string junk_png = scratch("junk.png"), junk_exr = scratch("junk.exr");
  write_bytes(junk_png, "this is not an image\n");
  write_bytes(junk_exr, "this is not an image either\n");
  check_unreadable(good, junk_png);
  check_unreadable(good, junk_exr);
  // The first file is checked first.
  CHECK(run_splinefig("diff " + q(junk_png) + " " + q(good)).err.find(junk_png) != std::string::npos);
}

TEST_CASE("PNGs truncated in the header or the pixel data, or corrupt, are unreadable") {
  const std::string good = scratch("hand_good.png");
  const std::string bytes = grey_png(8);
  write_bytes(good, bytes);
  const std::string head = scratch("trunc_head.png"), mid = scratch("trunc_idat.png"), crc = scratch("bad_crc.png");
  write_bytes(head, bytes.substr(0, 20));
  write_bytes(mid, bytes.substr(0, 33 + 8 + 20));  // inside the IDAT chunk
  std::string flipped = bytes;
  flipped[33 + 8 + 4] = char(flipped[33 + 8 + 4] ^ 0x55);  // a byte of compressed data
  write_bytes(crc, flipped);
  check_unreadable(good, head);
  check_unreadable(good, mid);
  check_unreadable(good, crc);
}

TEST_CASE("a PNG whose compressed pixel data ends early is unreadable, though its chunks are intact") {
  // Every chunk and CRC is valid; the zlib stream ends after 5 of 8 rows. libpng calls this
  // a benign error, so a plain decode returns rows of garbage.
  const std::string good = scratch("hand_good.png"), short_rows = scratch("short_rows.png");
  write_bytes(good, grey_png(8));
  write_bytes(short_rows, grey_png(5));
  try {
    check_png_structure(short_rows);
    FAIL("no error");
  } catch (const UnreadableImage& e) {
    CHECK(std::string(e.what()).find("pixel data ends after 45 of 72 bytes") != std::string::npos);
  }
  check_unreadable(good, short_rows);
}

TEST_CASE("EXRs truncated in the header or the pixel data are unreadable") {
  const std::string good = scratch("trunc_good.exr");
  std::vector<float> v(64 * 64 * 4);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i % 251) / 251.0f;
  write_raw(good, 64, 64, 4, v, OIIO::TypeHalf);
  const std::string bytes = read_text(good);
  const std::string head = scratch("trunc_head.exr"), mid = scratch("trunc_pixels.exr");
  write_bytes(head, bytes.substr(0, 60));
  write_bytes(mid, bytes.substr(0, bytes.size() * 2 / 3));
  check_unreadable(good, head);
  check_unreadable(good, mid);
}
