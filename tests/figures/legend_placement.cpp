// Legends never cover data: a legend goes to a spot in the plot box that no data reaches (the
// spec's own place when it is free), else outside the box; its entries run in the axes'
// legend_order, down each column. Checked from the layout's boxes (the legend's text box against
// every stroked polyline and marker of the data, with its half width, by exact segment-rectangle
// distances written here) and from pixels (where each entry's sample colour is drawn).
#include <catch2/catch.hpp>

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace splinefig;
using namespace splinefig::figures;

namespace {

using P = std::array<double, 2>;

// The distance from point q to the rectangle (0 inside).
double to_rect(P q, const std::array<double, 4>& r) {
  const double dx = std::max({r[0] - q[0], 0.0, q[0] - r[2]}), dy = std::max({r[1] - q[1], 0.0, q[1] - r[3]});
  return std::hypot(dx, dy);
}

// The distance from point q to the segment ab.
double to_segment(P q, P a, P b) {
  const double vx = b[0] - a[0], vy = b[1] - a[1], len2 = vx * vx + vy * vy;
  double t = len2 > 0 ? ((q[0] - a[0]) * vx + (q[1] - a[1]) * vy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(q[0] - a[0] - t * vx, q[1] - a[1] - t * vy);
}

// Whether segment ab crosses an edge of the rectangle (Liang-Barsky clipping).
bool crosses(P a, P b, const std::array<double, 4>& r) {
  double t0 = 0, t1 = 1;
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a[0] - r[0], r[2] - a[0], a[1] - r[1], r[3] - a[1]};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

// The least distance from the rectangle to the polyline (one point: to the point).
double to_polyline(const std::vector<P>& pts, const std::array<double, 4>& r) {
  double d = 1e300;
  if (pts.size() == 1) return to_rect(pts[0], r);
  const P corners[4] = {{r[0], r[1]}, {r[2], r[1]}, {r[2], r[3]}, {r[0], r[3]}};
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    if (crosses(pts[i], pts[i + 1], r)) return 0;
    d = std::min({d, to_rect(pts[i], r), to_rect(pts[i + 1], r)});
    for (P c : corners) d = std::min(d, to_segment(c, pts[i], pts[i + 1]));
  }
  return d;
}

// Every legend of the figure against every piece of its panel's data: the ink the data reaches
// must stay outside the legend's box. Returns how many legends were checked.
int check_legends_clear(const FigureInfo& info) {
  int legends = 0;
  for (std::size_t a = 0; a < info.axes.size(); ++a) {
    const AxesInfo& ax = info.axes[a];
    for (const TextBox& t : ax.text_boxes) {
      if (t.what != "legend") continue;
      ++legends;
      for (std::size_t k = 0; k < ax.data_ink.size(); ++k) {
        const auto& ink = ax.data_ink[k];
        const double d = to_polyline(ink.points, t.box);
        INFO(info.name << " panel " << a << ": the legend [" << t.box[0] << ", " << t.box[1] << ", " << t.box[2] << ", "
                       << t.box[3] << "] and data polyline " << k << " (" << ink.points.size() << " points, half width "
                       << ink.radius << ") at " << d << " px");
        CHECK(d > ink.radius);
      }
    }
  }
  return legends;
}

std::string two_series(const std::string& legend, const std::string& upper_right_data) {
  std::string s = "[canvas]\nwidth = 500\nheight = 320\n[axes]\nx_range = [0, 10]\ny_range = [0, 10]\nlegend = \"";
  s += legend;
  s += "\"\n[[axes.series]]\npoints = ";
  s += upper_right_data;
  s += "\nlabel = \"data in the upper right\"\n[[axes.series]]\npoints = [[0, 0], [1, 1]]\nlabel = \"a short line\"\n";
  return s;
}

// A zigzag over x in [x0, 10], y in [y0, 10], every half unit.
std::string zigzag(double x0, double y0) {
  std::string s = "[";
  bool up = false;
  for (double x = x0; x <= 10 + 1e-9; x += 0.5, up = !up) {
    if (s.size() > 1) s += ", ";
    s += '[';  // by appends (GCC 12 -Wrestrict, PR 105329, on "[" + s)
    s += std::to_string(x);
    s += ", ";
    s += std::to_string(up ? 10.0 : y0);
    s += ']';
  }
  return s + "]";
}

}  // namespace

