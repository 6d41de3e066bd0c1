// The vector files themselves: exact curves as a handful of Bezier commands, sizes by --dpi,
// deterministic bytes, bad flags.
#include "figures/support.hpp"
#include "skip.hpp"

#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/vector/vector.hpp>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <regex>

namespace fig = splinefig::figures;

namespace {

struct PathCounts {
  int cubics = 0, lines = 0;
};

// The stroked paths of an SVG (text outlines are filled), in order.
std::vector<PathCounts> stroked_paths(const std::string& svg) {
  std::vector<PathCounts> out;
  const std::regex path("<path d=\"([^\"]*)\" fill=\"none\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it) {
    const std::string d = (*it)[1];
    out.push_back({static_cast<int>(std::count(d.begin(), d.end(), 'C')), static_cast<int>(std::count(d.begin(), d.end(), 'L'))});
  }
  return out;
}

std::string svg_of(const std::string& name) {
  const fig::FigureSpec spec = fig::load_spec(fig::builtin_specs_dir() + "/" + name + ".toml");
  return splinefig::vector::to_svg(fig::figure_scene(spec, 1).scene);
}

}  // namespace

TEST_CASE("a kernel in SVG is its four cubic pieces, not a polyline") {
  // cbasis: the Catmull-Rom kernel in two colours, c_3 c_2 and c_1 c_0, one C command per piece.
  int cubics = 0;
  for (const PathCounts& p : stroked_paths(svg_of("cbasis"))) {
    cubics += p.cubics;
    if (p.cubics > 0) CHECK(p.lines == 0);
    CHECK(p.lines <= 8);  // axes, ticks, rules: a few lines each
  }
  CHECK(cubics == 4);
}

TEST_CASE("spline curves in SVG: one Bezier command per segment") {
  // ends: six knots; open ends give 6 - 3 = 3 segments, doubled 6 + 2 - 3 = 5, closed 6. The
  // closed Catmull-Rom curve's control points leave its plot box (the tangent at (7, 3) is
  // ((0, 0) - (6, 1)) / 2, so a control point is at x = 7 + 1 = 8 > 7.7), the curve does not
  // (its x stays below 7.34): clipped, it is still its six pieces.
  std::vector<int> counts;
  for (const PathCounts& p : stroked_paths(svg_of("ends")))
    if (p.cubics > 0) {
      CHECK(p.lines == 0);
      counts.push_back(p.cubics);
    }
  std::sort(counts.begin(), counts.end());
  CHECK(counts == std::vector<int>{3, 3, 5, 5, 6, 6});
}

TEST_CASE("clipped curves in SVG are their Bezier pieces, not polylines") {
  // Every stroked path of these figures is short: a curve is a few C commands, not hundreds of
  // sampled points (axes, ticks, legend samples and polygons are a few lines each).
  for (const std::string name : {"ends", "cbasis-a"}) {
    INFO(name);
    const std::string svg = svg_of(name);
    const std::regex path("<path d=\"([^\"]*)\" fill=\"none\"");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it)
      CHECK((*it)[1].length() < 600);
  }
  // cbasis-a: the cardinal kernels C_a for a = 0, 0.25, 0.5, 0.75, 1, each four cubic pieces on
  // [-2, 2] (for a = 0 the outer two are zero). The lobes of a = 0.75 and 1 have control points
  // below the box (the piece -a u (1 - u)^2 has Bernstein coefficients 0, -a/3, 0, 0, and
  // -a/3 < -0.2 = the y range's bottom), the curves themselves not (their minimum is -4a/27).
  std::vector<PathCounts> kernels;
  for (const PathCounts& p : stroked_paths(svg_of("cbasis-a")))
    if (p.cubics > 0) kernels.push_back(p);
  REQUIRE(kernels.size() == 5);
  for (const PathCounts& k : kernels) {
    CHECK(k.cubics == 4);
    CHECK(k.lines == 0);
  }
}

