// [canvas] blend: figures blend the sRGB-encoded values by default, as SVG and PDF viewers do,
// so a translucent fill's interior is the colour a viewer shows for the same SVG; "linear"
// blends in linear light. The expected 8-bit values are worked by hand from the hex colours.
// The EXR holds the linear decode of what was composited: the PNG's values, decoded.
#include "spec_error_check.hpp"
#include "support.hpp"
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/image/srgb.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

// A translucent fill (#1f77b4 at alpha 0x80) over the white canvas, covering the middle of the
// plot box.
std::string spec(const std::string& canvas_extra) {
  return "[canvas]\nwidth = 200\nheight = 150\n" + canvas_extra +
         "[axes]\nframe = \"none\"\nlegend = \"none\"\nx_range = [0, 1]\ny_range = [0, 1]\n"
         "[[axes.fill]]\npoints = [[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9]]\ncolor = \"#1f77b480\"\n";
}

// The 8-bit code of the fill's interior, at the plot box's centre.
std::array<long, 3> interior(const std::string& text) {
  const FigureSpec s = parse_spec(text, "f.toml");
  const auto box = layout_figure(s).axes.at(0).pixel_box;
  const RenderedFigure r = render_figure(s);
  const int x = static_cast<int>((box[0] + box[2]) / 2), y = static_cast<int>((box[1] + box[3]) / 2);
  // The canvas is opaque: the PNG's code is the encoded value rounded, or the linear value encoded.
  auto code = [&](int c) -> long {
    const float v = r.image.at(x, y, c);
    return r.image.encoding == Encoding::srgb ? std::lround(255 * v) : linear_to_srgb8(v);
  };
  return {code(0), code(1), code(2)};
}

}  // namespace

TEST_CASE("blend: a figure blends the sRGB-encoded values by default, as viewers show its SVG") {
  // Each channel a * c + (1 - a) * 255 in codes: 31 -> 142.56, 119 -> 186.73, 180 -> 217.35.
  CHECK(interior(spec("")) == std::array<long, 3>{143, 187, 217});
  CHECK(interior(spec("blend = \"srgb\"\n")) == std::array<long, 3>{143, 187, 217});
}

TEST_CASE("blend: \"linear\" blends in linear light") {
  // Each channel decoded with the sRGB curve, blended with a = 128/255, encoded again:
  // 31 -> 0.013702 -> 0.504917 -> 0.738568 -> 188.3; 119 -> 0.184452 -> 0.590627 -> 0.792175
  // -> 202.0; 180 -> 0.456406 -> 0.727138 -> 0.868825 -> 221.6.
  CHECK(interior(spec("blend = \"linear\"\n")) == std::array<long, 3>{188, 202, 222});
}

TEST_CASE("blend: the EXR of an sRGB-blended figure holds the linear decode of its PNG") {
  const FigureSpec s = parse_spec(spec(""), "f.toml");
  const FigureScene f = figure_scene(s, 1);
  const auto dir = figtest::scratch("blend-exr");
  std::optional<Image> raster;
  const std::string png = (dir / "f.png").string(), exr = (dir / "f.exr").string();
  write_figure_file(f, png, Format::png, {}, raster);
  write_figure_file(f, exr, Format::exr, {}, raster);
  const Image p = read_image(png, ReadMode::as_stored), e = read_image(exr, ReadMode::as_stored);
  REQUIRE(p.width == e.width);
  REQUIRE(p.height == e.height);
  // The sRGB curve (IEC 61966-2-1), written out here: the EXR's value of every pixel and channel
  // is the PNG's code decoded, to within the 8-bit rounding of the PNG (half a code).
  auto decode = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
  double worst = 0;
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i)
      for (int c = 0; c < 3; ++c) {
        const double code = 255.0 * p.at(i, j, c), lin = e.at(i, j, c);
        const double lo = decode(std::max(0.0, code - 0.5) / 255), hi = decode(std::min(255.0, code + 0.5) / 255);
        worst = std::max(worst, std::max(lo - lin, lin - hi));
      }
  CHECK(worst <= 1e-6);
  // The fill's interior: 142.5608 / 255 = 0.559062 decoded is 0.272836 (not the linear blend's
  // 0.504917 of the red channel).
  const auto box = layout_figure(s).axes.at(0).pixel_box;
  const int x = static_cast<int>((box[0] + box[2]) / 2), y = static_cast<int>((box[1] + box[3]) / 2);
  CHECK(e.at(x, y, 0) == Approx(0.272836).margin(2e-6));
}

TEST_CASE("blend: an unknown space is the spec's one-line error") {
  const std::string msg = figtest::spec_error(spec("blend = \"cmyk\"\n"), "f.toml");
  CAPTURE(msg);
  CHECK(msg.rfind("f.toml:4: canvas.blend:", 0) == 0);
  CHECK(msg.find("srgb | linear") != std::string::npos);
}
