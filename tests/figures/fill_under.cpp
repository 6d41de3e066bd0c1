// [[axes.fill]] under = "LABEL": the area under a curve, kernel or series of the same axes, down
// to a baseline or to another element. Checked against independent values: the B-spline basis
// function's integral (1, the partition of unity) as inked area, and a straight series' fill
// against the same triangle typed as a polygon; bad references name the fill's line and key.
#include "spec_error_check.hpp"
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <cmath>
#include <string>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

const std::string kAxes =
    "[canvas]\nwidth = 400\nheight = 300\n[axes]\nframe = \"none\"\nlegend = \"none\"\nx_range = [-2.5, 2.5]\ny_range = [-0.25, 1]\n";

// Sum over the image of how far each pixel is from the white background, in the values of its
// blend space: for an opaque black fill this is its area in pixels (a pixel at coverage c is
// 1 - c over white in linear light and in sRGB-encoded values alike).
double ink(const Image& im) {
  double sum = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) sum += 1.0 - im.at(x, y, 0);
  return sum;
}

std::string error_of(const std::string& text) { return figtest::spec_error(text, "f.toml"); }

}  // namespace

TEST_CASE("fill under: the area under the B-spline kernel is its integral, 1") {
  const std::string spec = kAxes +
                           "[[axes.kernel]]\nbasis = \"bspline\"\nwidth = 0\nlabel = \"B\"\n"
                           "[[axes.fill]]\nunder = \"B\"\ncolor = \"#000000\"\n";
  const FigureSpec s = parse_spec(spec, "f.toml");
  const auto box = layout_figure(s).axes.at(0).pixel_box;
  const double px_per_x = (box[2] - box[0]) / 5.0, px_per_y = (box[3] - box[1]) / 1.25;
  const Image im = render_figure(s).image;
  // 1 unit of area; the curve's samples are within 0.05 px of it, over a length of ~ 2 * 260 px.
  CHECK(ink(im) == Approx(px_per_x * px_per_y).epsilon(0.002));
}

TEST_CASE("fill under: a straight series filled to its baseline is the polygon typed by hand") {
  const std::string line = "[[axes.series]]\npoints = [[-2, 0.2], [2, 0.8]]\nlabel = \"line\"\nwidth = 0\n";
  const std::string under = kAxes + line + "[[axes.fill]]\nunder = \"line\"\nbaseline = 0.1\ncolor = \"#204080\"\n";
  const std::string typed = kAxes + line +
                            "[[axes.fill]]\npoints = [[-2, 0.2], [2, 0.8], [2, 0.1], [-2, 0.1]]\ncolor = \"#204080\"\n";
  const Image a = render_figure(parse_spec(under, "u.toml")).image;
  const Image b = render_figure(parse_spec(typed, "t.toml")).image;
  REQUIRE(a.pixels.size() == b.pixels.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, double(std::abs(a.pixels[i] - b.pixels[i])));
  CHECK(worst < 1e-6);
  CHECK(ink(a) > 1000);  // something was filled
}

TEST_CASE("fill under: between two elements, to = LABEL") {
  // Between y = 0.2 and y = 0.6 over x in [-2, 2]: a 4 x 0.4 rectangle.
  const std::string spec = kAxes + "[[axes.series]]\npoints = [[-2, 0.6], [2, 0.6]]\nlabel = \"top\"\nwidth = 0\n" +
                           "[[axes.series]]\npoints = [[-2, 0.2], [2, 0.2]]\nlabel = \"bottom\"\nwidth = 0\n" +
                           "[[axes.fill]]\nunder = \"top\"\nto = \"bottom\"\ncolor = \"#000000\"\n";
  const FigureSpec s = parse_spec(spec, "f.toml");
  const auto box = layout_figure(s).axes.at(0).pixel_box;
  const double px_per_x = (box[2] - box[0]) / 5.0, px_per_y = (box[3] - box[1]) / 1.25;
  CHECK(ink(render_figure(s).image) == Approx(4 * 0.4 * px_per_x * px_per_y).epsilon(1e-4));
}

TEST_CASE("fill under: bad references and keys name the fill's line and key") {
  const std::string curve = kAxes + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\nlabel = \"c\"\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {curve + "[[axes.fill]]\nunder = \"d\"\n",
       "f.toml:13: axes.fill[0].under: no curve, kernel or series labelled \"d\" in these axes (labels: \"c\")"},
      {kAxes + "[[axes.fill]]\nunder = \"d\"\n", "f.toml:10: axes.fill[0].under: no curve, kernel or series labelled \"d\" in these axes (none has a label)"},
      {curve + "[[axes.fill]]\nunder = \"c\"\nto = \"e\"\n", "f.toml:14: axes.fill[0].to: no curve, kernel or series labelled \"e\""},
      {curve + "[[axes.fill]]\nunder = \"c\"\nto = \"c\"\n", "f.toml:14: axes.fill[0].to: the same element as under"},
      {curve + "[[axes.fill]]\nunder = \"c\"\nto = \"c2\"\nbaseline = 1\n", "f.toml:15: axes.fill[0].baseline: give either to or baseline, not both"},
      {curve + "[[axes.fill]]\nunder = \"c\"\npoints = [[0, 0], [1, 1], [1, 0]]\n", "f.toml:14: axes.fill[0].points: give either under or points, not both"},
      {curve + "[[axes.fill]]\nunder = 3\n", "f.toml:13: axes.fill[0].under: expected a string"},
      {curve + "[[axes.fill]]\nunder = \"\"\n", "f.toml:13: axes.fill[0].under: expected the label of a curve, kernel or series"},
      {curve + "[[axes.fill]]\nunder = \"c\"\nbaseline = \"low\"\n", "f.toml:14: axes.fill[0].baseline: expected a number"},
      {curve + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\nlabel = \"c\"\n[[axes.fill]]\nunder = \"c\"\n",
       "f.toml:16: axes.fill[0].under: 2 elements are labelled \"c\""},
      {curve + "[[axes.fill]]\nunder = \"c\"\nunder_color = \"#000000\"\n", "f.toml:14: axes.fill[0].under_color: unknown key"},
  };
  figtest::check_spec_errors(cases, "f.toml");
  // A fill may come before the element it names (document order is drawing order).
  CHECK(error_of(kAxes + "[[axes.fill]]\nunder = \"c\"\n[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\nlabel = \"c\"\n").empty());
}
