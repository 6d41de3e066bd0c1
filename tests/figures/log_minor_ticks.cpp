// A log axis with a tick every decade also gets unlabelled minor ticks at 2, 3, ..., 9 times
// each power of ten, shorter than the decades' ticks; other axes get none. Positions are
// log10 of the values on the axis' pixel map (docs/conventions.md), read from the figure info.
#include <catch2/catch.hpp>

#include "ink.hpp"

#include <cmath>
#include <string>

using splinefig::figures::RenderedFigure;

namespace {

RenderedFigure log_axes(const std::string& x_axis) {
  return figtest::render_text_spec("[canvas]\nwidth = 500\nheight = 200\n[axes]\n" + x_axis +
                                   "y_range = [0, 1]\ny_ticks = []\nlegend = \"none\"\n"
                                   "[[axes.series]]\npoints = [[2, 0.5], [3, 0.5]]\ncolor = \"#ffffff\"\n");
}

// The most ink in the two pixel columns around data x, in the pixel row `below` px under the
// plot box's bottom edge.
double tick_ink(const RenderedFigure& f, double x, double below) {
  const auto& a = f.info.axes.at(0);
  const double px = a.x_map().to_pixel(x), row = a.pixel_box[3] + below;
  double best = 0;
  for (int c = static_cast<int>(std::floor(px - 0.5)); c <= static_cast<int>(std::floor(px + 0.5)); ++c)
    best = std::max(best, 1.0 - f.image.pixel(c, static_cast<int>(std::floor(row)))[1]);
  return best;
}

}  // namespace

TEST_CASE("log axes: minor ticks at 2..9 per decade, shorter than the decades' ticks") {
  const RenderedFigure f = log_axes("x_range = [1, 100]\nx_scale = \"log\"\n");
  REQUIRE(f.info.axes.at(0).x_ticks.size() == 3);  // 1, 10, 100
  for (double v : {2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 20.0, 30.0, 50.0, 90.0}) {
    INFO("minor tick at " << v);
    CHECK(tick_ink(f, v, 2) > 0.3);   // a tick 3 px long from 1 px under the box
    CHECK(tick_ink(f, v, 5) < 0.02);  // ... shorter than a decade's 5 px
  }
  for (double v : {1.5, 2.5, 15.0, 65.0}) CHECK(tick_ink(f, v, 2) < 0.02);  // nothing between
  CHECK(tick_ink(f, 10, 5) > 0.3);  // the decade's own tick runs 5 px
}

TEST_CASE("log axes: no minor ticks on linear axes or given ticks") {
  const RenderedFigure lin = log_axes("x_range = [1, 100]\nx_ticks = [1, 50, 100]\n");
  const RenderedFigure given = log_axes("x_range = [1, 100]\nx_scale = \"log\"\nx_ticks = [1, 10, 100]\n");
  for (double v : {2.0, 5.0, 20.0, 30.0}) {
    CHECK(tick_ink(lin, v, 2) < 0.02);
    CHECK(tick_ink(given, v, 2) < 0.02);
  }
}
