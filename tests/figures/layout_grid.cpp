// The layout of small and crowded panels: over a grid of canvas sizes, label lengths, titles
// and ranges, every panel either lays out with its text boxes apart, outside the plot box and
// inside the canvas, or is refused in one line naming the axes and the plot box it would get;
// a few cases rendered, their ink read off the pixels.
#include <catch2/catch.hpp>

#include <splinefig/figures/axes.hpp>
#include <splinefig/figures/figure.hpp>

#include "support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

using namespace splinefig::figures;

namespace {

using Box = std::array<double, 4>;  // left, top, right, bottom

bool meet(const Box& a, const Box& b) { return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]; }
bool inside(const Box& a, const Box& outer) {
  return a[0] >= outer[0] && a[1] >= outer[1] && a[2] <= outer[2] && a[3] <= outer[3];
}

const std::string kLong = "a label of forty characters, no shorter";  // 39 + 1 below
static_assert(sizeof("a label of forty characters, no shorter") - 1 == 39);

std::string spec_text(int w, int h, const std::string& label, bool title, const std::string& y_range, bool rotated,
                      bool data = true, bool legend = false) {
  std::string s = "[canvas]\nwidth = " + std::to_string(w) + "\nheight = " + std::to_string(h) + "\n[axes]\n";
  if (title) s += "title = \"" + (label.size() > 20 ? label : std::string("Step response")) + "\"\n";
  if (!label.empty()) s += "x_label = \"" + label + "\"\ny_label = \"" + label + "\"\n";
  if (rotated) s += "y_label_rotated = true\n";
  s += "x_range = [0, 3]\ny_range = " + y_range + "\n";
  if (data) s += "[[axes.series]]\npoints = [[0, 0], [1, 0.4], [2, 0.6], [3, 0.65]]\n";
  if (data && legend) s += "label = \"measured\"\n";
  return s;
}

// The refusal: one line, the file and line of the axes table, the canvas, the plot box it
// would leave and what it needs.
bool refusal(const std::string& msg, int w, int h) {
  static const std::regex re(
      "grid\\.toml:4: axes: the canvas ([0-9]+)x([0-9]+) leaves a plot box of [0-9]+ x [0-9]+ px after its labels; "
      "it needs at least [0-9]+ x [0-9]+ px[^\n]*");
  std::smatch m;
  return std::regex_match(msg, m, re) && m[1] == std::to_string(w) && m[2] == std::to_string(h);
}

// Whether an axis's ticks are coarser than the nice ticks the box's length alone would give
// (the 1-2-5 rule of axes.hpp, one tick per 90 px across and 55 px up): for counting only.
bool coarser(const std::vector<double>& ticks, double lo, double hi, double pixels, double spacing) {
  if (ticks.size() < 2) return true;
  return ticks[1] - ticks[0] > 1.0001 * nice_step(lo, hi, std::clamp(pixels / spacing, 2.0, 12.0));
}

}  // namespace

TEST_CASE("layout grid: every panel fits with its texts apart and inside the canvas, or is refused in one line") {
  const std::vector<int> widths = {120, 160, 200, 240, 320, 480, 800}, heights = {80, 100, 160, 240, 400, 600};
  const std::vector<std::string> labels = {"", "time (s)", kLong + "."};
  const std::vector<std::array<double, 2>> ranges = {{-0.05, 0.7}, {0, 1e6}, {-1e-4, 1e-4}};
  const std::vector<std::string> range_text = {"[-0.05, 0.7]", "[0, 1e6]", "[-1e-4, 1e-4]"};
  REQUIRE(labels[2].size() == 40);
  int cases = 0, fit = 0, thinned = 0, refused = 0;
  for (int w : widths)
    for (int h : heights)
      for (const std::string& label : labels)
        for (bool title : {false, true})
          for (bool rotated : {false, true})
            for (bool legend : {false, true})
            for (size_t r = 0; r < ranges.size(); ++r) {
              if (rotated && label.empty()) continue;
              ++cases;
              const std::string text = spec_text(w, h, label, title, range_text[r], rotated, true, legend);
              CAPTURE(w, h, label, title, rotated, legend, range_text[r]);
              FigureInfo info;
              try {
                info = layout_figure(parse_spec(text, "grid.toml"));
              } catch (const SpecFileError& e) {
                const std::string msg = e.what();
                CAPTURE(msg);
                CHECK(refusal(msg, w, h));
                // Room enough: 320 x 240 and more with short labels always lays out.
                CHECK_FALSE((w >= 320 && h >= 240 && label.size() < 20));
                ++refused;
                continue;
              }
              REQUIRE(info.axes.size() == 1);
              const AxesInfo& a = info.axes[0];
              const Box canvas{0, 0, static_cast<double>(w), static_cast<double>(h)};
              // The guides' texts and the legend (no element texts: the series's label, if
              // any, is in the legend).
              std::vector<TextBox> boxes;
              for (const TextBox& t : a.text_boxes)
                if (t.what != "text") boxes.push_back(t);
              // Every text the spec asks for is there: both labels and the title.
              auto count = [&](const std::string& what) {
                return std::count_if(boxes.begin(), boxes.end(), [&](const TextBox& t) { return t.what == what; });
              };
              CHECK(count("title") == (title ? 1 : 0));
              CHECK(count("x label") == (label.empty() ? 0 : 1));
              CHECK(count("y label") == (label.empty() ? 0 : 1));
              CHECK(count("x tick label") >= 2);
              CHECK(count("y tick label") >= 2);
              CHECK(count("legend") == (legend ? 1 : 0));
              const Box plot = a.pixel_box;
              for (size_t i = 0; i < boxes.size(); ++i) {
                CAPTURE(boxes[i].what, boxes[i].box[0], boxes[i].box[1], boxes[i].box[2], boxes[i].box[3]);
                CHECK(inside(boxes[i].box, canvas));
                // The legend is inside the plot box (where no data is) or wholly outside it
                // (where none was free: legend_placement.cpp), every other text outside it.
                if (boxes[i].what == "legend") CHECK((inside(boxes[i].box, plot) || !meet(boxes[i].box, plot)));
                else CHECK_FALSE(meet(boxes[i].box, plot));
                for (size_t j = i + 1; j < boxes.size(); ++j) {
                  CAPTURE(boxes[j].what, boxes[j].box[0], boxes[j].box[1], boxes[j].box[2], boxes[j].box[3]);
                  CHECK_FALSE(meet(boxes[i].box, boxes[j].box));
                }
              }
              if (coarser(a.x_ticks, 0, 3, plot[2] - plot[0], 90) ||
                  coarser(a.y_ticks, ranges[r][0], ranges[r][1], plot[3] - plot[1], 55))
                ++thinned;
              else
                ++fit;
            }
  WARN("layout grid: " << cases << " cases: " << fit << " fit, " << thinned << " thinned, " << refused << " refused");
  CHECK(cases == 7 * 6 * 2 * (3 * 2 * 3 + 2 * 2 * 3));
  CHECK(thinned > 0);
  CHECK(refused > 0);
}

