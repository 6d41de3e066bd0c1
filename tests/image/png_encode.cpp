// PNG files as libpng writes them for write_image, decoded by OpenImageIO directly (not by
// read_image): every channel count at 8 and 16 bits holds the stored codes, and the metadata
// (sRGB, Software, a UTF-8 Description, pHYs, oFFs) reads back.
#include <splinefig/image/io.hpp>

#include "scratch.hpp"

#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <fstream>

using namespace splinefig;

namespace {

// An sRGB-encoded image (stored as it is, alpha straight) whose values are exact codes: pixel i,
// channel c holds code (37 i + 11 c + 1) mod (max + 1), so neighbouring bytes differ and a
// 16-bit value stored in the wrong byte order reads back as another code.
Image codes(int channels, int bits) {
  const int max = bits == 16 ? 65535 : 255;
  Image im = Image::zeros(5, 3, channels, Encoding::srgb);  // alpha: the last of 2 or 4 channels
  for (std::size_t i = 0; i < im.pixels.size(); ++i) {
    const std::size_t px = i / static_cast<std::size_t>(channels), c = i % static_cast<std::size_t>(channels);
    const long code = static_cast<long>((bits == 16 ? 4099 : 37) * px + 11 * c + 1) % (max + 1);
    im.pixels[i] = static_cast<float>(static_cast<double>(code) / max);
  }
  // Straight alpha is stored as given only where alpha is 1 (else the colour is divided by it):
  // make alpha opaque so every colour code is stored untouched.
  if (im.alpha_channel >= 0)
    for (std::size_t i = static_cast<std::size_t>(im.alpha_channel); i < im.pixels.size(); i += static_cast<std::size_t>(channels))
      im.pixels[i] = 1.0f;
  return im;
}

}  // namespace

TEST_CASE("PNG holds the stored codes for 1 to 4 channels at 8 and 16 bits, decoded by OpenImageIO") {
  const auto dir = scratch_dir("png-encode");
  for (int bits : {8, 16})
    for (int channels = 1; channels <= 4; ++channels) {
      INFO(bits << " bits, " << channels << " channels");
      const Image im = codes(channels, bits);
      const std::string path = (dir / ('c' + std::to_string(channels) + "-" + std::to_string(bits) + ".png")).string();
      WriteOptions w;
      w.bits = bits;
      write_image(path, im, w);
      OIIO::ImageSpec config;
      config.attribute("oiio:UnassociatedAlpha", 1);
      auto in = OIIO::ImageInput::open(path, &config);
      REQUIRE(in);
      CHECK(in->spec().nchannels == channels);
      CHECK(in->spec().format == (bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8));
      std::vector<std::uint16_t> v(im.pixels.size());
      REQUIRE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT16, v.data()));
      const double max = bits == 16 ? 65535 : 255;
      for (std::size_t i = 0; i < v.size(); ++i) {
        // OpenImageIO widens 8-bit codes to 16 bits by 257.
        const long got = bits == 16 ? v[i] : v[i] / 257;
        REQUIRE(got == std::lround(im.pixels[i] * max));
      }
    }
}

TEST_CASE("PNG metadata: sRGB, Software, a UTF-8 Description, pHYs and oFFs read back in OpenImageIO") {
  const auto dir = scratch_dir("png-meta");
  Image im = codes(4, 8);
  im.x = 7;
  im.y = -3;
  const std::string path = (dir / "meta.png").string();
  WriteOptions w;
  w.software = "splinefig test";
  w.description = "β₁ = 0.2 − α";
  w.dpi = 300;
  write_image(path, im, w);
  auto in = OIIO::ImageInput::open(path);
  REQUIRE(in);
  const OIIO::ImageSpec& s = in->spec();
  CHECK(s.get_string_attribute("oiio:ColorSpace") == "sRGB");
  CHECK(s.get_string_attribute("Software") == "splinefig test");
  CHECK(s.get_string_attribute("ImageDescription") == "β₁ = 0.2 − α");
  CHECK(s.get_float_attribute("XResolution") == Approx(300).epsilon(1e-5));
  CHECK(s.get_float_attribute("YResolution") == Approx(300).epsilon(1e-5));
  CHECK(s.x == 7);
  CHECK(s.y == -3);
  // The file starts with the PNG signature and carries an sRGB chunk.
  std::ifstream f(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(f)), {});
  CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  CHECK(bytes.find("sRGB") != std::string::npos);
}

TEST_CASE("an alpha channel index outside the image's channels is refused and nothing is written") {
  const auto dir = scratch_dir("png-alpha-index");
  Image im = codes(3, 8);
  im.alpha_channel = 3;
  const std::string path = (dir / "a.png").string();
  CHECK_THROWS_WITH(write_image(path, im), path + ": alpha channel 3 is not one of the image's 3 channels (or -1 for none)");
  CHECK(!std::filesystem::exists(path));
}
