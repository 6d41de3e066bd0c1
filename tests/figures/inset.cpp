// Insets ([[axes.inset]], docs/spec.md): the inset shows the axes' data magnified to its
// ranges, the rectangle it magnifies is marked on the axes where the axes' own map puts those
// ranges, and bad inset keys are refused with FILE:LINE: KEY. Checked from pixels: a red line
// y = x, whose ink centre in each pixel column must lie where a data-to-pixel map written here
// (from the reported boxes and ranges) puts it, in the inset and in the axes.
#include "spec_error_check.hpp"

#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <array>
#include <cmath>
#include <string>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

// A 400 x 300 canvas blending in linear light (ink = coverage), the plot box [40, 20, 380, 280], no guides; the line y = x from (0, 0) to
// (10, 10), red, 2 px wide; the inset magnifies [4, 6] x [4, 6] into the box's lower right,
// where the line does not run.
const char* kSpec = R"(
[canvas]
width = 400
height = 300
blend = "linear"
[axes]
box = [40, 20, 380, 280]
x_range = [0, 10]
y_range = [0, 10]
frame = "none"
legend = "none"
[[axes.series]]
points = [[0, 0], [10, 10]]
color = "#ff0000"
width = 2
[[axes.inset]]
x_range = [4, 6]
y_range = [4, 6]
at = [0.6, 0.05, 0.35, 0.35]
)";

float green(const Image& im, int x, int y) { return im.pixels[(std::size_t(y) * im.width + x) * im.channels + 1]; }
float red(const Image& im, int x, int y) { return im.pixels[(std::size_t(y) * im.width + x) * im.channels + 0]; }

// The red line's ink centre (rows weighted by 1 - green: red over white takes exactly the
// green of its coverage) in column x between rows y0 and y1 (exclusive).
double ink_centre(const Image& im, int x, int y0, int y1) {
  double w = 0, wy = 0;
  for (int y = y0; y < y1; ++y) {
    const double a = 1.0 - green(im, x, y);
    if (red(im, x, y) > 0.9f) w += a, wy += a * (y + 0.5);  // red ink, not the grey marks
  }
  return w > 0 ? wy / w : -1;
}

// Data to pixels for a box [left, top, right, bottom] showing [x0, x1] x [y0, y1], y up.
struct Map {
  std::array<double, 4> box;
  std::array<double, 2> xr, yr;
  double px(double x) const { return box[0] + (x - xr[0]) / (xr[1] - xr[0]) * (box[2] - box[0]); }
  double py(double y) const { return box[3] - (y - yr[0]) / (yr[1] - yr[0]) * (box[3] - box[1]); }
  double x_of(double px_) const { return xr[0] + (px_ - box[0]) / (box[2] - box[0]) * (xr[1] - xr[0]); }
};

}  // namespace

TEST_CASE("an inset shows the axes' data magnified to its ranges") {
  const FigureSpec spec = parse_spec(kSpec, "inset", ".");
  const RenderedFigure r = render_figure(spec, {1, 0});
  const AxesInfo& ax = r.info.axes.at(0);
  REQUIRE(ax.insets.size() == 1);
  const AxesInfo::Inset& in = ax.insets[0];
  // The box the spec asks for: fractions of [40, 20, 380, 280] from its lower left, whole pixels.
  // 40 + 0.6 * 340, 280 - 0.4 * 260, 40 + 0.95 * 340, 280 - 0.05 * 260
  CHECK(in.pixel_box == std::array<double, 4>{244, 176, 363, 267});
  CHECK(in.x_range == std::array<double, 2>{4, 6});
  CHECK(in.y_range == std::array<double, 2>{4, 6});
  const Map inset{in.pixel_box, {4, 6}, {4, 6}}, parent{{40, 20, 380, 280}, {0, 10}, {0, 10}};
  // In the inset: every column whose line stays 4 px inside the box has its ink centre at the
  // magnified y = x.
  int columns = 0;
  for (int x = static_cast<int>(in.pixel_box[0]) + 1; x < static_cast<int>(in.pixel_box[2]) - 1; ++x) {
    const double want = inset.py(inset.x_of(x + 0.5));
    if (want < in.pixel_box[1] + 4 || want > in.pixel_box[3] - 4) continue;
    const double got = ink_centre(r.image, x, static_cast<int>(in.pixel_box[1]) + 1, static_cast<int>(in.pixel_box[3]));
    INFO("inset column " << x);
    CHECK(std::abs(got - want) < 0.02);
    ++columns;
  }
  CHECK(columns > 60);
  // On the axes, left of the inset and away from the marked rectangle: the same line unmagnified.
  for (int x = 60; x < 150; x += 7) {
    const double want = parent.py(parent.x_of(x + 0.5));
    INFO("axes column " << x);
    CHECK(std::abs(ink_centre(r.image, x, 20, 280) - want) < 0.02);
  }
}