TEST_CASE("a curve or kernel leaving its plot box is clipped there as Bezier pieces") {
  // The closed Catmull-Rom curve of `ends` (its y runs from -0.01 to 3.01) in two panels. With
  // y in [0.2, 2.8] it starts outside, at (0, 0): it enters in piece 0 (t ~ 0.26), leaves in
  // piece 4 (t ~ 0.74) and crosses the box again within piece 5 (t ~ 0.14 to 0.86): two parts,
  // of 5 pieces (the ends of 0 and 4, all of 1 to 3) and 1. With y in [-0.5, 2.8] it starts
  // inside and leaves only within pieces 4 and 5: one part, open, from piece 5 through piece 4.
  // The Catmull-Rom kernel with y in [-0.05, 1.1]: its lobes (minimum -2/27 at s = -4/3 and 4/3)
  // dip below the box, each within its piece: three parts, of 1, 4 and 1 pieces.
  const std::string spec = R"(
[canvas]
width = 1200
height = 400
[layout]
cols = 3
[[axes]]
x_range = [-0.6, 7.7]
y_range = [0.2, 2.8]
cell = [0, 0]
[[axes.curve]]
knots = [[0, 0], [1, 2], [3, 2.5], [4, 0.5], [6, 1], [7, 3]]
basis = "catmull-rom"
ends = "closed"
color = "#1f77b4"
[[axes]]
x_range = [-0.6, 7.7]
y_range = [-0.5, 2.8]
cell = [0, 1]
[[axes.curve]]
knots = [[0, 0], [1, 2], [3, 2.5], [4, 0.5], [6, 1], [7, 3]]
basis = "catmull-rom"
ends = "closed"
color = "#d62728"
[[axes]]
x_range = [-2, 2]
y_range = [-0.05, 1.1]
cell = [0, 2]
[[axes.kernel]]
basis = "catmull-rom"
color = "#2ca02c"
)";
  const std::string svg = splinefig::vector::to_svg(fig::figure_scene(fig::parse_spec(spec, "clipped"), 1).scene);
  auto parts = [&](const std::string& colour) {
    std::vector<std::string> out;
    const std::regex path("<path d=\"([^\"]*)\" fill=\"none\" stroke=\"" + colour + "\"");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it)
      out.push_back((*it)[1]);
    return out;
  };
  auto count = [](const std::string& d, char c) { return std::count(d.begin(), d.end(), c); };
  const auto blue = parts("#1f77b4");
  REQUIRE(blue.size() == 2);
  CHECK(count(blue[0], 'C') == 5);
  CHECK(count(blue[1], 'C') == 1);
  const auto red = parts("#d62728");
  REQUIRE(red.size() == 1);
  CHECK(count(red[0], 'C') == 6);
  const auto green = parts("#2ca02c");
  REQUIRE(green.size() == 3);
  CHECK(count(green[0], 'C') == 1);
  CHECK(count(green[1], 'C') == 4);
  CHECK(count(green[2], 'C') == 1);
  for (const std::string& d : {blue[0], blue[1], red[0], green[0], green[1], green[2]}) {
    CHECK(count(d, 'L') == 0);
    CHECK(count(d, 'M') == 1);
    CHECK(count(d, 'Z') == 0);
  }
}

TEST_CASE("SVG draws each label as its outlines, the string in a transparent <text> over them") {
  const std::string svg = svg_of("cbasis");
  CHECK(svg.find("<title>cbasis: ") == std::string::npos);  // the file title is the caller's
  // The outlines are hidden from screen readers, which read the <text> (tests/vector/text_layer.cpp).
  CHECK(svg.find("<path aria-hidden=\"true\" d=\"") != std::string::npos);
  CHECK(svg.find("<text fill-opacity=\"0\"") != std::string::npos);
  CHECK(svg.find(">Cardinal spline basis function (Catmull-Rom, </tspan>") != std::string::npos);
}