TEST_CASE("no legend of a built-in figure covers its data") {
  int legends = 0, figures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs")) {
    if (entry.path().extension() != ".toml") continue;
    const FigureInfo info = layout_figure(load_spec(entry.path().string()));
    ++figures;
    legends += check_legends_clear(info);
  }
  CHECK(figures >= 33);
  CHECK(legends >= 12);  // not vacuous: the figures with legends
}

TEST_CASE("the direct labels of bbasis-a, s003-fig16 and bias cover no data and no other label") {
  // These figures label each curve next to it instead of in a legend the reader matches by colour.
  for (const char* name : {"bbasis-a", "s003-fig16", "bias"}) {
    const FigureInfo info =
        layout_figure(load_spec(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/" + name + ".toml"));
    REQUIRE(info.axes.size() == 1);
    const AxesInfo& ax = info.axes[0];
    std::vector<std::array<double, 4>> labels;
    for (const TextBox& t : ax.text_boxes) {
      CHECK(t.what != "legend");
      if (t.what == "text") labels.push_back(t.box);
    }
    CHECK(labels.size() == ax.series.size());  // one per labelled series
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const auto& r = labels[i];
      for (std::size_t k = 0; k < ax.data_ink.size(); ++k) {
        const auto& ink = ax.data_ink[k];
        const double d = to_polyline(ink.points, r);
        INFO(name << ": label " << i << " [" << r[0] << ", " << r[1] << ", " << r[2] << ", " << r[3] << "] and data polyline "
                  << k << " (half width " << ink.radius << ") at " << d << " px");
        CHECK(d > ink.radius);
      }
      for (std::size_t j = i + 1; j < labels.size(); ++j) {
        const auto& q = labels[j];
        INFO(name << ": labels " << i << " and " << j);
        CHECK((r[2] <= q[0] || q[2] <= r[0] || r[3] <= q[1] || q[3] <= r[1]));
      }
    }
  }
}

TEST_CASE("a legend asked for the upper right, where the data is, goes where it is not") {
  for (const std::string place : {"upper right", "auto"}) {
    INFO(place);
    const FigureInfo info = layout_figure(parse_spec(two_series(place, zigzag(4, 4)), "ur.toml"));
    REQUIRE(check_legends_clear(info) == 1);
    const AxesInfo& ax = info.axes.at(0);
    const auto legend = std::find_if(ax.text_boxes.begin(), ax.text_boxes.end(), [](const TextBox& t) { return t.what == "legend"; });
    // Inside the box, away from the upper right (the data fills x >= 4, y >= 4 of [0, 10]^2):
    // in its lower part or its left.
    CHECK(legend->box[0] >= ax.pixel_box[0]);
    CHECK(legend->box[2] <= ax.pixel_box[2]);
    CHECK(legend->box[3] <= ax.pixel_box[3]);
    CHECK((legend->box[1] > 0.5 * (ax.pixel_box[1] + ax.pixel_box[3]) || legend->box[2] < 0.5 * (ax.pixel_box[0] + ax.pixel_box[2])));
  }
  // Where the upper right is free, the spec's place is kept.
  const FigureInfo free = layout_figure(parse_spec(two_series("upper right", "[[0, 0], [3, 2]]"), "free.toml"));
  const AxesInfo& ax = free.axes.at(0);
  const auto legend = std::find_if(ax.text_boxes.begin(), ax.text_boxes.end(), [](const TextBox& t) { return t.what == "legend"; });
  REQUIRE(legend != ax.text_boxes.end());
  CHECK(legend->box[2] > 0.5 * (ax.pixel_box[0] + ax.pixel_box[2]));
  CHECK(legend->box[1] < 0.5 * (ax.pixel_box[1] + ax.pixel_box[3]));
}

TEST_CASE("a legend with no free spot in the box goes outside it") {
  // The zigzag covers the whole box: every spot inside meets it.
  const FigureInfo info = layout_figure(parse_spec(two_series("upper right", zigzag(0, 0)), "full.toml"));
  REQUIRE(check_legends_clear(info) == 1);
  const AxesInfo& ax = info.axes.at(0);
  const auto legend = std::find_if(ax.text_boxes.begin(), ax.text_boxes.end(), [](const TextBox& t) { return t.what == "legend"; });
  CHECK(legend->box[0] > ax.pixel_box[2]);
  CHECK(legend->box[2] <= info.width);
}

TEST_CASE("legend entries run in legend_order, down each column") {
  // Four entries drawn A, B, C, D in distinct pure colours, listed D, C, B, A in two columns:
  // D above C in the left column, B above A in the right. Each colour's mean position inside
  // the legend box tells where its sample went.
  const std::string colours[4] = {"#ff0000", "#00ff00", "#0000ff", "#ff00ff"};
  std::string s = "[canvas]\nwidth = 500\nheight = 320\n[axes]\nx_range = [0, 10]\ny_range = [0, 10]\n"
                  "legend = \"upper right\"\nlegend_columns = 2\nlegend_order = [\"D\", \"C\", \"B\", \"A\"]\n";
  for (int i = 0; i < 4; ++i) {
    const std::string y = std::to_string(i);
    s += "[[axes.series]]\npoints = [[0, ";
    s += y;
    s += "], [1, ";
    s += y;
    s += "]]\ncolor = \"";
    s += colours[i];
    s += "\"\nlabel = \"";
    s += static_cast<char>('A' + i);
    s += "\"\n";
  }
  const RenderedFigure fig = render_figure(parse_spec(s, "order.toml"));
  const AxesInfo& ax = fig.info.axes.at(0);
  const auto legend = std::find_if(ax.text_boxes.begin(), ax.text_boxes.end(), [](const TextBox& t) { return t.what == "legend"; });
  REQUIRE(legend != ax.text_boxes.end());
  double mx[4] = {}, my[4] = {}, n[4] = {};
  for (int y = static_cast<int>(legend->box[1]); y < static_cast<int>(legend->box[3]); ++y)
    for (int x = static_cast<int>(legend->box[0]); x < static_cast<int>(legend->box[2]); ++x) {
      const float r = fig.image.at(x, y, 0), g = fig.image.at(x, y, 1), b = fig.image.at(x, y, 2);
      const int k = r > 0.9f && g < 0.1f && b < 0.1f   ? 0
                    : g > 0.9f && r < 0.1f && b < 0.1f ? 1
                    : b > 0.9f && r < 0.1f && g < 0.1f ? 2
                    : r > 0.9f && b > 0.9f && g < 0.1f ? 3
                                                       : -1;
      if (k < 0) continue;
      mx[k] += x, my[k] += y, n[k] += 1;
    }
  for (int k = 0; k < 4; ++k) {
    REQUIRE(n[k] > 10);
    mx[k] /= n[k], my[k] /= n[k];
  }
  enum { A, B, C, D };
  CHECK(mx[D] == Approx(mx[C]).margin(1));  // the left column: D, then C
  CHECK(my[D] < my[C] - 10);
  CHECK(mx[B] == Approx(mx[A]).margin(1));  // the right column: B, then A
  CHECK(my[B] < my[A] - 10);
  CHECK(mx[D] < mx[B] - 20);
  CHECK(my[D] == Approx(my[B]).margin(1));
}

TEST_CASE("legend_order naming no legend entry is an error naming the key") {
  std::string s = two_series("auto", "[[0, 0], [3, 2]]");
  s.insert(s.find("[[axes.series]]"), "legend_order = [\"nope\"]\n");
  try {
    layout_figure(parse_spec(s, "o.toml"));
    FAIL("no error");
  } catch (const std::exception& e) {
    CHECK(std::string(e.what()).find("legend_order: \"nope\" is no label in the legend") != std::string::npos);
  }
}
