// The figure checks of docs/figures.md, read off the files `splinefig figures` writes: index.json
// says where each axes is and which colour each series has, the PNG shows the pixels. The
// expected data points are worked out by hand from the memo's matrices (comments give the
// arithmetic), not taken from the code.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace figtest;

namespace {

struct Loaded {
  Json index;
  Png png;
  const Json& fig;
  AxesMap axes(size_t i) const { return AxesMap(fig["axes"][i]); }
};

Rgb series_color(const Json& axes, const std::string& label) {
  for (const auto& s : axes["series"].array)
    if (s["label"].string == label) return hex(s["color"].string);
  throw std::runtime_error("no series " + label);
}

// The largest share of colour c among the pixels within `r` pixels of (x, y).
double best_share(const Png& png, double x, double y, Rgb c, int r = 1) {
  double best = 0;
  int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) best = std::max(best, share(png.at(cx + dx, cy + dy), c));
  return best;
}

bool white(Rgb p) { return p.r >= 245 && p.g >= 245 && p.b >= 245; }

}  // namespace

TEST_CASE("cbasis: the Catmull-Rom kernel passes through (0, 1) and has its minimum -2/27 at 4/3") {
  auto dir = render_builtin("cbasis", {"cbasis"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "cbasis");
  Png png = load_png(dir / "cbasis.png");
  REQUIRE(fig["axes"].size() == 1);
  AxesMap m(fig["axes"][0]);
  CHECK(m.x0 == -2);
  CHECK(m.x1 == 2);
  CHECK(m.y0 == -0.2);
  CHECK(m.y1 == 1.1);
  const Rgb red = series_color(fig["axes"][0], "$c_1$"), blue = series_color(fig["axes"][0], "$c_2$");
  CHECK(red.r == 0xe6);  // #e69f00: the right half
  CHECK((blue.r == 0x33 && blue.b == 0x88));  // #332288 (indigo): the left half, not the B-spline's blue
  CHECK(series_color(fig["axes"][0], "$c_0$").r == 0xe6);
  CHECK(series_color(fig["axes"][0], "$c_3$").b == 0x88);

  // k(0) = 1: the knot dot sits on the pixel, the curve runs on both sides at the same height
  // (k(s) = 1 - 2.5 s^2 + 1.5 |s|^3 stays within 0.3 px of 1 over 5 px), indigo left, orange right.
  const double x0 = m.px(0), y1 = m.py(1);
  Rgb at_peak = png.at(static_cast<int>(x0), static_cast<int>(y1));
  CHECK(at_peak.r + at_peak.g + at_peak.b < 3 * 150);
  CHECK(best_share(png, x0 + 6, y1, red) > 0.7);
  CHECK(best_share(png, x0 - 6, y1, blue) > 0.7);
  CHECK(white(png.at(static_cast<int>(x0 + 6), static_cast<int>(y1) - 4)));
  CHECK(white(png.at(static_cast<int>(x0 - 6), static_cast<int>(y1) - 4)));

  // Minimum at s = 4/3: c_0(u) = -a u (u - 1)^2 with a = 1/2, u = 1/3: -2/27.
  const double xm = m.px(4.0 / 3), ym = m.py(-2.0 / 27);
  CHECK(share(png.at(static_cast<int>(xm), static_cast<int>(ym)), red) > 0.5);
  CHECK(white(png.at(static_cast<int>(xm), static_cast<int>(ym) + 4)));
  CHECK(white(png.at(static_cast<int>(xm), static_cast<int>(ym) - 4)));
  // Mirror minimum on the indigo side.
  CHECK(share(png.at(static_cast<int>(m.px(-4.0 / 3)), static_cast<int>(ym)), blue) > 0.5);
}

TEST_CASE("bbasis: the B-spline kernel is 2/3 at 0, 1/6 at +-1 and its halves are coloured") {
  auto dir = render_builtin("bbasis", {"bbasis"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "bbasis");
  Png png = load_png(dir / "bbasis.png");
  AxesMap m(fig["axes"][0]);
  const Rgb red = series_color(fig["axes"][0], "$b_1$"), blue = series_color(fig["axes"][0], "$b_2$");
  // The knot dots (dark) at k(0) = 2/3 and k(+-1) = 1/6.
  for (auto [s, k] : {std::pair{0.0, 2.0 / 3}, {1.0, 1.0 / 6}, {-1.0, 1.0 / 6}}) {
    Rgb p = png.at(static_cast<int>(m.px(s)), static_cast<int>(m.py(k)));
    CHECK(p.r + p.g + p.b < 3 * 150);
  }
  // k(s) = (4 - 6 s^2 + 3 |s|^3) / 6 on |s| <= 1: k(0.5) = 2.875 / 6; (2 - |s|)^3 / 6 beyond: k(1.5) = 1/48.
  CHECK(share(png.at(static_cast<int>(m.px(0.5)), static_cast<int>(m.py(2.875 / 6))), red) > 0.5);
  CHECK(share(png.at(static_cast<int>(m.px(-0.5)), static_cast<int>(m.py(2.875 / 6))), blue) > 0.5);
  CHECK(share(png.at(static_cast<int>(m.px(1.5)), static_cast<int>(m.py(1.0 / 48))), red) > 0.5);
  CHECK(share(png.at(static_cast<int>(m.px(-1.5)), static_cast<int>(m.py(1.0 / 48))), blue) > 0.5);
  CHECK(white(png.at(static_cast<int>(m.px(0.5)), static_cast<int>(m.py(2.875 / 6)) - 5)));
}

TEST_CASE("cbasis-a: each kernel has its legend colour where its lobe is") {
  auto dir = render_builtin("cbasis-a", {"cbasis-a"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "cbasis-a");
  Png png = load_png(dir / "cbasis-a.png");
  const Json& axes = fig["axes"][0];
  AxesMap m(axes);
  // The lobe of C_a at s = 4/3 is -4a/27 (c_0(u) = -a u (u-1)^2 at u = 1/3): 10 px apart per 0.25.
  const std::pair<double, const char*> kernels[] = {
      {0.25, "$a$ = 0.25"}, {0.5, "$a$ = 0.5 (Catmull-Rom)"}, {0.75, "$a$ = 0.75"}, {1.0, "$a$ = 1"}};
  for (auto [a, label] : kernels) {
    INFO(label);
    const Rgb own = series_color(axes, label);
    // The lobe is flat at its minimum: the best pixel within 5 px of it, past the kernel's dashes.
    Rgb p = png.at(static_cast<int>(m.px(4.0 / 3)), static_cast<int>(m.py(-4 * a / 27)));
    for (int dx = -5; dx <= 5; ++dx) {
      const Rgb q = png.at(static_cast<int>(m.px(4.0 / 3)) + dx, static_cast<int>(m.py(-4 * a / 27)));
      if (share(q, own) > share(p, own)) p = q;
    }
    CHECK(share(p, own) > 0.5);
    for (const auto& s : axes["series"].array)  // and it is nearer to its own colour than any other
      if (s["label"].string != label) CHECK(distance(p, own) < distance(p, hex(s["color"].string)));
  }
}

TEST_CASE("tension: each Beta-spline passes its knot-junction point in its own colour") {
  auto dir = render_builtin("tension", {"tension"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "tension");
  Png png = load_png(dir / "tension.png");
  const Json& axes = fig["axes"][0];
  AxesMap m(axes);
  // At a junction the memo's B_{b1,b2} gives (2 b1^3 P_{i-1} + (b2 + 4 b1^2 + 4 b1) P_i + 2 P_{i+1}) / d,
  // d = b2 + 2 b1^3 + 4 b1^2 + 4 b1 + 2. At P_1 = (1, 2) between (0, 0) and (2, 0), b1 = 1:
  // x = 1, y = 2 (b2 + 8) / (b2 + 12): b2 = 0 -> 4/3, 10 -> 18/11, 50 -> 58/31.
  const std::pair<double, const char*> curves[] = {
      {4.0 / 3, "$b_1$ = 1, $b_2$ = 0 (B-spline)"}, {18.0 / 11, "$b_1$ = 1, $b_2$ = 10"}, {58.0 / 31, "$b_1$ = 1, $b_2$ = 50"}};
  for (auto [y, label] : curves) {
    INFO(label);
    // The junction is the curve's peak: the best pixel within 5 px, past its dashes, and a row
    // either way (a dash gap may fall on the peak itself, and the shoulders of the sharper
    // curves lie half a pixel lower); the curves' peaks are 9 px and more apart.
    double at1 = 0, at5 = 0;
    for (int dx = -5; dx <= 5; ++dx) {
      at1 = std::max(at1, best_share(png, m.px(1) + dx, m.py(y), series_color(axes, label), 1));
      at5 = std::max(at5, best_share(png, m.px(5) + dx, m.py(y), series_color(axes, label), 1));  // and at P_5 = (5, 2)
    }
    CHECK(at1 > 0.5);
    CHECK(at5 > 0.5);
  }
}

TEST_CASE("bias: the B-spline (b1 = 1) is visible where it starts, a sixth along the first leg") {
  auto dir = render_builtin("bias", {"bias"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& axes = figure(index, "bias")["axes"][0];
  Png png = load_png(dir / "bias.png");
  AxesMap m(axes);
  // Doubled end knots: the first junction is (5 B_0 + B_1) / 6 = (1/6, 1/3) for b1 = 1, b2 = 0
  // (the memo's B-spline matrix), on the polygon's first leg, where the b1 = 5 curve runs too
  // (it starts at 0.005 of the leg). The dashed curve begins with a dash there.
  const Rgb own = series_color(axes, "$b_1$ = 1 (B-spline)");
  CHECK(best_share(png, m.px(1.0 / 6), m.py(1.0 / 3), own, 1) > 0.8);
}

TEST_CASE("multiplicity: the B-spline reaches a triple knot, Catmull-Rom passes every knot") {
  auto dir = render_builtin("multiplicity", {"multiplicity"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "multiplicity");
  Png png = load_png(dir / "multiplicity.png");
  REQUIRE(fig["axes"].size() == 6);  // B-spline row, Catmull-Rom row; multiplicity 1, 2, 3
  // The B-spline in its blue dashes, Catmull-Rom in vermillion (docs/figures.md): where a dash
  // gap falls on a point, the next dash is within 3 px of it along the curve.
  const Rgb blue = hex("#0072b2"), vermillion = hex("#d55e00");
  AxesMap bs1(fig["axes"][0]), bs2(fig["axes"][1]), bs3(fig["axes"][2]), cr1(fig["axes"][3]);
  CHECK(series_color(fig["axes"][0], "B-spline, multiplicity 1").r == blue.r);
  CHECK(series_color(fig["axes"][3], "Catmull-Rom, multiplicity 1").r == vermillion.r);
  // Multiplicity 1: the B-spline passes (P + 4 (2,0) + P') / 6 = (2, 2/3) above the knot.
  CHECK(best_share(png, bs1.px(2), bs1.py(2.0 / 3), blue, 3) > 0.5);
  CHECK(best_share(png, bs1.px(2), bs1.py(0), blue, 0) < 0.1);
  // Multiplicity 2: at the knot's copies the curve is at ((2,0) + 4 (2,0) + (1,2)) / 6 = (11/6, 1/3)
  // and symmetrically (13/6, 1/3).
  CHECK(best_share(png, bs2.px(11.0 / 6), bs2.py(1.0 / 3), blue, 3) > 0.5);
  // Multiplicity 3: the piece between the copies is the constant (2, 0): the curve reaches the knot.
  CHECK(best_share(png, bs3.px(2), bs3.py(0), blue, 3) > 0.5);
  // Catmull-Rom interpolates: it passes (1, 2), (2, 0) and (3, 2).
  for (auto [x, y] : {std::pair{1.0, 2.0}, {2.0, 0.0}, {3.0, 2.0}}) CHECK(best_share(png, cr1.px(x), cr1.py(y), vermillion, 0) > 0.5);
}

TEST_CASE("ends: doubled Catmull-Rom reaches the end knots, open Catmull-Rom starts at the second") {
  auto dir = render_builtin("ends", {"ends"});
  Json index = parse_json(read_file(dir / "index.json"));
  const Json& fig = figure(index, "ends");
  Png png = load_png(dir / "ends.png");
  REQUIRE(fig["axes"].size() == 6);
  const Rgb vermillion = hex("#d55e00");  // Catmull-Rom's colour (docs/figures.md)
  AxesMap open(fig["axes"][0]), dbl(fig["axes"][1]);
  CHECK(best_share(png, dbl.px(0), dbl.py(0), vermillion, 0) > 0.5);
  CHECK(best_share(png, dbl.px(7), dbl.py(3), vermillion, 0) > 0.5);
  CHECK(best_share(png, open.px(1), open.py(2), vermillion, 0) > 0.5);
  CHECK(best_share(png, open.px(0), open.py(0), vermillion, 0) < 0.1);  // the first knot only steers
  // The panels do not overlap and sit inside the image.
  for (size_t i = 0; i < 6; ++i) {
    AxesMap a(fig["axes"][i]);
    CHECK(a.left >= 0);
    CHECK(a.right <= png.width);
    CHECK(a.bottom <= png.height);
    for (size_t j = i + 1; j < 6; ++j) {
      AxesMap b(fig["axes"][j]);
      bool apart = a.right <= b.left || b.right <= a.left || a.bottom <= b.top || b.bottom <= a.top;
      CHECK(apart);
    }
  }
}

TEST_CASE("index.json and the gallery list every built-in figure with its files") {
  const std::vector<std::string> expected = {"cbasis", "cbasis-a", "bbasis", "bbasis-a", "bias", "bias-kernels",
                                             "tension", "ends", "multiplicity", "arclength"};
  auto dir = render_builtin("index", expected, "--format png,exr");
  Json index = parse_json(read_file(dir / "index.json"));
  const std::string html = read_file(dir / "index.html");
  CHECK(index["figures"].size() == expected.size());
  for (const auto& name : expected) {
    INFO(name);
    const Json& f = figure(index, name);
    CHECK_FALSE(f["title"].string.empty());
    CHECK_FALSE(f["caption"].string.empty());
    REQUIRE(f["files"].size() == 2);
    CHECK(f["files"][0].string == name + ".png");
    CHECK(f["files"][1].string == name + ".exr");
    Png png = load_png(dir / (name + ".png"));
    CHECK(png.width == f["width"].number);
    CHECK(png.height == f["height"].number);
    CHECK(fs::exists(dir / (name + ".exr")));
    CHECK(f["axes"].size() >= 1);
    for (const auto& ax : f["axes"].array) {
      AxesMap m(ax);
      CHECK(0 <= m.left);
      CHECK(m.left < m.right);
      CHECK(m.right <= png.width);
      CHECK(0 <= m.top);
      CHECK(m.top < m.bottom);
      CHECK(m.bottom <= png.height);
      for (const auto& s : ax["series"].array) {
        CHECK(s["color"].string.size() == 7);
        CHECK(s["color"].string[0] == '#');
      }
    }
    CHECK(html.find("src=\"" + name + ".png\"") != std::string::npos);
  }
}

TEST_CASE("figures --scale 2 doubles the image and the pixel boxes") {
  auto one = render_builtin("scale1", {"bbasis"});
  auto two = render_builtin("scale2", {"bbasis"}, "--scale 2");
  const Json ia = parse_json(read_file(one / "index.json")), ib = parse_json(read_file(two / "index.json"));
  const Json& a = figure(ia, "bbasis");
  const Json& b = figure(ib, "bbasis");
  CHECK(b["width"].number == 2 * a["width"].number);
  CHECK(b["height"].number == 2 * a["height"].number);
  for (int k = 0; k < 4; ++k) CHECK(b["axes"][0]["pixel_box"][k].number == 2 * a["axes"][0]["pixel_box"][k].number);
  Png png = load_png(two / "bbasis.png");
  CHECK(png.width == 1600);
  // The same check at 2x: the orange half through k(0.5) = 2.875/6.
  AxesMap m(b["axes"][0]);
  CHECK(share(png.at(static_cast<int>(m.px(0.5)), static_cast<int>(m.py(2.875 / 6))), hex("#e69f00")) > 0.7);
}
