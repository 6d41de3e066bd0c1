// [[axes.relaxed_bspline]] show = "aframes": one A per interior control point B_i (seed 003
// §3-4), and `aframe = i` for the one at B_i alone. With B_1 = (1, 3), B_2 = (3, 3.5),
// B_3 = (4, 1) (seed 003 Figure 10's polygon), by hand: the A at B_2 has legs from
// (2 B_1 + B_2)/3 = (5/3, 19/6) and (2 B_3 + B_2)/3 = (11/3, 11/6) up to B_2, and its cross-bar
// from (B_1 + 2 B_2)/3 = (7/3, 10/3) to (2 B_2 + B_3)/3 = (10/3, 8/3), through S_2 = (17/6, 3).
// The A at B_1 has legs from (1/3, 1) and (7/3, 10/3) up to B_1.
#include <catch2/catch.hpp>

#include "ink.hpp"
#include "spec_error_check.hpp"

#include <string>

using figtest::ink_near;

namespace {

const std::string kPolygon = "points = [[0, 0], [1, 3], [3, 3.5], [4, 1], [6, 0.5], [7, 3], [9, 3.5]]\n";

std::string aframes_spec(const std::string& extra) {
  return "[canvas]\nwidth = 500\nheight = 300\n[axes]\nx_range = [-0.5, 9.5]\ny_range = [-0.5, 4]\n"
         "frame = \"none\"\nlegend = \"none\"\n[[axes.relaxed_bspline]]\n" + kPolygon +
         "show = \"aframes\"\ncolor = \"#000000\"\n" + extra;
}

}  // namespace

TEST_CASE("relaxed_bspline aframe = i draws the A-frame at B_i alone") {
  const auto one = figtest::render_text_spec(aframes_spec("aframe = 2\n"));
  CHECK(ink_near(one, 8.0 / 3, 41.0 / 12) > 0.9);   // its left leg, between (7/3, 10/3) and B_2
  CHECK(ink_near(one, 10.0 / 3, 8.0 / 3) > 0.9);     // its right leg, near the cross-bar's end
  CHECK(ink_near(one, 17.0 / 6, 3) > 0.9);           // its cross-bar at S_2
  CHECK(ink_near(one, 4.0 / 3, 37.0 / 12) < 0.01);   // the A at B_1: its left leg, near B_1
  CHECK(ink_near(one, 2.0 / 3, 2) < 0.01);           // ... its leg's start half
  CHECK(ink_near(one, 5, 0.75) < 0.01);              // the A at B_4 (6, 0.5): the leg from B_3
  const auto all = figtest::render_text_spec(aframes_spec(""));
  CHECK(ink_near(all, 8.0 / 3, 41.0 / 12) > 0.9);
  CHECK(ink_near(all, 4.0 / 3, 37.0 / 12) > 0.9);
  CHECK(ink_near(all, 2.0 / 3, 2) > 0.9);
}

TEST_CASE("relaxed_bspline aframe outside 1 .. n-1 or without show = aframes is an error") {
  struct Case {
    std::string text, expect;
  } cases[] = {
      {aframes_spec("aframe = 6\n"), "bad.toml:13: axes.relaxed_bspline[0].aframe: must be in [1, 5], found 6"},
      {aframes_spec("aframe = 0\n"), "bad.toml:13: axes.relaxed_bspline[0].aframe: must be in [1, 5], found 0"},
      {"[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n[[axes.relaxed_bspline]]\n" + kPolygon + "aframe = 1\n",
       "bad.toml:6: axes.relaxed_bspline[0].aframe: needs show = \"aframes\""},
  };
  figtest::check_spec_errors(cases, "bad.toml");
}
