// Ticks and spines on the pixel grid in raster output: a 1-px tick at a fractional position is
// one pixel column at the axis colour's full ink, not two grey ones; at 2x (2 px wide) two full
// columns. The SVG keeps the exact position. The tick positions are worked out here from the
// plot box and range the spec gives.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/srgb.hpp>

#include <cmath>
#include <string>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

// A 301-px wide box from x = 50 for x in [0, 3]: the ticks at 1 and 2 fall at 150.333 and
// 250.667, a third of a pixel off the grid each way; the box's bottom is at y = 220.
const std::string kSpec =
    "[canvas]\nwidth = 400\nheight = 260\n[axes]\nbox = [50, 20, 351, 220]\nx_range = [0, 3]\ny_range = [0, 1]\n"
    "x_ticks = [0, 1, 2, 3]\n[[axes.series]]\npoints = [[0, 0.5], [3, 0.5]]\n";

// The axis colour #333333 in linear light, and white.
const double kAxis = srgb_to_linear(0x33 / 255.0);

}  // namespace

TEST_CASE("a 1-px tick at a fractional position is one pixel column at full ink") {
  const FigureSpec spec = parse_spec(kSpec, "snap.toml");
  const RenderedFigure fig = render_figure(spec);
  const Image im = to_linear(fig.image);
  const AxesInfo& ax = fig.info.axes.at(0);
  REQUIRE(ax.pixel_box[0] == 50);
  REQUIRE(ax.pixel_box[2] == 351);
  REQUIRE(ax.pixel_box[3] == 220);
  const double at1 = 50 + 301.0 / 3, at2 = 50 + 2 * 301.0 / 3;
  REQUIRE(ax.x_map().to_pixel(1) == Approx(at1));
  // Ticks run from the box's bottom + 1 down 5 px: rows 221..225. Each tick is the pixel column
  // holding its position, at the axis colour; the columns beside it are white.
  for (const double at : {50.0, at1, at2}) {
    const int col = static_cast<int>(std::floor(at));
    INFO("tick at x = " << at << ", column " << col);
    for (int y = 222; y <= 224; ++y) {
      CHECK(im.at(col, y, 0) == Approx(kAxis).margin(2e-3));
      CHECK(im.at(col - 1, y, 0) == Approx(1).margin(2e-3));
      CHECK(im.at(col + 1, y, 0) == Approx(1).margin(2e-3));
    }
  }
  // The left spine: the column left of the box, full ink, from the box's top row.
  for (int y = 20; y < 220; y += 37) CHECK(im.at(49, y, 0) == Approx(kAxis).margin(2e-3));
}

TEST_CASE("at 2x a tick is two whole pixel columns at full ink") {
  const RenderedFigure fig = render_figure(parse_spec(kSpec, "snap.toml"), {2, 1});
  const Image im = to_linear(fig.image);
  const double at1 = 2 * (50 + 301.0 / 3);  // 300.667: its 2-px line on columns 300 and 301
  const int left = static_cast<int>(std::round(at1)) - 1;
  for (int y = 444; y <= 448; ++y) {
    INFO("row " << y);
    CHECK(im.at(left, y, 0) == Approx(kAxis).margin(2e-3));
    CHECK(im.at(left + 1, y, 0) == Approx(kAxis).margin(2e-3));
    CHECK(im.at(left - 1, y, 0) == Approx(1).margin(2e-3));
    CHECK(im.at(left + 2, y, 0) == Approx(1).margin(2e-3));
  }
}

TEST_CASE("the SVG keeps the ticks' exact positions") {
  const FigureScene fig = figure_scene(parse_spec(kSpec, "snap.toml"));
  const std::string svg = figure_svg(fig, {});
  // Numbers to 1/1000 px: the tick at 1 is at 150.333, at 2 at 250.667.
  CHECK(svg.find("150.333") != std::string::npos);
  CHECK(svg.find("250.667") != std::string::npos);
}
