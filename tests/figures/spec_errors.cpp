// Bad figure specs: every one gives one line naming the file, the line and the key, and the
// commands write no output file.
#include "spec_error_check.hpp"
#include <catch2/catch.hpp>

#include <splinefig/figures/output.hpp>
#include <splinefig/figures/spec.hpp>

#include "support.hpp"

using splinefig::figures::parse_spec;
using splinefig::figures::SpecFileError;

namespace {

const char* kAxes = "[canvas]\nwidth = 100\nheight = 80\n[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n";

}  // namespace

TEST_CASE("bad specs name the file, the line and the key") {
  struct Case {
    std::string text, expect;  // expect: "bad.toml:LINE: KEY" prefix
  } cases[] = {
      {"[canvas]\nwidth = 100\ncolour = \"#fff\"\n", "bad.toml:3: canvas.colour: unknown key"},
      {"[canvas]\nwidth = \"wide\"\n", "bad.toml:2: canvas.width: expected an integer"},
      {"[gallery]\npixel_exact = \"yes\"\n", "bad.toml:2: gallery.pixel_exact: expected"},
      {"[gallery]\npixel = true\n", "bad.toml:2: gallery.pixel: unknown key"},
      {"[[polyline]]\npoints = [[0, 0], [1, 1]]\nwidth = -1\n", "bad.toml:3: polyline[0].width: must not be negative"},
      {"[[polyline]]\npoints = [[0, 0], [nan, 1]]\n", "bad.toml:2: polyline[0].points: expected a finite number, found nan"},
      {"[[polyline]]\npoints = [[0, 0], [1, 1]]\ncolor = \"red\"\n", "bad.toml:3: polyline[0].color: \"red\" is not a hex colour"},
      {"[[polyline]]\npoints = [[0, 0], [1, 1]]\ncolor = \"#12345\"\n", "bad.toml:3: polyline[0].color"},
      {"[canvas]\nwidth = 40000\nheight = 10\n", "bad.toml:2: canvas.width: larger than 32768 px"},
      {"[canvas]\nwidth = 20000\nheight = 20000\n", "bad.toml:3: canvas.height: canvas of 400000000 pixels is over the limit of 2^28"},
      {"[[polyline]]\npoints = []\n", "bad.toml:2: polyline[0].points: empty polyline"},
      {std::string(kAxes) + "[[axes.series]]\ncolor = \"#000000\"\n", "bad.toml:7: axes.series[0].points: a series without data"},
      {std::string(kAxes) + "[[axes.series]]\nx = [1, 2]\ny = [1]\n", "bad.toml:9: axes.series[0].y: x has 2 values but y has 1"},
      {"[axes]\nx_range = [1, 1]\n", "bad.toml:2: axes.x_range: x0 = x1"},
      {std::string(kAxes) + "[[axes.kernel]]\nbasis = \"catmul-rom\"\n", "bad.toml:8: axes.kernel[0].basis: basis \"catmul-rom\""},
      {std::string(kAxes) + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\nbasis = \"beta:b1=-1,b2=0\"\n",
       "bad.toml:9: axes.curve[0].basis: basis \"beta:b1=-1,b2=0\""},
      {std::string(kAxes) + "[[axes.curve]]\nknots = [[0, 0], [1, 1]]\n", "bad.toml:8: axes.curve[0].knots: 2 knots are too few"},
      {std::string(kAxes) + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\ndash = [1, -1]\n",
       "bad.toml:9: axes.curve[0].dash: dash length -1 is negative"},
      {std::string(kAxes) + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\ndash = [0.0001]\n",
       "bad.toml:9: axes.curve[0].dash: dash pattern period 0.0001 px is below 0.001 px"},
      {std::string(kAxes) + "[[axes.curve]]\nknots = [[0, 0], [1, 1], [2, 0], [3, 1]]\nwidht = 2\n",
       "bad.toml:9: axes.curve[0].widht: unknown key"},
      {"[canvas]\nfilter = \"gauss\"\n", "bad.toml:2: canvas.filter: unknown filter 'gauss' (known: box, tent, lanczos3"},
      // A filter the renderer refuses as a pixel filter is refused at load, with the key.
      {"[canvas]\nfilter = \"uniform-bspline:degree=12\"\n",
       "bad.toml:2: canvas.filter: pixel filter 'uniform-bspline:degree=12': support wider than 8 px"},
      {"[canvas]\nwidth = 10\nfilter = \"lanczos3\"\n", "bad.toml:3: canvas.filter: pixel filter 'lanczos3': not a piecewise polynomial"},
      {"[[text]]\nat = [1, 2]\ntext = \"c_{3\"\n", "bad.toml:3: text[0].text"},
      {"[canvas]\nwidth = 10\n[canvas\n", "bad.toml:3"},
      {"[layout]\nrows = 1\ncols = 1\n[[axes]]\ncell = [1, 0]\n", "bad.toml:4: axes.cell: [1, 0] is outside the 1x1 layout"},
  };
  figtest::check_spec_errors(cases, "bad.toml");
}