TEST_CASE("layout grid: the 240x160 figure with a title and both labels thins its y ticks to labels apart") {
  const FigureInfo info = layout_figure(parse_spec(spec_text(240, 160, "amplitude", true, "[-0.05, 0.7]", false), "grid.toml"));
  const AxesInfo& a = info.axes.at(0);
  // The box is about 30 px high: 0.0, 0.2, 0.4, 0.6 are 8 px apart, the labels 9 px high;
  // the next coarser steps 0.5 gives 0 and 0.5, 20 px apart.
  CHECK(a.pixel_box[3] - a.pixel_box[1] < 40);
  CHECK(a.y_ticks == std::vector<double>{0, 0.5});
}

TEST_CASE("layout grid: 200x100 with a title and both labels is refused, naming the axes, and writes nothing") {
  std::string msg;
  try {
    layout_figure(parse_spec(spec_text(200, 100, "amplitude", true, "[-0.05, 0.7]", false), "grid.toml"));
  } catch (const SpecFileError& e) {
    msg = e.what();
  }
  CAPTURE(msg);
  CHECK(refusal(msg, 200, 100));
  // The command: exit 2, the one line on stderr, no file.
  const figtest::fs::path dir = figtest::scratch("layout-grid-refused");
  {
    std::ofstream(dir / "grid.toml") << spec_text(200, 100, "amplitude", true, "[-0.05, 0.7]", false);
  }
  const figtest::Result r =
      figtest::run(figtest::exe() + " render " + (dir / "grid.toml").string() + " -o " + (dir / "out.png").string());
  CAPTURE(r.out);
  CHECK(r.code == 2);
  CHECK(r.out == "splinefig render: " + (dir / "grid.toml").string() + msg.substr(std::string("grid.toml").size()) + "\n");
  CHECK_FALSE(figtest::fs::exists(dir / "out.png"));
}

namespace {

// Ink: a pixel visibly darker than the white background in any channel.
bool ink(const RenderedFigure& f, int x, int y) {
  const float* px = f.image.pixel(x, y);
  return px[0] < 0.98f || px[1] < 0.98f || px[2] < 0.98f;
}

}  // namespace