TEST_CASE("dpi: PNG pHYs, EXR resolution, PDF page and SVG size follow one rule") {
  const auto dir = figtest::scratch("vector-dpi");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";  // 800 x 500
  auto render = [&](const std::string& out, const std::string& flags) {
    const auto r = figtest::run(figtest::exe() + " render " + spec + " -o " + (dir / out).string() + " " + flags);
    INFO(r.out);
    REQUIRE(r.code == 0);
    return (dir / out).string();
  };
  auto resolution = [](const std::string& file) {
    auto in = OIIO::ImageInput::open(file);
    REQUIRE(in);
    return in->spec().get_float_attribute("XResolution");
  };
  // 300 spec pixels per inch at scale 2: 600 image pixels per inch (pHYs stores pixels per
  // metre, 23622, which reads back as 599.9988).
  CHECK(resolution(render("c.png", "--dpi 300 --scale 2")) == Approx(600).epsilon(1e-5));
  CHECK(resolution(render("c.exr", "--dpi 300")) == Approx(300));
  // 800 / 300 inches = 192 points, 500 / 300 = 120; 96 CSS px per inch: 256 x 160 px.
  const std::string pdf = figtest::read_file(render("c.pdf", "--dpi 300 --scale 2"));
  CHECK(pdf.find("/MediaBox [ 0 0 192 120 ]") != std::string::npos);
  const std::string svg = figtest::read_file(render("c.svg", "--dpi 300"));
  CHECK(svg.find("width=\"256\" height=\"160\" viewBox=\"0 0 800 500\"") != std::string::npos);
  // Without --dpi, cbasis's print width, 6 in: 800 / 6 = 133.33 px per inch, a PDF page of
  // 6 x 72 = 432 by 500 / 800 x 432 = 270 points, an SVG of 6 x 96 = 576 by 360 CSS px.
  CHECK(resolution(render("p.png", "")) == Approx(800.0 / 6).epsilon(1e-4));
  CHECK(resolution(render("p.png", "--scale 2")) == Approx(1600.0 / 6).epsilon(1e-4));
  CHECK(figtest::read_file(render("p.pdf", "--scale 2")).find("/MediaBox [ 0 0 432 270 ]") != std::string::npos);
  CHECK(figtest::read_file(render("p.svg", "")).find("width=\"576\" height=\"360\" viewBox=\"0 0 800 500\"") !=
        std::string::npos);
  // Neither --dpi nor a print width: no pHYs, the CSS pixel for vector files (a 1x figure is
  // 800 px, 600 pt).
  const std::string plain = (dir / "plain.toml").string();
  {
    std::ofstream out(plain);
    out << "[canvas]\nwidth = 800\nheight = 500\n[[circle]]\ncenter = [400, 250]\nradius = 100\n";
  }
  auto render_plain = [&](const std::string& out, const std::string& flags) {
    const auto r = figtest::run(figtest::exe() + " render " + plain + " -o " + (dir / out).string() + " " + flags);
    INFO(r.out);
    REQUIRE(r.code == 0);
    return (dir / out).string();
  };
  CHECK(resolution(render_plain("d.png", "")) == 0);
  CHECK(figtest::read_file(render_plain("d.pdf", "--scale 2")).find("/MediaBox [ 0 0 600 375 ]") != std::string::npos);
  CHECK(figtest::read_file(render_plain("d.svg", "--scale 2")).find("width=\"800\" height=\"500\" viewBox=\"0 0 1600 1000\"") !=
        std::string::npos);
}

TEST_CASE("bad --dpi and unknown formats are one-line errors that write nothing") {
  const auto dir = figtest::scratch("vector-bad");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/cbasis.toml";
  for (const std::string dpi : {"0.5", "20000", "-3", "nan"}) {
    const auto r = figtest::run(figtest::exe() + " render " + spec + " -o " + (dir / "x.svg").string() + " --dpi " + dpi);
    INFO(dpi << ": " << r.out);
    CHECK(r.code != 0);
    CHECK(r.out.find("--dpi") != std::string::npos);
    CHECK_FALSE(figtest::fs::exists(dir / "x.svg"));
  }
  const auto r = figtest::run(figtest::exe() + " figures --out " + dir.string() + " --only cbasis --format svg,eps");
  CHECK(r.code != 0);
  CHECK(r.out.find("\"eps\" is not png, exr, svg or pdf") != std::string::npos);
  CHECK_FALSE(figtest::fs::exists(dir / "cbasis.svg"));
}

