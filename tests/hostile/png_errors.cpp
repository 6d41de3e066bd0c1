// A PNG that libpng would stop at with an error of its own (a row filter type over 4, a chunk
// type that is not letters, an unknown critical chunk, a second IHDR or PLTE, a bad or missing
// palette) is refused by the reader's check before libpng sees it: libpng prints its errors on
// stderr ("libpng error: ..."), a second line besides splinefig's. Each case: exit 4 from diff,
// one line, the check's words, no "libpng" and no "PNG read error".
#include "hostile.hpp"

#include <zlib.h>

#include <cstdint>

using namespace splinefig::hostile;

namespace {

std::string be32(std::uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

std::string chunk(const std::string& type, const std::string& data) {
  const std::string td = type + data;
  const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(td.data()), uInt(td.size()));
  return be32(std::uint32_t(data.size())) + td + be32(std::uint32_t(crc));
}

std::string deflated(const std::string& raw) {
  uLongf n = compressBound(uLong(raw.size()));
  std::string out(n, '\0');
  compress(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
  out.resize(n);
  return out;
}

// A w x h 8-bit PNG of colour type `ct` (interlaced when `adam7`), `pre` before its IDAT,
// `post` after it, the filtered scanlines `rows` as given.
std::string png(std::uint32_t w, std::uint32_t h, int ct, const std::string& rows, const std::string& pre = "",
                const std::string& post = "", bool adam7 = false) {
  const std::string ihdr = be32(w) + be32(h) + std::string{8, char(ct), 0, 0, char(adam7)};
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + pre + chunk("IDAT", deflated(rows)) + post +
         chunk("IEND", "");
}

const std::string kRgbRow = std::string(7, '\0');  // filter 0, two black RGB pixels

void check_png_refused(const std::string& name, const std::string& bytes, const std::string& says) {
  const fs::path dir = scratch();
  write_file(dir / (name + ".png"), bytes);
  const Outcome o = run_in(dir, {"diff", name + ".png", name + ".png"});
  INFO(name << ": " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == 4);
  CHECK(splinefig::test::count_lines(o.err) == 1);
  CHECK(o.err == "splinefig diff: cannot read " + name + ".png: corrupt PNG (" + says + ")\n");
  CHECK(o.err.find("libpng") == std::string::npos);
  fs::remove_all(dir);
}

}  // namespace

TEST_CASE("a PNG row filter type over 4 is refused by the check, in plain and Adam7 images") {
  check_png_refused("filter5", png(2, 1, 2, std::string(1, '\x05') + std::string(6, '\0')),
                "row filter type 5 at byte 0 of the pixel data, not 0 to 4");
  check_png_refused("filter_row2", png(2, 2, 2, kRgbRow + "\x07" + std::string(6, '\0')),
                "row filter type 7 at byte 7 of the pixel data, not 0 to 4");
  // 2 x 2 Adam7: pass 1 is pixel (0,0) (4 bytes with its filter byte), pass 6 pixel (1,0), pass 7 row 1.
  check_png_refused("filter_adam7",
                png(2, 2, 2, std::string(4, '\0') + "\x09" + std::string(3, '\0') + std::string(7, '\0'), "", "", true),
                "row filter type 9 at byte 4 of the pixel data, not 0 to 4");
}

TEST_CASE("PNG chunks libpng stops at are refused by the check") {
  check_png_refused("type_digit", png(2, 1, 2, kRgbRow, chunk("a1cd", "")), "chunk type a1cd at byte 33 is not four letters");
  check_png_refused("critical", png(2, 1, 2, kRgbRow, chunk("ABCD", "")), "unknown critical chunk ABCD");
  check_png_refused("critical_after", png(2, 1, 2, kRgbRow, "", chunk("ABCD", "")), "unknown critical chunk ABCD");
  const std::string ihdr = chunk("IHDR", be32(2) + be32(1) + std::string{8, 2, 0, 0, 0});
  check_png_refused("ihdr2", png(2, 1, 2, kRgbRow, ihdr), "a second IHDR chunk");
  const std::string plte = chunk("PLTE", std::string(3, '\x10'));
  check_png_refused("plte2", png(2, 1, 2, kRgbRow, plte + plte), "a second PLTE chunk");
  check_png_refused("no_plte", png(2, 1, 3, std::string(3, '\0')), "a palette image with no PLTE chunk before its pixel data");
  check_png_refused("plte0", png(2, 1, 3, std::string(3, '\0'), chunk("PLTE", "")),
                "PLTE of 0 bytes: not 1 to 256 three-byte entries");
  check_png_refused("plte4", png(2, 1, 3, std::string(3, '\0'), chunk("PLTE", std::string(4, '\0'))),
                "PLTE of 4 bytes: not 1 to 256 three-byte entries");
  check_png_refused("plte257", png(2, 1, 3, std::string(3, '\0'), chunk("PLTE", std::string(3 * 257, '\0'))),
                "PLTE of 771 bytes: not 1 to 256 three-byte entries");
}

TEST_CASE("valid PNGs the new checks look at still read: every filter type, Adam7, a palette") {
  const fs::path dir = scratch();
  // Rows with filters 1 to 4 over zero bytes decode to zeros.
  write_file(dir / "filters.png", png(2, 4, 2, std::string(1, '\x01') + std::string(6, '\0') + "\x02" + std::string(6, '\0') + "\x03" +
                                                   std::string(6, '\0') + "\x04" + std::string(6, '\0')));
  write_file(dir / "adam7.png", png(2, 2, 2, std::string(4, '\0') + "\x04" + std::string(3, '\0') + std::string(7, '\0'), "", "", true));
  write_file(dir / "palette.png", png(2, 1, 3, std::string(3, '\0'), chunk("PLTE", "\x10\x20\x30") + chunk("tEXt", std::string("k\0v", 3))));
  for (const char* f : {"filters.png", "adam7.png", "palette.png"}) {
    const Outcome o = run_in(dir, {"diff", f, f});
    INFO(f << ": " << o.err);
    CHECK(o.code == 0);
    CHECK(o.err.empty());
  }
  fs::remove_all(dir);
}

// Found by fuzz_resample: a file starting "\x89PNG" but not with the whole signature reached
// libpng (under any name: OpenImageIO tries its PNG reader on unknown files too), which printed
// "libpng error: PNG file corrupted by ASCII conversion".
TEST_CASE("a file with a damaged PNG signature is refused by the check, whatever its name") {
  const std::string bad_end = std::string("\x89PNG\r\n\x1a\x02", 8) + "IHDR" + std::string(24, 'x');
  const std::string cut = std::string("\x89PNG\r\n\x1a", 7);
  for (const auto& [name, bytes] : {std::pair<std::string, std::string>{"sig_end", bad_end}, {"sig_cut", cut}})
    for (const char* ext : {".png", ".dat"}) {
      const fs::path dir = scratch();
      write_file(dir / (name + ext), bytes);
      const Outcome o = run_in(dir, {"diff", name + ext, name + ext});
      INFO(name << ext << ": " << o.err);
      CHECK(o.code == 4);
      CHECK(o.err == "splinefig diff: cannot read " + name + ext + ": not a PNG file (bad signature or no IHDR chunk)\n");
      fs::remove_all(dir);
    }
}
