// [canvas] print_width: a figure's printed width makes its font sizes points. The size a text
// is set at is read back from the layout (the ink box of a text of capitals, whose height is the
// cap height) and turned into points by hand: a point is width_px / (W * 72) pixels at 1x, and
// DejaVu Sans's capitals are 1493 font units tall in an em of 2048 (its 'glyf' table, read with
// fontTools: H, E and one all span y 0..1493). Also: the errors of bad print widths and sizes.
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include "spec_error_check.hpp"

#include <cmath>
#include <string>
#include <vector>

using namespace splinefig::figures;

namespace {

constexpr double kCapPerEm = 1493.0 / 2048.0;  // DejaVu Sans, H and E

// A panel whose tick labels, axis labels and annotation are all capitals (their ink box is the
// cap height tall), on an 800 x 500 canvas printed `print_width` wide (no key when empty).
std::string spec_text(const std::string& print_width, const std::string& extra = "") {
  std::string s = "[canvas]\nwidth = 800\nheight = 500\n";
  if (!print_width.empty()) s += "print_width = " + print_width + "\n";
  s += extra;
  s += "[axes]\nx_range = [0, 3]\ny_range = [0, 3]\nx_ticks = [1, 2]\nx_tick_labels = [\"H\", \"E\"]\n"
       "y_ticks = [1, 2]\ny_tick_labels = [\"EH\", \"HE\"]\nx_label = \"HEH\"\ny_label = \"EHE\"\n"
       "[[axes.series]]\npoints = [[0, 0], [3, 3]]\n"
       "[[axes.text]]\nat = [2.2, 0.6]\ntext = \"HHE\"\n";
  return s;
}

// The em of each text box of kind `what` in printed points: its height in output pixels over
// the output pixels of a point (scale x 800 px across `inches` x 72 points), over the cap height.
std::vector<double> ems_pt(const FigureInfo& info, const std::string& what, double scale, double inches) {
  const double px_per_pt = scale * 800 / (inches * 72);
  std::vector<double> out;
  for (const AxesInfo& ax : info.axes)
    for (const TextBox& t : ax.text_boxes)
      if (t.what == what) out.push_back((t.box[3] - t.box[1]) / px_per_pt / kCapPerEm);
  return out;
}

}  // namespace

TEST_CASE("print width: the default tick labels are 8 pt, axis labels 9 pt and annotations 8 pt as printed") {
  struct Case {
    std::string key;
    double inches;
  };
  // 3.5 in (a column), 6 in (a text width), 89 mm and 15.24 cm (6 in), 252 pt (3.5 in), a bare number.
  const std::vector<Case> cases = {{"\"3.5in\"", 3.5},  {"\"6in\"", 6},         {"\"89mm\"", 89 / 25.4},
                                   {"\"15.24cm\"", 6},  {"\"252pt\"", 3.5},     {"4.25", 4.25}};
  for (const Case& c : cases)
    for (double scale : {1.0, 2.0}) {
      INFO(c.key << " at scale " << scale);
      const FigureInfo info = layout_figure(parse_spec(spec_text(c.key), "pw.toml"), scale);
      for (const auto& [what, pt] : std::vector<std::pair<std::string, double>>{
               {"x tick label", 8}, {"y tick label", 8}, {"x label", 9}, {"y label", 9}, {"text", 8}}) {
        const std::vector<double> ems = ems_pt(info, what, scale, c.inches);
        INFO(what);
        REQUIRE(!ems.empty());
        for (double em : ems) {
          CHECK(em == Approx(pt).margin(0.01));
          CHECK(em >= 8 - 0.01);  // typeset like the text around it: 8-9 pt
          CHECK(em <= 9 + 0.01);
        }
      }
    }
}

