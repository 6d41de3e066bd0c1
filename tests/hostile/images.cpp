// Image inputs are checked from their headers before anything is decoded: a PNG declaring
// 100000 x 100000 pixels and a decompression bomb of a few hundred KB (20000 x 20000 zeros)
// are refused in time with one line, exit 4 for diff ("unreadable", not "the images differ"),
// exit 2 for resample (its code for any error), a FILE:LINE: KEY error for [[image]], and no
// output.
#include "hostile.hpp"

#include <splinefig/image/io.hpp>

#include <zlib.h>

#include <cstdint>

using namespace splinefig::hostile;

namespace {

std::string be32(std::uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  const std::string td = type + data;
  const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(td.data()), uInt(td.size()));
  return be32(std::uint32_t(data.size())) + td + be32(std::uint32_t(crc));
}

// A grey 8-bit PNG of w x h zero pixels whose IDAT holds `rows` rows (all of them: a
// complete, valid file).
std::string zero_png(std::uint32_t w, std::uint32_t h, std::uint32_t rows) {
  z_stream zs{};
  deflateInit(&zs, 9);
  const std::string row(w + 1, '\0');
  std::string out(1 << 16, '\0'), idat;
  for (std::uint32_t r = 0; r <= rows; ++r) {
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(row.data()));
    zs.avail_in = r < rows ? uInt(row.size()) : 0;
    const int flush = r < rows ? Z_NO_FLUSH : Z_FINISH;
    do {
      zs.next_out = reinterpret_cast<Bytef*>(out.data());
      zs.avail_out = uInt(out.size());
      deflate(&zs, flush);
      idat.append(out.data(), out.size() - zs.avail_out);
    } while (zs.avail_out == 0);
  }
  deflateEnd(&zs);
  const std::string ihdr = be32(w) + be32(h) + std::string{8, 0, 0, 0, 0};
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) + chunk("IEND", "");
}

void check_unreadable(const std::vector<std::string>& args, const fs::path& dir, int code, const std::string& says) {
  const Outcome o = run_in(dir, args);
  INFO(args[0] << " (" << o.seconds << " s): " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.code == code);
  CHECK(splinefig::test::count_lines(o.err) == 1);
  CHECK_THAT(o.err, Catch::Contains(says));
  CHECK_FALSE(fs::exists(dir / "out.png"));
}

}  // namespace

TEST_CASE("a PNG header declaring 100000 x 100000 pixels is refused before decoding, by every command") {
  const fs::path dir = scratch();
  write_file(dir / "huge.png", zero_png(100000, 100000, 1));
  write_file(dir / "small.png", zero_png(4, 4, 4));
  const std::string says = "huge.png: image too large (100000 x 100000 pixels declared in the header, limit 2^28 pixels)";
  check_unreadable({"diff", "small.png", "huge.png"}, dir, 4, says);
  check_unreadable({"diff", "huge.png", "small.png"}, dir, 4, says);
  check_unreadable({"resample", "huge.png", "-o", "out.png", "--filter", "bspline", "--size", "8x8"}, dir,
                   2, says);
  fs::remove_all(dir);
  check_refused("huge_image", "[[image]]\nfile = \"" + (fs::temp_directory_path() / "huge.png").string() + "\"\n",
                "no such image file");  // the path is checked first
}

TEST_CASE("a decompression bomb (20000 x 20000 zeros) is refused from its header by diff, resample and specs") {
  const fs::path dir = scratch();
  write_file(dir / "bomb.png", zero_png(20000, 20000, 20000));
  write_file(dir / "small.png", zero_png(4, 4, 4));
  const std::string says = "bomb.png: image too large (20000 x 20000 pixels declared in the header, limit 2^28 pixels)";
  check_unreadable({"diff", "small.png", "bomb.png"}, dir, 4, says);
  check_unreadable({"resample", "bomb.png", "-o", "out.png", "--filter", "bspline", "--size", "8x8"}, dir,
                   2, says);
  write_file(dir / "bomb.toml", "[canvas]\nwidth = 10\nheight = 10\n[[image]]\nfile = \"bomb.png\"\n");
  check_unreadable({"render", "bomb.toml", "-o", "out.png"}, dir, 2, "bomb.toml:5: image[0].file: ./bomb.png: image too large");
  write_file(dir / "bomb_axes.toml", "[axes]\n[[axes.image]]\nfile = \"bomb.png\"\nextent = [0, 1, 0, 1]\n");
  check_unreadable({"render", "bomb_axes.toml", "-o", "out.png"}, dir, 2,
                   "bomb_axes.toml:3: axes.image[0].file: ./bomb.png: image too large");
  fs::remove_all(dir);
}

