// Every built-in figure can be read without colour, and each of its series is encoded twice:
// any two labelled series of one panel differ in how they are drawn (dash pattern, line or none,
// marker shape), always, and also in CIE lightness L*, by at least kMinDeltaL, both as printed
// (greyscale keeps L*) and as a deuteranope sees them (Machado, Oliveira and Fernandes 2009,
// severity 1, applied in linear light), in every panel of up to kMaxShadedSeries series.
// Lightness alone is not enough: at print size thin antialiased lines of two dark colours both
// read as black (a dark red at L* 35 beside black), so two solid lines are never told apart by
// shade. The series and their styles are the layout's own (figures::layout_figure, as index.json
// reports them); L* is worked out here from the "#rrggbb" with the sRGB and CIE formulas written out.
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/palette.hpp>
#include <splinefig/figures/spec.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace splinefig;

namespace {

// The lightness step between two series that also differ in dash or marker: half of the step
// a reader needs to tell lines apart by shade alone (about a sixth of the range from black to
// white), rounded up. The deuteranope's L* stays within about 5 of the printed one for most
// colours; the second condition guards against a pair that only hue separates.
constexpr double kMinDeltaL = 8;
// Lines keep a 3:1 contrast on white up to L* 62, and the concepts' colours (docs/figures.md)
// are fixed: more than six series in a panel (the filter set's seven and eight kernels) cannot
// all be kMinDeltaL apart, and are told apart by their dashes and their hues.
constexpr std::size_t kMaxShadedSeries = 6;

std::array<double, 3> linear_rgb(const std::string& hex) {
  REQUIRE(hex.size() == 7);
  std::array<double, 3> c{};
  for (int i = 0; i < 3; ++i) {
    const double v = std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;  // IEC 61966-2-1 decoding
    c[i] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  return c;
}

// CIE 1976 L* of a linear-light colour (D65 white: Y = 1).
double lightness(const std::array<double, 3>& c) {
  const double Y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
  const double d = 6.0 / 29.0;
  const double f = Y > d * d * d ? std::cbrt(Y) : Y / (3 * d * d) + 4.0 / 29.0;
  return 116 * f - 16;
}

// Deuteranopia, Machado et al. 2009 (severity 1.0), on linear RGB, clamped to [0, 1].
std::array<double, 3> deuteranope(const std::array<double, 3>& c) {
  static constexpr double m[3][3] = {{0.367322, 0.860646, -0.227968},
                                     {0.280085, 0.672501, 0.047413},
                                     {-0.011820, 0.042940, 0.968881}};
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) out[i] = std::clamp(m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2], 0.0, 1.0);
  return out;
}

// Two dash patterns look different: one solid and one not, a different number of dashes per
// period, or some length differing by a factor of 1.4 or more (lengths under 1 px count as 1).
bool dashes_differ(std::vector<double> a, std::vector<double> b) {
  if (a.empty() != b.empty()) return true;
  if (a.size() % 2) a.insert(a.end(), a.begin(), a.end());
  if (b.size() % 2) b.insert(b.end(), b.begin(), b.end());
  if (a.size() != b.size()) return true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x = std::max(a[i], 1.0), y = std::max(b[i], 1.0);
    if (std::max(x, y) / std::min(x, y) >= 1.4) return true;
  }
  return false;
}

bool drawn_differently(const figures::SeriesInfo& a, const figures::SeriesInfo& b) {
  if (a.line != b.line || a.marker != b.marker) return true;
  return a.line && dashes_differ(a.dash, b.dash);
}

