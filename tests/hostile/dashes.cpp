// Dashes are generated only over the visible part of a path, walked from where it enters the
// canvas (a path from x = -1e14 keeps its dash phase and ends), and a pattern too fine for its
// length and pen is refused before any dash is made.
#include "hostile.hpp"

using namespace splinefig::hostile;

TEST_CASE("a dashed polyline from x = -1e14 renders its visible dashes quickly") {
  check_renders("far_dash", "[canvas]\nwidth = 200\nheight = 100\n[[polyline]]\n"
                            "points = [[-1e14, 50], [100, 50], [100, -1e14]]\ndash = [4, 2]\nwidth = 2\n");
}

TEST_CASE("a dash pattern of 0.001 px on a path from -1e14 is refused naming the polyline") {
  check_refused("fine_dash", "[canvas]\nwidth = 200\nheight = 100\n[[polyline]]\n"
                             "points = [[-1e14, 50], [100, 50]]\ndash = [0.001]\n",
                "fine_dash.toml:4: polyline[0]: stroke_polyline: the dash pattern is too fine");
}

TEST_CASE("a dashed series through a point at 1e11 is refused naming the series") {
  check_refused("series_dash", "[axes]\nx_range = [0, 10]\ny_range = [0, 10]\n[[axes.series]]\n"
                               "points = [[0, 0], [1e11, 5], [5, 5]]\ndash = [0.001]\n",
                "series_dash.toml:4: axes.series[0]: stroke_polyline: the dash pattern is too fine");
}

TEST_CASE("round-capped dashes shorter than their pen are refused before they are made") {
  check_refused("round_dash", "[canvas]\nwidth = 1000\nheight = 100\n[[polyline]]\n"
                              "points = [[0, 50], [900, 50], [0, 52], [900, 54]]\ndash = [0.1]\nwidth = 20\n"
                              "cap = \"round\"\njoin = \"round\"\n",
                "round_dash.toml:4: polyline[0]: stroke_polyline: the dash pattern is too fine");
}