// Found by fuzz_resample: a PNG whose chunk type bytes hold a newline gave a two-line message.
TEST_CASE("an unreadable PNG's message is one line whatever bytes its chunk types hold") {
  const std::string path = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/hostile/data/png_chunk_type_newline.png";
  try {
    (void)splinefig::read_image(path);
    FAIL("the corrupt PNG was read");
  } catch (const splinefig::UnreadableImage& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
    CHECK_THAT(e.what(), Catch::Contains("corrupt PNG"));
  }
}

// Found by fuzz_resample: OpenEXR headers of a few hundred bytes whose first attribute declares
// about 2 GB; OpenEXR allocated that before finding the file too short.
TEST_CASE("an OpenEXR attribute larger than its file is refused before OpenEXR allocates it") {
  for (int i = 1; i <= 3; ++i) {
    const std::string path = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/hostile/data/exr_attribute_size_" + std::to_string(i) + ".exr";
    INFO(path);
    try {
      (void)splinefig::read_image(path);
      FAIL("the corrupt EXR was read");
    } catch (const splinefig::UnreadableImage& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
      CHECK_THAT(e.what(), Catch::Contains("more than the file holds"));
    }
    CHECK_THROWS_WITH(splinefig::check_image_header(path), Catch::Contains("more than the file holds"));
  }
}

// Found by fuzz_resample: a 457-byte OpenEXR header declaring 2097155 x 3 pixels (within the
// pixel and value limits) for which OpenEXR asked for 4 GiB of scanline buffers.
TEST_CASE("an image wider or taller than 65536 px is refused from its header") {
  const std::string path = std::string(SPLINEFIG_SOURCE_DIR) + "/tests/hostile/data/exr_wide_scanlines.exr";
  CHECK_THROWS_WITH(splinefig::check_image_header(path),
                    Catch::Contains("image too large (2097155 x 3 pixels, limit 65536 a side)"));
  CHECK_THROWS_WITH(splinefig::read_image(path), Catch::Contains("limit 65536 a side"));
}

// Found by fuzz_resample: a 21-byte file that OpenImageIO reads as a TGA header declaring
// 10240 x 25953 RGB pixels (within the pixel and value limits): 3.2 GB of floats were
// allocated before the read found no pixel data.
TEST_CASE("an image declaring more values than its file could hold is refused before it is allocated") {
  const fs::path dir = scratch();
  // An uncompressed true-colour TGA header (18 bytes): type 2, 10240 x 25953, 24 bits.
  std::string tga(18, '\0');
  tga[2] = 2;
  tga[12] = char(10240 & 255), tga[13] = char(10240 >> 8);
  tga[14] = char(25953 & 255), tga[15] = char(25953 >> 8);
  tga[16] = 24;
  write_file(dir / "short.tga", tga + "abc");
  const std::string says = "short.tga: the header declares 10240 x 25953 x 3 values, more than a file of 21 bytes can hold";
  CHECK_THROWS_WITH(splinefig::read_image((dir / "short.tga").string()), Catch::Contains(says));
  CHECK_THROWS_WITH(splinefig::check_image_header((dir / "short.tga").string()), Catch::Contains(says));
  check_unreadable({"resample", "short.tga", "-o", "out.png", "--filter", "bspline", "--size", "8x8"}, dir, 2, says);
  // A complete file compressing 1000:1 (deflate's best on zeros) is read.
  write_file(dir / "zeros.png", zero_png(2000, 2000, 2000));
  INFO(fs::file_size(dir / "zeros.png") << " bytes");
  CHECK(4000000 > fs::file_size(dir / "zeros.png") * 900);
  const splinefig::Image zeros = splinefig::read_image((dir / "zeros.png").string());
  CHECK(zeros.width == 2000);
  CHECK(zeros.pixels.size() == 4000000);
  fs::remove_all(dir);
}

namespace {

// zero_png with an oFFs chunk (pixel units) placing its data window at (x, y).
std::string offset_png(std::uint32_t w, std::uint32_t h, std::int32_t x, std::int32_t y) {
  const std::string png = zero_png(w, h, h);
  const std::size_t after_ihdr = 8 + 4 + 4 + 13 + 4;
  return png.substr(0, after_ihdr) +
         chunk("oFFs", be32(std::uint32_t(x)) + be32(std::uint32_t(y)) + std::string(1, '\0')) +
         png.substr(after_ihdr);
}

}  // namespace