// The pairs of one panel not encoded twice: drawn alike, or (two lines, or two series of
// markers, in a panel of up to kMaxShadedSeries) too close in L*, with their L* (print,
// deuteranope).
std::vector<std::string> indistinct_pairs(const figures::FigureInfo& info) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < info.axes.size(); ++k) {
    const auto& s = info.axes[k].series;
    const auto shown = static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](const auto& e) { return e.kind != "fill"; }));
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j) {
        const auto &a = s[i], &b = s[j];
        if (a.kind == "fill" || b.kind == "fill") continue;  // areas: told apart by where they are
        if (a.piece && b.piece) continue;  // pieces of one kernel: drawn alike on purpose, told apart by where they are
        const auto ca = linear_rgb(a.color), cb = linear_rgb(b.color);
        const double dl = std::abs(lightness(ca) - lightness(cb));
        const double dd = std::abs(lightness(deuteranope(ca)) - lightness(deuteranope(cb)));
        const bool drawn = drawn_differently(a, b);
        // A line and a series of markers without one are told apart by their form; two lines, or
        // two series of markers, need the lightness step too.
        const bool shaded = shown > kMaxShadedSeries || a.line != b.line || (dl >= kMinDeltaL && dd >= kMinDeltaL);
        if (drawn && shaded) continue;
        std::ostringstream m;
        m << info.name << " axes " << k << ": \"" << a.label << "\" " << a.color << " and \"" << b.label << "\" "
          << b.color << (drawn ? " differ only in how they are drawn" : " are drawn alike") << ", L* " << dl
          << " apart (deuteranope " << dd << ")";
        out.push_back(m.str());
      }
  }
  return out;
}

figures::FigureInfo layout_of(const std::string& toml) {
  return figures::layout_figure(figures::parse_spec(toml, "test", "."));
}

}  // namespace

TEST_CASE("L* by the CIE formula: black 0, white 100, mid grey, the house red and blue") {
  CHECK(lightness(linear_rgb("#000000")) == Approx(0).margin(1e-9));
  CHECK(lightness(linear_rgb("#ffffff")) == Approx(100));
  CHECK(lightness(linear_rgb("#777777")) == Approx(50.0).margin(0.1));  // sRGB 119: L* 50.03
  // The pair that told six meanings apart by hue alone: L* 46.8 and 48.0.
  CHECK(lightness(linear_rgb("#d62728")) == Approx(46.8).margin(0.05));
  CHECK(lightness(linear_rgb("#1f77b4")) == Approx(48.0).margin(0.05));
  // A deuteranope sees grey as grey.
  const auto g = deuteranope(linear_rgb("#777777"));
  CHECK(g[0] == Approx(g[1]).margin(1e-6));
}

TEST_CASE("every built-in figure's series can be told apart in greyscale and by a deuteranope") {
  int figures_seen = 0, pairs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SPLINEFIG_SOURCE_DIR "/figures/specs")) {
    if (entry.path().extension() != ".toml") continue;
    const figures::FigureInfo info = figures::layout_figure(figures::load_spec(entry.path().string()));
    ++figures_seen;
    for (const auto& ax : info.axes) pairs += static_cast<int>(ax.series.size() * (ax.series.size() - (ax.series.empty() ? 0 : 1)) / 2);
    for (const std::string& problem : indistinct_pairs(info)) FAIL_CHECK(problem);
  }
  CHECK(figures_seen >= 33);
  CHECK(pairs > 100);
}

TEST_CASE("the greyscale check catches two series told apart by hue alone") {
  const std::string head = "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n";
  const std::string red = "[[axes.series]]\npoints = [[0, 0], [1, 1]]\ncolor = \"#d62728\"\nlabel = \"red\"\n";
  const std::string blue = "[[axes.series]]\npoints = [[0, 1], [1, 0]]\ncolor = \"#1f77b4\"\nlabel = \"blue\"\n";
  CHECK(indistinct_pairs(layout_of(head + red + blue)).size() == 1);
  // A dash or markers on one of them is one cue: the two are 1.2 apart in L*.
  CHECK(indistinct_pairs(layout_of(head + red + blue + "dash = [8, 4]\n")).size() == 1);
  CHECK(indistinct_pairs(layout_of(head + red + blue + "style = \"line+markers\"\n")).size() == 1);
  // A darker blue (#08306b, L* 21) alone is one cue too; with a dash or markers, two.
  std::string dark = blue;
  dark.replace(dark.find("#1f77b4"), 7, "#08306b");
  CHECK(indistinct_pairs(layout_of(head + red + dark)).size() == 1);
  CHECK(indistinct_pairs(layout_of(head + red + dark + "dash = [8, 4]\n")).empty());
  CHECK(indistinct_pairs(layout_of(head + red + dark + "style = \"line+markers\"\n")).empty());
  // Dashes of nearly the same pattern are no cue.
  CHECK(indistinct_pairs(layout_of(head + red + "dash = [7, 4]\n" + dark + "dash = [8, 4]\n")).size() == 1);
  // Red against green: 10 apart in L* (46.8 and 56.9), 4 apart as a deuteranope sees them.
  std::string green = blue;
  green.replace(green.find("#1f77b4"), 7, "#4c9a2a");
  CHECK(indistinct_pairs(layout_of(head + red + "dash = [8, 4]\n" + green)).size() == 1);
}