TEST_CASE("good specs parse, keep document order and take the house defaults") {
  auto spec = parse_spec(
      "title = \"t\"\n[[text]]\nat = [1, 2]\ntext = \"a\"\n[[polyline]]\npoints = [[0, 0], [3, 4]]\n"
      "dash = [2]\n[[text]]\nat = [3, 4]\ntext = \"b\"\n",
      "good.toml");
  REQUIRE(spec.items.size() == 3);
  CHECK(std::holds_alternative<splinefig::figures::TextItem>(spec.items[0]));
  CHECK(std::holds_alternative<splinefig::figures::PolylineItem>(spec.items[1]));
  CHECK(std::get<splinefig::figures::TextItem>(spec.items[2]).text == "b");
  const auto& pl = std::get<splinefig::figures::PolylineItem>(spec.items[1]);
  CHECK(std::vector<double>(pl.pen.style.dashes.begin(), pl.pen.style.dashes.end()) == std::vector<double>{2, 2});  // an odd dash list repeats (SVG)
  CHECK(pl.pen.style.width == 1.0);
  CHECK(spec.canvas.width == 800);
  CHECK(spec.canvas.height == 500);
  CHECK(spec.name == "good");
}

TEST_CASE("filter and edge names are read as their values at load") {
  using namespace splinefig::figures;
  auto spec = parse_spec(std::string("[canvas]\nwidth = 100\nheight = 80\nfilter = \"tent\"\n[axes]\nx_range = [0, 1]\n"
                                     "y_range = [0, 1]\n[[axes.step]]\nfilter = \"bspline\"\nedge = \"wrap\"\n"
                                     "[[axes.zoneplate]]\nfilter = \"box\"\nsource = 8\n"),
                         "good.toml");
  // The tent 1 - |s| on [-1, 1]: 1/2 at s = 1/2.
  CHECK(spec.canvas.filter.support().lo == -1);
  CHECK(spec.canvas.filter.support().hi == 1);
  CHECK(spec.canvas.filter(0.5) == Approx(0.5));
  CHECK(parse_spec("[canvas]\nwidth = 10\n", "good.toml").canvas.filter(0.25) == 1);  // the box
  const auto& ax = std::get<AxesSpec>(spec.items.at(0));
  REQUIRE(ax.elements.size() == 2);
  const auto& step = std::get<StepElement>(ax.elements[0]);
  CHECK(step.edge == splinefig::Edge::wrap);
  // The cubic B-spline (4 - 6 s^2 + 3 |s|^3) / 6: 2/3 at 0, 1/6 at 1, support [-2, 2].
  CHECK(step.filter(0) == Approx(2.0 / 3));
  CHECK(step.filter(1) == Approx(1.0 / 6));
  CHECK(step.filter.support().hi == 2);
  CHECK(std::get<ZoneplateElement>(ax.elements[1]).edge == splinefig::Edge::mirror);  // its default
}