TEST_CASE("a data window origin beyond 2^30 is refused from the header, so no window sum overflows") {
  const fs::path dir = scratch();
  const std::int32_t far = std::int32_t(1) << 30;
  struct Origin {
    std::int32_t x, y;
  };
  for (Origin o : {Origin{0, 2147483647}, {2147483640, 0}, {-2147483647, 0}, {0, -far - 1}, {far + 1, 3}}) {
    write_file(dir / "far.png", offset_png(23, 5, o.x, o.y));
    const std::string says = "far.png: data window origin (" + std::to_string(o.x) + ", " + std::to_string(o.y) +
                             ") out of range (limit 2^30 either way)";
    check_unreadable({"diff", "far.png", "far.png"}, dir, 4, says);
    check_unreadable({"resample", "far.png", "-o", "out.png", "--filter", "bspline", "--size", "8x8"}, dir, 2, says);
    write_file(dir / "far.toml", "[canvas]\nwidth = 10\nheight = 10\n[[image]]\nfile = \"far.png\"\n");
    check_unreadable({"render", "far.toml", "-o", "out.png"}, dir, 2, "far.toml:5: image[0].file: ./far.png: data window");
    CHECK_THROWS_WITH(splinefig::read_image((dir / "far.png").string()), Catch::Contains(says));
  }
  // At the limit the image is read, and compared with itself it matches.
  write_file(dir / "edge.png", offset_png(23, 5, -far, far));
  const Outcome same = run_in(dir, {"diff", "edge.png", "edge.png"});
  INFO(same.err);
  CHECK(same.code == 0);
  CHECK_THAT(same.out, Catch::Contains("PASS"));
  fs::remove_all(dir);
}

TEST_CASE("two small images whose windows lie far apart are refused before the span is allocated") {
  const fs::path dir = scratch();
  splinefig::Image a = splinefig::Image::zeros(1, 1, 4), b = splinefig::Image::zeros(1, 1, 4);
  b.x = b.y = 30000;
  splinefig::write_image((dir / "near.exr").string(), a);
  splinefig::write_image((dir / "far.exr").string(), b);
  const Outcome o = run_in(dir, {"diff", "near.exr", "far.exr"});
  INFO(o.seconds << " s: " << o.err);
  CHECK(o.code == 2);
  CHECK(o.err ==
        "splinefig diff: near.exr and far.exr: the data windows [0, 0, 1 x 1] and [30000, 30000, 1 x 1] span 30001 x "
        "30001 pixels, over the limit of 2^28 pixels compared\n");
  fs::remove_all(dir);
}

TEST_CASE("an [[image]] reaching 1e14 px past the canvas draws its visible part") {
  const fs::path dir = scratch();
  write_file(dir / "small.png", zero_png(4, 4, 4));
  for (const std::string interpolation : {"nearest", "bilinear"}) {
    write_file(dir / "huge_item.toml", "[canvas]\nwidth = 16\nheight = 16\n[[image]]\nfile = \"small.png\"\n"
                                       "at = [-5e13, -5e13]\nsize = [1e14, 1e14]\ninterpolation = \"" +
                                           interpolation + "\"\n");
    const Outcome o = run_in(dir, {"render", "huge_item.toml", "-o", "out.png"});
    INFO(interpolation << ": " << o.err);
    CHECK(o.code == 0);
    CHECK(fs::exists(dir / "out.png"));
    fs::remove(dir / "out.png");
  }
  fs::remove_all(dir);
}

TEST_CASE("two 1x1 images 8000 px apart are refused at once, not compared over 64M pixels of padding") {
  const fs::path dir = scratch();
  splinefig::Image a = splinefig::Image::zeros(1, 1, 3), b = splinefig::Image::zeros(1, 1, 3);
  a.pixels = {0.5f, 0.5f, 0.5f};
  b.pixels = {0.5f, 0.5f, 0.5f};
  b.x = b.y = 8000;
  splinefig::write_image((dir / "near.exr").string(), a);
  splinefig::write_image((dir / "far.exr").string(), b);
  const Outcome o = run_in(dir, {"diff", "near.exr", "far.exr"});
  INFO(o.seconds << " s: " << o.err);
  CHECK(o.seconds < 5);
  CHECK(o.code == 2);
  CHECK(o.err ==
        "splinefig diff: near.exr and far.exr: the data windows [0, 0, 1 x 1] and [8000, 8000, 1 x 1] span 8001 x 8001 "
        "pixels, more than 16 times the 2 pixels they hold (limit: 2^22 pixels, or 16 times the pixels held)\n");
  fs::remove_all(dir);
}
