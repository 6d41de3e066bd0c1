// One alpha rule: files hold straight alpha, images hold associated alpha; reading decodes
// before associating, writing dissociates before encoding.
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>

#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <fstream>

using namespace splinefig;

namespace {

// A 1x1 RGBA PNG written by OpenImageIO directly (straight alpha, as PNG stores it).
void write_png_rgba(const std::string& path, const unsigned char px[4]) {
  OIIO::ImageSpec spec(1, 1, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(path);
  REQUIRE(out);
  REQUIRE(out->open(path, spec));
  REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, px));
  REQUIRE(out->close());
}

std::array<int, 4> stored_bytes(const std::string& path) {
  OIIO::ImageSpec raw;
  raw.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &raw);
  REQUIRE(in);
  unsigned char px[4] = {};
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px));
  return {px[0], px[1], px[2], px[3]};
}

}  // namespace

TEST_CASE("a half-transparent sRGB PNG reads as linear associated, or as stored") {
  const auto dir = scratch_dir("alpha-read");
  const std::string path = (dir / "red.png").string();
  const unsigned char px[4] = {255, 128, 0, 127};
  write_png_rgba(path, px);
  const float a = 127 / 255.0f;

  const Image lin = read_image(path, ReadMode::linear);
  REQUIRE(lin.channels == 4);
  CHECK(lin.alpha_channel == 3);
  CHECK(lin.encoding == Encoding::linear);
  // Decoded first (sRGB 128/255 -> 0.2158605), then multiplied by alpha.
  CHECK(lin.at(0, 0, 0) == Approx(1.0 * a).epsilon(1e-6));
  CHECK(lin.at(0, 0, 1) == Approx(0.21586050 * a).epsilon(1e-6));
  CHECK(lin.at(0, 0, 2) == 0.0f);
  CHECK(lin.at(0, 0, 3) == Approx(a).epsilon(1e-6));

  // As stored (idiff's view): the file's sRGB values, associated by OpenImageIO, which
  // multiplies the 8-bit values (128 * 127 / 255 = 63.75 comes out as 63).
  const Image raw = read_image(path, ReadMode::as_stored);
  CHECK(raw.encoding == Encoding::srgb);
  CHECK(raw.at(0, 0, 0) == Approx(a).epsilon(1e-6));
  CHECK(raw.at(0, 0, 1) == Approx(128 / 255.0 * a).margin(1.0 / 255));
  CHECK(raw.at(0, 0, 3) == Approx(a).epsilon(1e-6));

  // Written back, the linear image gives the file's bytes again; the stored one within
  // OpenImageIO's rounding.
  write_image((dir / "lin.png").string(), lin);
  write_image((dir / "raw.png").string(), raw);
  CHECK(stored_bytes((dir / "lin.png").string()) == std::array<int, 4>{255, 128, 0, 127});
  const auto back = stored_bytes((dir / "raw.png").string());
  CHECK(back[0] == 255);
  CHECK(std::abs(back[1] - 128) <= 2);
  CHECK(back[2] == 0);
  CHECK(back[3] == 127);
}

TEST_CASE("16-bit PNGs keep 16 bits and decode with the formula") {
  const auto dir = scratch_dir("sixteen");
  Image im(2, 1, 3);
  const float v[6] = {0.5f, 0.25f, 0.0f, 1.0f, 0.001f, 0.75f};
  std::copy(v, v + 6, im.pixels.begin());
  const std::string path = (dir / "w.png").string();
  write_image(path, im, {.bits = 16});
  FileFormat f;
  const Image back = read_image(path, ReadMode::linear, &f);
  CHECK(f.name == "png");
  CHECK(f.bits == 16);
  for (int k = 0; k < 6; ++k) CHECK(back.pixels[std::size_t(k)] == Approx(v[k]).margin(2e-5));
  auto in = OIIO::ImageInput::open(path);
  REQUIRE(in);
  CHECK(in->spec().format == OIIO::TypeDesc::UINT16);
  unsigned short w[6];
  REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, w));
  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.73535698..., times 65535 = 48191.6 (IEC 61966-2-1, by hand).
  CHECK(int(w[0]) == 48192);
}

TEST_CASE("reading refuses what is not a regular image file, in one line") {
  const auto dir = scratch_dir("not-files");
  CHECK_THROWS_WITH(read_image((dir / "nothing.png").string()), Catch::Contains("no such file"));
  CHECK_THROWS_WITH(read_image(dir.string()), Catch::Contains("is a directory"));
  CHECK_THROWS_WITH(read_image("/dev/zero"), Catch::Contains("/dev/zero: not a regular file"));
  const std::string text = (dir / "text.png").string();
  { std::ofstream(text) << "not an image\n"; }
  try {
    read_image(text);
    FAIL("read a text file as an image");
  } catch (const UnreadableImage& e) {
    const std::string what = e.what();
    CHECK(what.rfind(text + ": ", 0) == 0);
    CHECK(what.find('\n') == std::string::npos);
  }
}