TEST_CASE("the rectangle an inset magnifies is marked where the axes map its ranges") {
  const RenderedFigure r = render_figure(parse_spec(kSpec, "inset", "."), {1, 0});
  // [4, 6] on [0, 10] over the box [40, 20, 380, 280]: x 176..244, y 124..176.
  const double zl = 40 + 0.4 * 340, zr = 40 + 0.6 * 340, zt = 280 - 0.6 * 260, zb = 280 - 0.4 * 260;
  CHECK(r.info.axes.at(0).insets.at(0).marked_box == std::array<double, 4>{zl, zt, zr, zb});
  // The darkest grey column (row) near each edge, at the middle of the other side: the mark's
  // 1-px line, within half a pixel of the edge (the guides' lines lie on the pixel grid).
  auto darkest = [&](bool vertical, double at, int across) {
    int best = -1;
    float v = 2;
    for (int k = static_cast<int>(at) - 4; k <= static_cast<int>(at) + 4; ++k) {
      const float g = vertical ? green(r.image, k, across) : green(r.image, across, k);
      if (g < v) v = g, best = k;
    }
    CHECK(v < 0.1f);  // #333333 is 0.033 in linear light
    return best + 0.5;
  };
  const int mid_y = static_cast<int>(0.5 * (zt + zb)), mid_x = static_cast<int>(0.5 * (zl + zr));
  CHECK(std::abs(darkest(true, zl, mid_y) - zl) <= 0.5);
  CHECK(std::abs(darkest(true, zr, mid_y) - zr) <= 0.5);
  CHECK(std::abs(darkest(false, zt, mid_x) - zt) <= 0.5);
  CHECK(std::abs(darkest(false, zb, mid_x) - zb) <= 0.5);
}

TEST_CASE("bad inset keys name the file, the line and the key") {
  const std::string axes = "[canvas]\nwidth = 100\nheight = 80\n[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {axes + "[[axes.inset]]\ny_range = [0, 1]\n", "bad.toml:7: axes.inset[0].x_range: an inset needs x_range"},
      {axes + "[[axes.inset]]\nx_range = [0.5, 0.5]\ny_range = [0, 1]\n",
       "bad.toml:8: axes.inset[0].x_range: expected [lo, hi] with lo < hi"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [1, 0]\n",
       "bad.toml:9: axes.inset[0].y_range: expected [lo, hi] with lo < hi"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1, 2]\n",
       "bad.toml:9: axes.inset[0].y_range: expected [lo, hi]"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nat = [0.7, 0, 0.5, 0.5]\n",
       "bad.toml:10: axes.inset[0].at: expected [x, y, width, height]"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nat = [0, 0, 0, 0.5]\n",
       "bad.toml:10: axes.inset[0].at: expected [x, y, width, height]"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nat = [0, 0, 0.5]\n",
       "bad.toml:10: axes.inset[0].at: expected [x, y, width, height]"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nsize = [0.5, 1.5]\n",
       "bad.toml:10: axes.inset[0].size: expected [width, height]"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nat = [0, 0, 0.5, 0.5]\nsize = [0.5, 0.5]\n",
       "bad.toml:11: axes.inset[0].size: give either at or size"},
      {axes + "[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\nzoom = 2\n", "bad.toml:10: axes.inset[0].zoom: unknown key"},
      {"[axes]\ny_scale = \"log\"\n[[axes.inset]]\nx_range = [0, 1]\ny_range = [0, 1]\n",
       "bad.toml:5: axes.inset[0].y_range: a log axis needs a positive range"},
  };
  figtest::check_spec_errors(cases, "bad.toml");
}