TEST_CASE("two solid dark lines are not told apart by their lightness") {
  // The filter figures' Catmull-Rom (#a50f15, L* 35) and β-spline (black): 35 apart in L*, yet
  // both read as black lines at print size.
  const std::string head = "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n";
  const std::string cr = "[[axes.series]]\npoints = [[0, 0], [1, 1]]\ncolor = \"#a50f15\"\nlabel = \"Catmull-Rom\"\n";
  const std::string beta = "[[axes.series]]\npoints = [[0, 1], [1, 0]]\ncolor = \"#000000\"\nlabel = \"beta\"\n";
  CHECK(lightness(linear_rgb("#a50f15")) == Approx(34.8).margin(0.05));
  CHECK(indistinct_pairs(layout_of(head + cr + beta)).size() == 1);
  CHECK(indistinct_pairs(layout_of(head + cr + beta + "dash = [8, 3, 2, 3, 2, 3]\n")).empty());
  // Seven series: still never two drawn alike, however far apart in L*.
  std::string seven = head;
  for (int on : {2, 3, 5, 8, 12})
    seven += "[[axes.series]]\npoints = [[0, 0], [1, 1]]\ncolor = \"#777777\"\ndash = [" + std::to_string(on) +
             ", 1]\nlabel = \"s" + std::to_string(on) + "\"\n";
  CHECK(indistinct_pairs(layout_of(seven + cr + beta)).size() == 1);
}

TEST_CASE("series coloured from the palette take the style cycle's dashes") {
  // Six curves from viridis: each has its own dash from the cycle and the next colour, at least
  // kMinDeltaL lighter; without the cycle (dash_cycle = false) every pair is drawn alike.
  auto family = [](int n) {
    std::string toml = "[axes]\nx_range = [0, 1]\ny_range = [0, 7]\n";
    for (int i = 0; i < n; ++i)
      toml += "[[axes.series]]\npoints = [[0, " + std::to_string(i) + "], [1, " + std::to_string(i + 1) +
              "]]\nlabel = \"s" + std::to_string(i) + "\"\n";
    return toml;
  };
  const figures::FigureInfo cycled = layout_of(family(6));
  CHECK(indistinct_pairs(cycled).empty());
  const auto& s = cycled.axes.at(0).series;
  REQUIRE(s.size() == 6);
  CHECK(s[0].dash.empty());
  CHECK(s[1].dash == std::vector<double>{8, 4});
  CHECK(s[2].dash == std::vector<double>{2, 3});
  for (std::size_t i = 0; i + 1 < s.size(); ++i)
    CHECK(lightness(linear_rgb(s[i + 1].color)) - lightness(linear_rgb(s[i].color)) >= kMinDeltaL);
  // The cycle has six patterns: a seventh curve is solid again, drawn like the first.
  const figures::FigureInfo seven = layout_of(family(7));
  CHECK(seven.axes.at(0).series.at(6).dash.empty());
  CHECK(indistinct_pairs(seven).size() == 1);
  std::string plain = family(6);
  plain.insert(plain.find("y_range"), "dash_cycle = false\n");
  CHECK(indistinct_pairs(layout_of(plain)).size() == 15);
  // An explicit dash or colour is kept as given.
  const figures::FigureInfo own = layout_of(
      "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n[[axes.series]]\npoints = [[0, 0], [1, 1]]\nlabel = \"a\"\n"
      "[[axes.series]]\npoints = [[0, 1], [1, 0]]\ndash = [3, 3]\nlabel = \"b\"\n"
      "[[axes.series]]\npoints = [[0, 1], [1, 1]]\ncolor = \"#000000\"\nlabel = \"c\"\n");
  CHECK(own.axes.at(0).series.at(1).dash == std::vector<double>{3, 3});
  CHECK(own.axes.at(0).series.at(2).dash.empty());
}
