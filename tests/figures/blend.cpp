// [canvas] blend: figures blend in linear light by default; "srgb" blends the sRGB-encoded
// values, as SVG and PDF viewers do, so a translucent fill's interior is the colour a viewer
// shows for the same SVG. The expected 8-bit values are worked by hand from the hex colours.
#include "spec_error_check.hpp"
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/srgb.hpp>

#include <array>
#include <cmath>
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

TEST_CASE("blend: a figure blends in linear light by default") {
  // Each channel decoded with the sRGB curve, blended with a = 128/255, encoded again:
  // 31 -> 0.013702 -> 0.504917 -> 0.738568 -> 188.3; 119 -> 0.184452 -> 0.590627 -> 0.792175
  // -> 202.0; 180 -> 0.456406 -> 0.727138 -> 0.868825 -> 221.6.
  CHECK(interior(spec("")) == std::array<long, 3>{188, 202, 222});
  CHECK(interior(spec("blend = \"linear\"\n")) == std::array<long, 3>{188, 202, 222});
}

TEST_CASE("blend: \"srgb\" blends the encoded values, as viewers show the figure's SVG") {
  // Each channel a * c + (1 - a) * 255 in codes: 31 -> 142.56, 119 -> 186.73, 180 -> 217.35.
  CHECK(interior(spec("blend = \"srgb\"\n")) == std::array<long, 3>{143, 187, 217});
}

TEST_CASE("blend: an unknown space is the spec's one-line error") {
  const std::string msg = figtest::spec_error(spec("blend = \"cmyk\"\n"), "f.toml");
  CAPTURE(msg);
  CHECK(msg.rfind("f.toml:4: canvas.blend:", 0) == 0);
  CHECK(msg.find("linear | srgb") != std::string::npos);
}
