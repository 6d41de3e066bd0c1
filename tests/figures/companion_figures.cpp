// docs/figures.md's checks for the companion figures (seeds 002 and 003, local-betas), read off the
// PNG and index.json that `splinefig figures` writes. Expected points are worked out by hand
// (comments give the arithmetic) from the seeds, not taken from the code.
#include <catch2/catch.hpp>

#include "support.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/palette.hpp>

using namespace figtest;

namespace {

// The largest share of colour c among the pixels within r of (x, y).
double near_share(const Png& png, double x, double y, Rgb c, int r = 1) {
  double best = 0;
  const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) best = std::max(best, share(png.at(cx + dx, cy + dy), c));
  return best;
}

struct Rendered {
  Json index;
  Png png;
  AxesMap map(size_t axes = 0) const { return AxesMap(figure(index, name)["axes"][axes]); }
  std::string name;
};

// One `splinefig figures` run for all the checked figures (a process start is the slow part).
Rendered render(const std::string& name) {
  static const fs::path dir = render_builtin(
      "companion", {"s003-fig01", "s003-fig02", "s003-fig14", "s003-fig16", "s003-fig17", "s002-fig474", "local-betas"});
  return {parse_json(read_file(dir / "index.json")), load_png(dir / (name + ".png")), name};
}

bool on(const Rendered& f, double x, double y, const char* color, double at_least = 0.5) {
  const AxesMap m = f.map();
  return near_share(f.png, m.px(x), m.py(y), hex(color)) > at_least;
}

}  // namespace