TEST_CASE("vector files are the same bytes for any thread count, the PDF date from SOURCE_DATE_EPOCH") {
  const auto dir = figtest::scratch("vector-same");
  const std::string spec = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/filter-zoneplate.toml";
  std::string bytes[2][2];
  for (int k = 0; k < 2; ++k)
    for (int f = 0; f < 2; ++f) {
      const std::string out = (dir / (std::string(f ? "z.pdf" : "z.svg"))).string();
      const auto r = figtest::run("SOURCE_DATE_EPOCH=1700000000 " + figtest::exe() + " render " + spec + " -o " + out +
                                  " --threads " + (k ? "1" : "2"));
      REQUIRE(r.code == 0);
      bytes[k][f] = figtest::read_file(out);
    }
  CHECK(bytes[0][0] == bytes[1][0]);
  CHECK(bytes[0][1] == bytes[1][1]);
  // 1700000000 s is 2023-11-14 22:13:20 UTC.
  CHECK(bytes[0][1].find("20231114221320") != std::string::npos);
  // The zone plate is embedded once, as PNG at its own size.
  CHECK(bytes[0][0].find("href=\"data:image/png;base64,") != std::string::npos);
}

TEST_CASE("write_vector names the file it cannot write and accepts only .svg and .pdf") {
  splinefig::render::Scene s(10, 10);
  CHECK_THROWS_WITH(splinefig::vector::write_vector("/nonexistent-dir/x.svg", s), Catch::Contains("/nonexistent-dir/x.svg"));
  CHECK_THROWS_WITH(splinefig::vector::write_vector("x.eps", s), Catch::Contains("x.eps"));
  CHECK(splinefig::vector::is_vector_file("A.SVG"));
  CHECK_FALSE(splinefig::vector::is_vector_file("a.png"));
}

TEST_CASE("SVG and PDF refuse a scene with clipped items, which only the rasterizer draws") {
  namespace r = splinefig::render;
  r::Scene s(10, 10);
  s.fill_circle({5, 5}, 2, {0, 0, 0, 1});
  CHECK(splinefig::vector::to_svg(s).find("<circle") != std::string::npos);  // unclipped: written
  r::Path clip;
  clip.move_to({0, 0}), clip.line_to({10, 0}), clip.line_to({10, 10}), clip.close();
  s.set_clip(clip);
  s.fill_circle({5, 5}, 3, {0, 0, 0, 1});
  CHECK_THROWS_WITH(splinefig::vector::to_svg(s), Catch::Contains("clipped items"));
  CHECK_THROWS_WITH(splinefig::vector::to_pdf(s), Catch::Contains("clipped items"));
}

TEST_CASE("generated splines in SVG: an interpolating spline, relaxed B-splines and cubic Bezier curves are their pieces") {
  // The cubic pieces of each curve, in drawing order (paths without a C are axes, ticks and
  // the polygons, which are polylines of their own).
  auto cubic_counts = [](const std::string& name) {
    std::vector<int> counts;
    for (const PathCounts& p : stroked_paths(svg_of(name)))
      if (p.cubics > 0) {
        CHECK(p.lines == 0);
        counts.push_back(p.cubics);
      }
    return counts;
  };
  CHECK(cubic_counts("s003-fig02") == std::vector<int>{10});    // 11 data points: 10 pieces
  CHECK(cubic_counts("s003-fig12") == std::vector<int>{6, 6});  // 7 control points each: 6 pieces
  CHECK(cubic_counts("s003-fig05") == std::vector<int>{1, 1});  // two cubic Bezier curves
}
