// [[axes.filter]]: a filter's k(s) drawn over the axis, with every jump upright. The box
// k(s) = 1 on [-1/2, 1/2) and 0 elsewhere, and the tent 1 - |s| on [-1, 1], are known by
// definition; the tests look for the curve's pixels where those say it must be.
#include <catch2/catch.hpp>

#include "ink.hpp"

#include <string>

using figtest::ink_near;
using splinefig::figures::RenderedFigure;

namespace {

// One black filter curve, 2 px wide, on an axes without zero line, frame, ticks or legend.
RenderedFigure filter_figure(const std::string& filter, const std::string& range_key) {
  return figtest::render_text_spec("[canvas]\nwidth = 400\nheight = 300\n[axes]\nx_range = [-2.5, 2.5]\n"
                                   "y_range = [-0.5, 1.5]\nframe = \"none\"\nlegend = \"none\"\n"
                                   "[[axes.filter]]\nfilter = \"" + filter + "\"\ncolor = \"#000000\"\n" + range_key);
}

}  // namespace

TEST_CASE("filter curves: the box's jumps are drawn upright at both -1/2 and +1/2") {
  for (const std::string range : {"", "range = [-0.5, 0.5]\n"}) {
    INFO("range key: '" << range << "'");
    RenderedFigure f = filter_figure("box", range);
    for (double y : {0.25, 0.5, 0.75}) {
      CHECK(ink_near(f, -0.5, y) > 0.9);
      CHECK(ink_near(f, 0.5, y) > 0.9);
      CHECK(ink_near(f, 0.0, y) < 0.01);  // inside the box: nothing between the edges
    }
    CHECK(ink_near(f, 0.0, 1.0) > 0.9);  // the top
  }
}

TEST_CASE("filter curves: without a range a kernel is drawn over the whole axis, zero outside its support") {
  RenderedFigure tent = filter_figure("tent", "");
  for (double x : {-2.3, -1.6, 1.6, 2.3}) CHECK(ink_near(tent, x, 0.0) > 0.9);
  CHECK(ink_near(tent, 0.0, 1.0) > 0.9);
  RenderedFigure box = filter_figure("box", "");
  for (double x : {-2.3, -1.2, 1.2, 2.3}) CHECK(ink_near(box, x, 0.0) > 0.9);
  // A range given is kept: nothing beyond it.
  RenderedFigure kept = filter_figure("tent", "range = [-1, 1]\n");
  for (double x : {-2.3, -1.6, 1.6, 2.3}) CHECK(ink_near(kept, x, 0.0) < 0.01);
}