TEST_CASE("companion figures show their documented checks") {
  SECTION("s003-fig01: the degree-10 Lagrange polynomial passes 2.76 and 3.17 at t = 0.5 and 9.5") {
    const Rendered f = render("s003-fig01");
    // P(1/2) = 362017/131072, P(19/2) = 415701/131072 (exact rational arithmetic).
    CHECK(on(f, 0.5, 362017.0 / 131072, "#d62728"));
    CHECK(on(f, 9.5, 415701.0 / 131072, "#d62728"));
    CHECK_FALSE(on(f, 0.5, 0.5, "#d62728", 0.2));
  }
  SECTION("s003-fig02: the relaxed spline through the step passes 1/2 halfway (odd symmetry)") {
    const Rendered f = render("s003-fig02");
    // y - 1/2 is odd about t = 4.5 in the data, so the natural spline has P(4.5) = (4.5, 0.5).
    CHECK(on(f, 4.5, 0.5, "#1f77b4"));
  }
  SECTION("s003-fig14: the seed's Bezier points and B-spline control points are drawn") {
    const Rendered f = render("s003-fig14");
    // Bezier #1..#4 of the seed's solution (their inner control points).
    for (auto [x, y] : {std::pair{0.0, 0.0}, {-1.0, 1.0}, {-1.0, 3.0}, {0.0, 4.0}, {2.0, 4.0}, {3.0, 3.0}, {5.0, 3.0}, {6.0, 4.0}})
      CHECK(on(f, x, y, "#2ca02c"));
    // B_1 = (-2, 2), B_2 = (1, 5), B_3 = (4, 2): grey polygon vertices.
    for (auto [x, y] : {std::pair{-2.0, 2.0}, {1.0, 5.0}, {4.0, 2.0}}) CHECK(on(f, x, y, "#888888"));
  }
  SECTION("s003-fig16: basis function f_k is 1 at t = k") {
    const Rendered f = render("s003-fig16");
    // f_k(k) = 1 and f_k'(k) = 0 for the inner ones (f_2 is symmetric about 2): the curve is at
    // height 1 a few pixels beside its knot's dot. (f_4 rises steeply into its end dot, which
    // covers the point where it reaches 1: it is not checked here.)
    const AxesMap m = f.map();
    const double dx = 6 / (m.px(1) - m.px(0));  // 6 px in t
    // f_2 is the palette's third colour, dotted: the best of five spots 4..8 px beside the knot
    // (one dot and gap period) finds a dot.
    const std::string own = splinefig::figures::to_hex(splinefig::figures::palette_color("viridis", 2, 5));
    bool right = false, left = false;
    for (int k = 4; k <= 8; ++k) {
      right = right || on(f, 2 + k * dx / 6, 1, own.c_str(), 0.3);
      left = left || on(f, 2 - k * dx / 6, 1, own.c_str(), 0.3);
    }
    CHECK(right);
    CHECK(left);
  }
  SECTION("s003-fig17: the in-between heel is (13 S_0 + 22 S_1 - 3 S_2)/32 (DD-4(d))") {
    const Rendered f = render("s003-fig17");
    // Heels (0,0), (2.9,0.3), (4,0): (22*2.9 - 12, 22*0.3)/32 = (1.61875, 0.20625); toes (0.8,0),
    // (3.7,0.1), (4.8,0): (10.4 + 81.4 - 14.4, 2.2)/32 = (2.41875, 0.06875). The frame's foot runs
    // between them, through their midpoint.
    CHECK(on(f, 1.61875, 0.20625, "#d62728"));
    CHECK(on(f, (1.61875 + 2.41875) / 2, (0.20625 + 0.06875) / 2, "#d62728"));
    CHECK(on(f, 2.41875, 0.06875, "#d62728"));
  }
  SECTION("s002-fig474: step 1 has the seed's points and the limit points lie on the segment") {
    const Rendered f = render("s002-fig474");
    // Step 1 of (0,0),(1,2),(3,2),(4,0): vertex points (P0 + 6P1 + P2)/8 = (1.125, 1.75) and
    // (P1 + 6P2 + P3)/8 = (2.875, 1.75).
    CHECK(on(f, 1.125, 1.75, "#8c564b"));
    CHECK(on(f, 2.875, 1.75, "#8c564b"));
    // Limits: P(0) = (P0 + 4P1 + P2)/6 = (7/6, 5/3) and the segment's midpoint
    // (P0 + 23P1 + 23P2 + P3)/48 = (96/48, 92/48).
    CHECK(on(f, 7.0 / 6, 5.0 / 3, "#d62728"));
    CHECK(on(f, 2, 92.0 / 48, "#d62728"));
    // Every step's polygon has 3 + 2^k points: one series each, as index.json lists them.
    const Json& axes = figure(f.index, "s002-fig474")["axes"][0];
    CHECK(axes["series"].size() >= 5);
  }
  SECTION("local-betas: the joints take the uniform Beta-spline values of their vertex") {
    const Rendered f = render("local-betas");
    auto on_panel = [&](size_t axes, double x, double y, const char* color) {
      const AxesMap m = f.map(axes);
      return near_share(f.png, m.px(x), m.py(y), hex(color)) > 0.5;
    };
    // Bias 2 at vertex (3,2) (top panel): the joint is (2b1^3 x2 + 4(b1^2 + b1) x3 + 2 x4)/d with
    // the memo's B_{2,0} (2b1^3 = 16, 4(b1^2 + b1) = 24, d = 42): (112/42, 48/42).
    CHECK(on_panel(0, 112.0 / 42, 48.0 / 42, "#303030"));
    // Tension 20 at the same vertex (bottom): B_{1,20} gives (2 x2 + 28 x3 + 2 x4)/32 = (3, 56/32).
    CHECK(on_panel(1, 3, 56.0 / 32, "#303030"));
    // Far from vertex 4 every curve is the B-spline: the joint at (5,2) is (5, 4/3), dark
    // where the dashed B-spline, drawn last, lies over the curves.
    const AxesMap m = f.map(1);
    const Rgb p = f.png.at(static_cast<int>(m.px(5)), static_cast<int>(m.py(4.0 / 3)));
    CHECK(p.r + p.g + p.b < 3 * 200);
  }
}

