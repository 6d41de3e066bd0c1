// The panel grid: explicit and automatic cells, and the boxes they give.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/sampling.hpp>

#include <cmath>

using namespace splinefig::figures;

namespace {

bool overlap(const AxesInfo& a, const AxesInfo& b) {
  return a.pixel_box[0] < b.pixel_box[2] && b.pixel_box[0] < a.pixel_box[2] && a.pixel_box[1] < b.pixel_box[3] &&
         b.pixel_box[1] < a.pixel_box[3];
}

}  // namespace

TEST_CASE("layout: automatic placement skips cells that an explicit cell claimed") {
  // Three panels in a 1x3 grid: the first asks for the middle cell, the other two are placed
  // automatically and must take the left and the right cells, in reading order.
  const FigureSpec spec = parse_spec(
      "[canvas]\nwidth = 600\nheight = 200\n[layout]\nrows = 1\ncols = 3\n"
      "[[axes]]\ncell = [0, 1]\nx_range = [0, 1]\ny_range = [0, 1]\n"
      "[[axes]]\nx_range = [0, 1]\ny_range = [0, 1]\n"
      "[[axes]]\nx_range = [0, 1]\ny_range = [0, 1]\n",
      "layout.toml");
  const FigureInfo info = layout_figure(spec);
  REQUIRE(info.axes.size() == 3);
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = i + 1; j < 3; ++j) {
      INFO("panels " << i << " and " << j);
      CHECK_FALSE(overlap(info.axes[i], info.axes[j]));
    }
  // Cells are 600 - 2*16 - 2*24 = 520 / 3 wide: left [16, 189.3], middle [213.3, 386.7],
  // right [410.7, 584]; each plot box lies inside its own cell.
  const double w = (600.0 - 2 * 16 - 2 * 24) / 3;
  auto inside_cell = [&](const AxesInfo& a, int col) {
    const double left = 16 + col * (w + 24), right = left + w;
    return a.pixel_box[0] >= left - 1e-9 && a.pixel_box[2] <= right + 1e-9;
  };
  CHECK(inside_cell(info.axes[0], 1));
  CHECK(inside_cell(info.axes[1], 0));
  CHECK(inside_cell(info.axes[2], 2));
}

TEST_CASE("layout: a grid with more automatic panels than free cells is an error naming the panel") {
  std::string msg;
  try {
    parse_spec("[layout]\nrows = 1\ncols = 2\n[[axes]]\ncell = [0, 0]\n[[axes]]\n[[axes]]\n", "full.toml");
  } catch (const SpecFileError& e) {
    msg = e.what();
  }
  CAPTURE(msg);
  CHECK(msg.rfind("full.toml:7: axes", 0) == 0);
  CHECK(msg.find("no free cell") != std::string::npos);
}

TEST_CASE("layout: the loader keeps generated elements as parameters, the layout computes them") {
  const std::string text =
      "[canvas]\nwidth = 200\nheight = 150\n[axes]\nx_range = [0, 4]\ny_range = [-1, 2]\n"
      "[[axes.lagrange]]\npoints = [[0, 0], [1, 1], [1, 2]]\n";
  // Loading only reads the parameters: the repeated x is found when the figure is laid out,
  // and the message still names the file, the line and the key.
  const FigureSpec spec = parse_spec(text, "gen.toml");
  const auto& ax = std::get<AxesSpec>(spec.items.at(0));
  REQUIRE(ax.elements.size() == 1);
  const auto* e = std::get_if<LagrangeElement>(&ax.elements[0]);
  REQUIRE(e != nullptr);
  CHECK(e->points.size() == 3);
  std::string msg;
  try {
    layout_figure(spec);
  } catch (const SpecFileError& x) {
    msg = x.what();
  }
  CAPTURE(msg);
  CHECK(msg.rfind("gen.toml:8: axes.lagrange[0].points: ", 0) == 0);
  CHECK(msg.find('\n') == std::string::npos);
}

TEST_CASE("layout: flat_parameters cuts a circle into chords within the tolerance") {
  // A circle of radius 100 px: a chord over the angle d lies 100 (1 - cos(d/2)) from its arc.
  const double r = 100, tol = 0.05;
  auto f = [&](double u) { return Vec2{r * std::cos(u), r * std::sin(u)}; };
  const double two_pi = 6.283185307179586;
  const std::vector<double> us = flat_parameters(f, 0, two_pi, tol, 3);
  REQUIRE(!us.empty());
  CHECK(us.back() == two_pi);
  double prev = 0, worst = 0;
  for (double u : us) {
    CHECK(u > prev);
    worst = std::max(worst, r * (1 - std::cos(0.5 * (u - prev))));
    prev = u;
  }
  CHECK(worst <= tol);
  // Not far more chords than needed: 2 pi / (2 acos(1 - tol / r)) = 99.3, so at most 2 x 128.
  CHECK(us.size() <= 256);
}

TEST_CASE("layout: a generated curve below zero on a log axis names its element") {
  const FigureSpec spec = parse_spec(
      "[canvas]\nwidth = 200\nheight = 150\n[axes]\nx_range = [0, 4]\ny_scale = \"log\"\ny_range = [0.1, 10]\n"
      "[[axes.lagrange]]\npoints = [[0, 1], [1, -2], [2, 3]]\n",
      "log.toml");
  std::string msg;
  try {
    render_figure(spec);
  } catch (const SpecFileError& e) {
    msg = e.what();
  }
  CHECK(msg == "log.toml:8: axes.lagrange[0]: a log y axis needs positive y data");
}
