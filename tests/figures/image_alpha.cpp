// An `[[image]]` file with alpha is composited once: straight alpha in the file, decoded from
// sRGB, associated, then drawn over the canvas in linear light.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/image/srgb.hpp>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

using namespace splinefig;
using namespace splinefig::figures;
namespace fs = std::filesystem;

TEST_CASE("elements: a half-transparent red PNG over white is (255, 188, 188), premultiplied once") {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-image-alpha-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    OIIO::ImageSpec spec(2, 2, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    const unsigned char px[16] = {255, 0, 0, 127, 255, 0, 0, 127, 255, 0, 0, 127, 255, 0, 0, 127};
    auto out = OIIO::ImageOutput::create((dir / "red.png").string());
    REQUIRE(out);
    REQUIRE(out->open((dir / "red.png").string(), spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::UINT8, px));
    REQUIRE(out->close());
  }
  const std::string text = R"(
title = "alpha"
show_title = false
[canvas]
width = 8
height = 8
background = "#ffffff"
[[image]]
file = "red.png"
at = [2, 2]
size = [4, 4]
)";
  const FigureSpec spec = parse_spec(text, "alpha", dir.string());
  const RenderedFigure r = render_figure(spec, {1, 1});
  // Over white in linear light: red 1 * a + 1 * (1 - a) = 1; green and blue 1 - a.
  const double a = 127 / 255.0;
  const double g = 1.055 * std::pow(1 - a, 1 / 2.4) - 0.055;
  const int expected_g = static_cast<int>(std::lround(255 * g));
  REQUIRE(expected_g == 188);
  const float* p = r.image.pixel(3, 3);
  CHECK(int(linear_to_srgb8(p[0])) == 255);
  CHECK(int(linear_to_srgb8(p[1])) == expected_g);
  CHECK(int(linear_to_srgb8(p[2])) == expected_g);
  CHECK(p[3] == 1.0f);
  // Outside the image: the white canvas.
  const float* q = r.image.pixel(0, 0);
  CHECK((q[0] == 1.0f && q[1] == 1.0f && q[2] == 1.0f));
  fs::remove_all(dir);
}
