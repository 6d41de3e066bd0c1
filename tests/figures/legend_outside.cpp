// legend = "outside-right": the legend goes right of the plot box, which narrows to make room
// for it inside the panel; nothing of it is drawn over the data.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <string>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

std::string spec(const std::string& legend) {
  return "[canvas]\nwidth = 600\nheight = 300\n[axes]\nx_range = [0, 5]\ny_range = [0, 3]\nlegend = \"" + legend +
         "\"\n[[axes.series]]\npoints = [[0, 0], [5, 1]]\nlabel = \"a rising line\"\n"
         "[[axes.series]]\npoints = [[0, 1], [5, 0]]\nlabel = \"falling\"\n";
}

// Pixels of columns [x0, x1) and rows [y0, y1) that are not the white background.
int inked(const Image& im, int x0, int x1, int y0, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        if (im.at(x, y, c) < 0.9f) {
          ++n;
          break;
        }
  return n;
}

}  // namespace

TEST_CASE("legend outside-right: the box narrows and the legend is drawn right of it") {
  const FigureSpec inside = parse_spec(spec("upper right"), "in.toml");
  const FigureSpec outside = parse_spec(spec("outside-right"), "out.toml");
  const auto bin = layout_figure(inside).axes.at(0).pixel_box;
  const auto bout = layout_figure(outside).axes.at(0).pixel_box;
  CHECK(bout[0] == bin[0]);  // left, top and bottom stay
  CHECK(bout[1] == bin[1]);
  CHECK(bout[3] == bin[3]);
  // The legend's width: two rows of a 28 px sample, 8 px gaps and "a rising line" in 12 px text
  // are more than 100 px; and the box gives up no more than the panel has right of it.
  CHECK(bin[2] - bout[2] > 100);
  CHECK(bout[2] < 600 - 100);

  const Image in = render_figure(inside).image, out = render_figure(outside).image;
  const int right = static_cast<int>(bout[2]), top = static_cast<int>(bout[1]);
  // Right of the narrowed box: the legend (frame, samples, text) there, nothing in the inside case.
  CHECK(inked(out, right + 12, 600, top, top + 50) > 200);
  CHECK(inked(in, static_cast<int>(bin[2]) + 12, 600, 0, 300) == 0);  // past the last tick label
  // Nothing of the legend inside the box's upper right corner (the data keeps to the lower
  // third), where "upper right" puts it.
  CHECK(inked(out, right - 120, right - 2, top + 2, top + 40) == 0);
  CHECK(inked(in, static_cast<int>(bin[2]) - 120, static_cast<int>(bin[2]) - 12, top + 12, top + 40) > 200);
  // The spelling "outside right" is the same.
  CHECK(render_figure(parse_spec(spec("outside right"), "o.toml")).image.pixels == out.pixels);
}

TEST_CASE("legend outside-right: a wrong place names the choices") {
  try {
    parse_spec(spec("outside-left"), "bad.toml");
    FAIL("no error");
  } catch (const SpecFileError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("bad.toml:7: axes.legend"));
    CHECK_THAT(e.what(), Catch::Contains("outside-right"));
  }
}