TEST_CASE("print width: size keys are points, and without a print width they stay pixels as before") {
  // 6 in across 800 px: 800 / 432 px a point.
  const double px_per_pt = 800.0 / (6 * 72);
  const std::string sizes = "tick_size = 9.5\nlabel_size = 7\ntext_size = 10\n";
  const FigureInfo info = layout_figure(parse_spec(sizes + spec_text("\"6in\""), "pw.toml"), 1);
  for (double em : ems_pt(info, "x tick label", 1, 6)) CHECK(em == Approx(9.5).margin(0.01));
  for (double em : ems_pt(info, "x label", 1, 6)) CHECK(em == Approx(7).margin(0.01));
  for (double em : ems_pt(info, "text", 1, 6)) CHECK(em == Approx(10).margin(0.01));
  // An element's own size is in points too.
  const std::string own = spec_text("\"6in\"") + "size = 11\n";
  for (double em : ems_pt(layout_figure(parse_spec(own, "pw.toml"), 1), "text", 1, 6)) CHECK(em == Approx(11).margin(0.01));

  // No print width: the pixel sizes of before (tick labels 12 px, axis labels 13, texts 13), the
  // keys in pixels.
  const FigureInfo px = layout_figure(parse_spec(spec_text(""), "px.toml"), 1);
  auto heights = [](const FigureInfo& f, const std::string& what) {
    std::vector<double> h;
    for (const TextBox& t : f.axes.at(0).text_boxes)
      if (t.what == what) h.push_back(t.box[3] - t.box[1]);
    return h;
  };
  for (double h : heights(px, "x tick label")) CHECK(h == Approx(12 * kCapPerEm).margin(0.005));
  for (double h : heights(px, "x label")) CHECK(h == Approx(13 * kCapPerEm).margin(0.005));
  for (double h : heights(px, "text")) CHECK(h == Approx(13 * kCapPerEm).margin(0.005));
  const FigureInfo px_keys = layout_figure(parse_spec("tick_size = 10\n" + spec_text(""), "px.toml"), 1);
  for (double h : heights(px_keys, "x tick label")) CHECK(h == Approx(10 * kCapPerEm).margin(0.005));
  const FigureSpec old = parse_spec("title = \"t\"\n" + spec_text(""), "px.toml");
  CHECK(old.sizes.title == 18);
  CHECK(old.sizes.panel_title == 14);
  CHECK(old.sizes.legend == 12);
  CHECK(old.sizes.inline_label == 15);
  CHECK(!old.canvas.print_width);
  // The conversion itself, once, at the spec's location.
  const FigureSpec printed = parse_spec(spec_text("\"6in\""), "pw.toml");
  REQUIRE(printed.canvas.print_width);
  CHECK(printed.canvas.print_width->inches == 6);
  CHECK(printed.canvas.print_width->origin.str() == "pw.toml:4: canvas.print_width");
  CHECK(printed.sizes.title == Approx(10 * px_per_pt));
}

TEST_CASE("print width: bad print widths and sizes are refused in one line naming the file, line and key") {
  struct Case {
    std::string text, expect;
  };
  auto canvas = [](const std::string& value) { return "[canvas]\nwidth = 800\nprint_width = " + value + "\n"; };
  const std::vector<Case> cases = {
      {canvas("-3.5"), "pw.toml:3: canvas.print_width: must be positive, found -3.5"},
      {canvas("\"-3.5in\""), "pw.toml:3: canvas.print_width: must be positive, found \"-3.5in\""},
      {canvas("0"), "pw.toml:3: canvas.print_width: must be positive, found 0"},
      {canvas("\"0mm\""), "pw.toml:3: canvas.print_width: must be positive, found \"0mm\""},
      {canvas("nan"), "pw.toml:3: canvas.print_width: expected a finite number, found nan"},
      {canvas("-inf"), "pw.toml:3: canvas.print_width: expected a finite number, found inf"},
      {canvas("\"nanin\""), "pw.toml:3: canvas.print_width: \"nanin\" is not a length: write \"3.5in\""},
      {canvas("\"NaN mm\""), "pw.toml:3: canvas.print_width: \"NaN mm\" is not a length"},
      {canvas("\"3.5ft\""), "pw.toml:3: canvas.print_width: unknown unit \"ft\" in \"3.5ft\": write \"3.5in\", \"89mm\""},
      {canvas("\"3.5 px\""), "pw.toml:3: canvas.print_width: unknown unit \"px\" in \"3.5 px\""},
      {canvas("\"3.5\""), "pw.toml:3: canvas.print_width: \"3.5\" has no unit: write \"3.5in\""},
      {canvas("\"1e400in\""), "pw.toml:3: canvas.print_width: \"1e400in\" is out of range"},
      {canvas("\"2000in\""), "pw.toml:3: canvas.print_width: \"2000in\" is over the limit of 1000 in"},
      {canvas("true"), "pw.toml:3: canvas.print_width: must be a length: \"3.5in\""},
      // 800 px across 900 in: under a pixel an inch, no file could record it.
      {canvas("\"900in\""), "pw.toml:3: canvas.print_width: 800 px across 900 in is 0.888889 px per inch, outside [1, 10000]"},
      // 800 px across 0.01 in: 80000 px an inch (a point 1111 px, the default title 11111 px).
      {canvas("\"0.01in\""), "pw.toml:3: canvas.print_width: 800 px across 0.01 in is 80000 px per inch, outside [1, 10000]"},
      {"tick_size = 5000\n" + canvas("\"3.5in\""),
       "pw.toml:1: tick_size: font size 5000 pt is 15873 px at the print width, over the limit of 4096 px"},
      {"legend_size = -8\n" + canvas("\"3.5in\""), "pw.toml:1: legend_size: must be positive, found -8"},
      {"label_size = \"9pt\"\n", "pw.toml:1: label_size: expected a number, found a string"},
  };
  figtest::check_spec_errors(cases, "pw.toml");
}