TEST_CASE("layout grid: rendered, no ink lies inside an empty plot box or outside the texts and the frame") {
  struct Case {
    int w, h;
    std::string label;
    bool title, rotated;
    std::string y_range;
  };
  const std::vector<Case> cases = {{240, 160, "amplitude", true, false, "[-0.05, 0.7]"},
                                   {200, 140, "amplitude", false, false, "[-0.05, 0.7]"},
                                   {320, 200, "time (s)", true, true, "[0, 1e6]"},
                                   {160, 240, "x", true, false, "[-1e-4, 1e-4]"},
                                   {800, 500, "time (s)", true, true, "[-0.05, 0.7]"}};
  for (const Case& c : cases) {
    CAPTURE(c.w, c.h, c.label, c.title, c.rotated, c.y_range);
    FigureSpec spec = parse_spec(spec_text(c.w, c.h, c.label, c.title, c.y_range, c.rotated, false), "grid.toml");
    const RenderedFigure f = render_figure(spec, {1, 1});
    const AxesInfo& a = f.info.axes.at(0);
    const int l = static_cast<int>(a.pixel_box[0]), t = static_cast<int>(a.pixel_box[1]),
              r = static_cast<int>(a.pixel_box[2]), b = static_cast<int>(a.pixel_box[3]);
    // The spines lie on the pixels just outside the box, the ticks 5 px beyond: a band of 7 px
    // around the box; each text may ink 2 px past its box (antialiasing, side bearings).
    auto expected = [&](int x, int y) {
      const bool band = x >= l - 7 && x < r + 7 && y >= t - 7 && y < b + 7 && !(x >= l && x < r && y >= t && y < b);
      if (band) return true;
      for (const TextBox& tb : a.text_boxes)
        if (x + 1 > tb.box[0] - 2 && x < tb.box[2] + 2 && y + 1 > tb.box[1] - 2 && y < tb.box[3] + 2) return true;
      return false;
    };
    long inside_box = 0, stray = 0;
    for (int y = 0; y < f.image.height; ++y)
      for (int x = 0; x < f.image.width; ++x) {
        if (!ink(f, x, y)) continue;
        if (x >= l && x < r && y >= t && y < b) ++inside_box;
        else if (!expected(x, y)) ++stray;
      }
    CHECK(inside_box == 0);
    CHECK(stray == 0);
    // The y tick labels, left of the ticks and above the x tick labels, are as many separate
    // bands of inked rows as there are y ticks (labels piled on each other merge).
    int bands = 0;
    bool in_band = false;
    for (int y = std::max(0, t - 7); y < std::min(f.image.height, b + 8); ++y) {
      bool row = false;
      for (int x = 0; x < l - 8; ++x) row = row || ink(f, x, y);
      if (row && !in_band) ++bands;
      in_band = row;
    }
    // A y label above the box ends 8 px above it and is not in these rows; a rotated one is
    // at the cell's left edge, in these rows: its band merges with none of the labels'
    // columns, so count only right of it.
    if (!c.rotated) CHECK(bands == static_cast<int>(a.y_ticks.size()));
  }
}

TEST_CASE("layout grid: an element's text over a tick label or off the canvas is an error naming the element") {
  const std::string head = "[canvas]\nwidth = 320\nheight = 200\n[axes]\nx_range = [0, 3]\ny_range = [0, 1]\n";
  auto message = [&](const std::string& element) {
    try {
      layout_figure(parse_spec(head + element, "text.toml"));
    } catch (const SpecFileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // 14 px below y = 0 is where the x tick labels are (9 px below the box, 9 px high).
  CHECK(message("[[axes.text]]\nat = [1, 0]\ntext = \"over the ticks\"\noffset = [0, 14]\n") ==
        "text.toml:7: axes.text[0]: its text would meet the axes' x tick label (the canvas 320x200)");
  CHECK(message("[[axes.text]]\nat = [3, 1]\ntext = \"past the right edge\"\noffset = [60, 0]\n") ==
        "text.toml:7: axes.text[0]: its text would leave the canvas (the canvas 320x200)");
  // Inside the box it is drawn, and listed.
  const FigureInfo info =
      layout_figure(parse_spec(head + "[[axes.text]]\nat = [1.5, 0.5]\ntext = \"inside\"\n", "text.toml"));
  const auto& boxes = info.axes.at(0).text_boxes;
  CHECK(std::count_if(boxes.begin(), boxes.end(), [](const TextBox& t) { return t.what == "text"; }) == 1);
}

TEST_CASE("layout grid: a figure title wider than the canvas shrinks inside it, or is refused in one line") {
  const std::string body = "[axes]\nx_range = [0, 3]\ny_range = [0, 1]\n";
  auto spec = [&](int w) {
    return "title = \"" + kLong + ".\"\n[canvas]\nwidth = " + std::to_string(w) + "\nheight = 200\n" + body;
  };
  // At 18 px bold the title is about 420 px wide: on 240 px it shrinks; its ink keeps off the
  // canvas's edge columns (a title cut by the edge inks them) and off the plot box.
  const RenderedFigure f = render_figure(parse_spec(spec(240), "title.toml"), {1, 1});
  const AxesInfo& a = f.info.axes.at(0);
  long edge = 0, title_ink = 0;
  for (int y = 0; y < static_cast<int>(a.pixel_box[1]) - 8; ++y) {
    edge += ink(f, 0, y) + ink(f, 1, y) + ink(f, f.image.width - 1, y) + ink(f, f.image.width - 2, y);
    for (int x = 0; x < f.image.width; ++x) title_ink += ink(f, x, y);
  }
  CHECK(edge == 0);
  CHECK(title_ink > 200);  // the title is drawn
  std::string msg;
  try {
    layout_figure(parse_spec(spec(80), "title.toml"));
  } catch (const SpecFileError& e) {
    msg = e.what();
  }
  CHECK(std::regex_match(msg, std::regex("title\\.toml:1: title: the canvas 80x200 leaves 80 px across for the title; "
                                         "it needs at least [0-9]+ px \\(its text at 9 px\\), or show_title = false")));
}
