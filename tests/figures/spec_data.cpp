// Point data a spec does not type where it is used: KEY_file = "x.csv" (CSV by the command
// line's rules, relative to the spec) and [data] NAME = [[x, y], ...] used as KEY = "NAME".
// Each gives the same spec as the points typed inline; bad data is one line naming the spec's
// line and key, and the data file's line.
#include "spec_error_check.hpp"
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace splinefig::figures;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-specdata-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

const std::string kKnots = "[[0, 0], [1, 2], [3, 1], [4, 3], [5, 0]]";
const std::string kCanvas = "[canvas]\nwidth = 160\nheight = 120\n";

// A polygon, a curve and markers over the same knots, written as `ref` says for each.
std::string spec_with(const std::string& head, const std::string& ref) {
  return kCanvas + head + "[[polygon]]\n" + "points" + ref + "\n" + "[axes]\nx_range = [0, 5]\ny_range = [0, 3]\n" +
         "[[axes.curve]]\nknots" + ref + "\nbasis = \"catmull-rom\"\n" + "[[axes.markers]]\npoints" + ref + "\n";
}

bool same(const std::vector<std::vector<splinefig::figures::Vec2>>& a, const std::vector<std::vector<splinefig::figures::Vec2>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (std::size_t j = 0; j < a[i].size(); ++j)
      if (a[i][j].x != b[i][j].x || a[i][j].y != b[i][j].y) return false;
  }
  return true;
}

std::string load_error(const fs::path& spec) {
  try {
    load_spec(spec.string());
  } catch (const SpecFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("spec data: [data] names and points_file give the spec of the inline points") {
  const fs::path dir = scratch("same");
  const std::string inline_spec = spec_with("", " = " + kKnots);
  const FigureSpec a = parse_spec(inline_spec, "s.toml");
  const auto& poly = std::get<PolygonItem>(a.items.at(0));
  REQUIRE(poly.contours.at(0).size() == 5);
  CHECK(poly.contours[0][1].x == 1);
  CHECK(poly.contours[0][1].y == 2);
  const auto pixels = render_figure(a).image.pixels;

  const FigureSpec named = parse_spec(spec_with("[data]\nknots = " + kKnots + "\n", " = \"knots\""), "s.toml");
  CHECK(same(std::get<PolygonItem>(named.items.at(0)).contours, poly.contours));
  CHECK(render_figure(named).image.pixels == pixels);

  // A header line, comments and blanks as on the command line.
  write_text(dir / "knots.csv", "# the memo's knots\nx,y\n0,0\n1,2\n\n3,1\n4,3\n5,0\n");
  fs::create_directories(dir / "sub");
  write_text(dir / "sub" / "fig.toml", spec_with("", "_file = \"../knots.csv\""));
  const FigureSpec from_file = load_spec((dir / "sub" / "fig.toml").string());  // relative to the spec
  CHECK(same(std::get<PolygonItem>(from_file.items.at(0)).contours, poly.contours));
  CHECK(render_figure(from_file).image.pixels == pixels);
  fs::remove_all(dir);
}

TEST_CASE("spec data: bad data files name the spec's line, the key and the file's line") {
  const fs::path dir = scratch("bad");
  const auto spec = dir / "fig.toml";
  auto with_file = [&](const std::string& csv) {
    write_text(dir / "knots.csv", csv);
    write_text(spec, kCanvas + "[[polyline]]\npoints_file = \"knots.csv\"\n");
    return load_error(spec);
  };
  const std::string at = spec.string() + ":5: polyline[0].points_file: ";
  CHECK(with_file("0,0\n1,1\n2,x\n") == at + "knots.csv line 3, field 2: 'x' is not a number");
  CHECK(with_file("x,y\n0,0\n1,1,1\n") == at + "knots.csv line 3: 3 coordinates, but the header on line 1 names 2");
  CHECK(with_file("0,0,0\n1,1,1\n") == at + "knots.csv: 3 coordinates per line, a point is x,y");
  CHECK(with_file("# nothing\n") == at + "knots.csv: no points in the file");
  CHECK(with_file(std::string("0,0\n1,\0", 7)) == at + "knots.csv line 2: a NUL byte: the input is not text");
  fs::remove(dir / "knots.csv");
  CHECK(load_error(spec) == at + "no such data file \"" + (dir / "knots.csv").string() + "\"");
  fs::create_directories(dir / "knots.csv");
  CHECK(load_error(spec) == at + "\"" + (dir / "knots.csv").string() + "\" is not a regular file");
  fs::remove_all(dir);
}

TEST_CASE("spec data: wrong types, unknown names and doubled keys are errors naming the key") {
  const std::string line = kCanvas + "[[polyline]]\n";
  struct Case {
    std::string text, expect;
  } cases[] = {
      {line + "points_file = 3\n", "s.toml:5: polyline[0].points_file: expected the name of a CSV file (a string)"},
      {line + "points_file = \"\"\n", "s.toml:5: polyline[0].points_file: expected the name of a CSV file"},
      {line + "points = [[0, 0], [1, 1]]\npoints_file = \"k.csv\"\n",
       "s.toml:6: polyline[0].points_file: give either points or points_file, not both"},
      {line + "points = \"knots\"\n", "s.toml:5: polyline[0].points: no data named \"knots\" (the spec has no [data] table)"},
      {"[data]\nknots = " + kKnots + "\nother = [[0, 0]]\n" + line + "points = \"knot\"\n",
       "s.toml:8: polyline[0].points: no data named \"knot\" (known: knots other)"},
      {"[data]\nknots = 3\n", "s.toml:2: data.knots: expected an array of points [[x, y], ...]"},
      {"[data]\nknots = [[0, 0], [1]]\n", "s.toml:2: data.knots"},
      {"[data]\nknots = []\n", "s.toml:2: data.knots: no points"},
      {"data = 3\n", "s.toml:1: data: expected a table [data] of named point lists"},
      {"[[data]]\nknots = [[0, 0]]\n", "s.toml:1: data: expected a table [data]"},
      {"[data]\n\"two words\" = [[0, 0]]\n", "s.toml:2: data.two words: a data name is letters, digits"},
      // Only where points are read: elsewhere KEY_file is an unknown key.
      {kCanvas + "[[circle]]\ncenter = [1, 1]\nradius = 1\ncenter_file = \"c.csv\"\n", "s.toml:7: circle[0].center_file: unknown key"},
  };
  figtest::check_spec_errors(cases, "s.toml");
}
