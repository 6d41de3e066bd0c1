// TIFF output: 8 and 16 bits hold what PNG holds (sRGB, straight alpha), float holds what EXR
// holds (linear, associated alpha). Each file is decoded by OpenImageIO directly, not by
// read_image, and compared with the PNG or EXR of the same image.
#include <splinefig/image/io.hpp>

#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <fstream>
#include <algorithm>

using namespace splinefig;

namespace {

// 3x2 linear RGBA, associated alpha: opaque, half and nearly transparent, clear, a bright value.
Image sample() {
  Image im = Image::zeros(3, 2, 4, Encoding::linear);
  im.alpha_channel = 3;
  const float px[6][4] = {{1.0f, 0.5f, 0.25f, 1.0f},  {0.1f, 0.2f, 0.3f, 0.5f}, {0.001f, 0.002f, 0.0f, 0.01f},
                          {0.0f, 0.0f, 0.0f, 0.0f},   {0.75f, 0.0f, 0.9f, 1.0f}, {0.2158605f, 0.0f, 0.0f, 0.4f}};
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 4; ++c) im.pixels[std::size_t(i * 4 + c)] = px[i][c];
  return im;
}

// The stored values as OpenImageIO decodes them, alpha left as stored.
template <class T>
std::vector<T> stored(const std::string& path, OIIO::TypeDesc type, std::string* format = nullptr) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  REQUIRE(in);
  if (format) *format = in->spec().format.c_str();
  std::vector<T> v(std::size_t(in->spec().image_pixels()) * std::size_t(in->spec().nchannels));
  REQUIRE(in->read_image(0, 0, 0, in->spec().nchannels, type, v.data()));
  return v;
}

std::string head(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::string s(4, '\0');
  f.read(s.data(), 4);
  return s;
}

}  // namespace

TEST_CASE("TIFF at 8 and 16 bits stores the values PNG stores") {
  const auto dir = scratch_dir("tiff-int");
  const Image im = sample();
  for (int bits : {8, 16}) {
    INFO(bits << " bits");
    const std::string png = (dir / ('x' + std::to_string(bits) + ".png")).string();
    const std::string tif = (dir / ('x' + std::to_string(bits) + ".tif")).string();
    WriteOptions w;
    w.bits = bits;
    write_image(png, im, w);
    write_image(tif, im, w);
    CHECK(head(tif) == std::string("II*\0", 4));
    std::string format;
    if (bits == 8) {
      CHECK(stored<std::uint8_t>(tif, OIIO::TypeDesc::UINT8, &format) == stored<std::uint8_t>(png, OIIO::TypeDesc::UINT8));
      CHECK(format == "uint8");
    } else {
      CHECK(stored<std::uint16_t>(tif, OIIO::TypeDesc::UINT16, &format) ==
            stored<std::uint16_t>(png, OIIO::TypeDesc::UINT16));
      CHECK(format == "uint16");
    }
    auto in = OIIO::ImageInput::open(tif);
    REQUIRE(in);
    CHECK(in->spec().get_int_attribute("tiff:UnassociatedAlpha") == 1);  // ExtraSamples: unassociated
    CHECK(in->spec().get_string_attribute("compression") == "zip");
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("TIFF as float stores the linear associated values EXR stores, bit for bit") {
  const auto dir = scratch_dir("tiff-float");
  const Image im = sample();
  const std::string exr = (dir / "x.exr").string(), tif = (dir / "x.tiff").string();
  WriteOptions w;
  w.bits = 32;
  w.dpi = 300;
  write_image(exr, im, w);
  write_image(tif, im, w);
  OIIO::ImageSpec config;  // associated, as both files hold it
  auto in = OIIO::ImageInput::open(tif, &config);
  REQUIRE(in);
  CHECK(in->spec().format == OIIO::TypeDesc::FLOAT);
  CHECK(in->spec().get_float_attribute("XResolution") == 300.0f);
  CHECK(in->spec().get_string_attribute("ResolutionUnit") == "in");
  CHECK(in->spec().get_int_attribute("tiff:UnassociatedAlpha") == 0);  // ExtraSamples: associated
  std::vector<float> from_tif(im.pixels.size());
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, from_tif.data()));
  CHECK(std::equal(from_tif.begin(), from_tif.end(), im.pixels.begin(), im.pixels.end()));
  auto ein = OIIO::ImageInput::open(exr, &config);
  REQUIRE(ein);
  std::vector<float> from_exr(im.pixels.size());
  REQUIRE(ein->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, from_exr.data()));
  CHECK(from_exr == from_tif);
  std::filesystem::remove_all(dir);
}

TEST_CASE("TIFF with another bit depth is refused, naming the file, and nothing is written") {
  const auto dir = scratch_dir("tiff-bad");
  const std::string tif = (dir / "x.tif").string();
  WriteOptions w;
  w.bits = 12;
  CHECK_THROWS_WITH(write_image(tif, sample(), w),
                    tif + ": TIFF is written with 8 or 16 bits per channel or as float (32), not 12");
  CHECK(!std::filesystem::exists(tif));
  std::filesystem::remove_all(dir);
}

TEST_CASE("EXR and TIFF carry a DateTime only when one is given, so the same image gives the same bytes") {
  const auto dir = scratch_dir("tiff-date");
  auto date_of = [](const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    return in->spec().get_string_attribute("DateTime", "(none)");
  };
  auto bytes = [](const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  for (const char* ext : {".exr", ".tif"}) {
    const std::string a = (dir / (std::string("a") + ext)).string(), b = (dir / (std::string("b") + ext)).string();
    WriteOptions w;
    if (std::string(ext) == ".tif") w.bits = 32;
    write_image(a, sample(), w);
    CHECK(date_of(a) == "(none)");
    write_image(b, sample(), w);
    CHECK(bytes(a) == bytes(b));
    w.date = 1700000000;  // 2023-11-14 22:13:20 UTC
    write_image(b, sample(), w);
    CHECK(date_of(b) == "2023:11:14 22:13:20");
  }
}