TEST_CASE("splinefig render: a bad spec fails with one line and writes nothing") {
  auto dir = figtest::scratch("render-bad");
  auto spec = dir / "bad.toml";
  std::ofstream(spec) << "[canvas]\nwidth = 64\nheight = 64\n[[polyline]]\npoints = [[0, 0], [1, 1]]\nwidth = -2\n";
  auto out = dir / "out.png";
  auto r = figtest::run(figtest::exe() + " render " + spec.string() + " -o " + out.string());
  CHECK(r.code != 0);
  CHECK(r.out == "splinefig render: " + spec.string() + ":6: polyline[0].width: must not be negative, found -2\n");
  CHECK_FALSE(figtest::fs::exists(out));
  CHECK(figtest::fs::directory_iterator(dir) != figtest::fs::directory_iterator());  // only bad.toml
  int files = 0;
  for ([[maybe_unused]] auto& e : figtest::fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
}

TEST_CASE("splinefig render: bad flags and scales that make the canvas too large") {
  auto dir = figtest::scratch("render-flags");
  auto spec = dir / "ok.toml";
  std::ofstream(spec) << "[canvas]\nwidth = 20000\nheight = 100\n";
  auto r = figtest::run(figtest::exe() + " render " + spec.string() + " -o " + (dir / "x.jpg").string());
  CHECK(r.code != 0);
  CHECK(r.out.find("must end in .png, .exr, .svg or .pdf") != std::string::npos);
  r = figtest::run(figtest::exe() + " render " + spec.string() + " -o " + (dir / "x.png").string() + " --scale 2");
  CHECK(r.code != 0);
  CHECK(r.out.find("--scale: the scaled canvas 40000x200 is larger than 32768 px a side") != std::string::npos);
  CHECK_FALSE(figtest::fs::exists(dir / "x.png"));
  r = figtest::run(figtest::exe() + " render " + (dir / "missing.toml").string() + " -o " + (dir / "x.png").string());
  CHECK(r.code != 0);
  CHECK(r.out.find("missing.toml: cannot read the spec file") != std::string::npos);
}

TEST_CASE("splinefig figures: unknown names and formats are errors") {
  auto dir = figtest::scratch("figures-bad");
  auto r = figtest::run(figtest::exe() + " figures --out " + dir.string() + " --only nosuchfigure");
  CHECK(r.code != 0);
  CHECK(r.out.find("--only nosuchfigure: no such figure") != std::string::npos);
  r = figtest::run(figtest::exe() + " figures --out " + dir.string() + " --only cbasis --format png,tiff");
  CHECK(r.code != 0);
  CHECK(r.out.find("\"tiff\" is not png, exr, svg or pdf") != std::string::npos);
  CHECK_FALSE(figtest::fs::exists(dir / "cbasis.png"));
}

TEST_CASE("an output format is named once: by its name or a path's extension, in any case") {
  namespace fig = splinefig::figures;
  CHECK(fig::format_named("png") == fig::Format::png);
  CHECK(fig::format_named("PDF") == fig::Format::pdf);
  CHECK_FALSE(fig::format_named("tif"));
  CHECK_FALSE(fig::format_named(""));
  CHECK(fig::format_of_path("out/Fig.SVG") == fig::Format::svg);
  CHECK(fig::format_of_path("a.b/fig.exr") == fig::Format::exr);
  CHECK_FALSE(fig::format_of_path("a.png/fig"));
  CHECK_FALSE(fig::format_of_path(".png"));  // a hidden file with no extension
  for (fig::Format f : {fig::Format::png, fig::Format::exr, fig::Format::svg, fig::Format::pdf})
    CHECK(fig::format_named(fig::extension(f)) == f);
}
