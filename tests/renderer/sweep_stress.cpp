// The scan converter where paths cross themselves densely: many mutual crossings in one pixel
// row, several edges through one point, coincident edges, both fill rules. Fills are checked
// against a brute-force oracle written here (below), strokes against the union oracle; and a
// random polyline with 10^4 uniform points must render in far less time than the blow-up of a
// sweep whose cost grows with (chains x events) would take.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <random>
#include <vector>

namespace sr = splinefig::render;

namespace {

// Instrumented or unoptimized builds run several times slower: their time limit is 10x.
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
constexpr double kSlowBuild = 10;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
constexpr double kSlowBuild = 10;
#else
constexpr double kSlowBuild = 1;
#endif
#else
constexpr double kSlowBuild = 1;
#endif

// Exact coverage of a polygon fill by slabs: every vertex height, every pixel row's edge and
// every height where two edges cross cut the plane into slabs in which no two edges cross; in
// each slab the edges are ordered at mid-height, the fill rule is applied to the winding of
// every gap, and each filled gap (a trapezoid) is clipped to the pixels. O(edges^2) slabs: for
// small test paths only.
std::vector<double> fill_oracle(const std::vector<std::vector<oracle::P2>>& contours, sr::FillRule rule, int W, int H) {
  struct Edge {
    oracle::P2 a, b;  // a.y < b.y
    int dir;
    double x(double y) const { return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y); }
  };
  std::vector<Edge> edges;
  std::vector<double> ys;
  for (int r = 0; r <= H; ++r) ys.push_back(r);
  for (const auto& c : contours)
    for (std::size_t i = 0; i < c.size(); ++i) {
      oracle::P2 p = c[i], q = c[(i + 1) % c.size()];
      ys.push_back(p.y);
      if (p.y == q.y) continue;
      edges.push_back(p.y < q.y ? Edge{p, q, 1} : Edge{q, p, -1});
    }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &e = edges[i], &f = edges[j];
      const oracle::P2 r{e.b.x - e.a.x, e.b.y - e.a.y}, s{f.b.x - f.a.x, f.b.y - f.a.y};
      const double den = r.x * s.y - r.y * s.x;
      if (den == 0) continue;
      const double t = ((f.a.x - e.a.x) * s.y - (f.a.y - e.a.y) * s.x) / den;
      const double u = ((f.a.x - e.a.x) * r.y - (f.a.y - e.a.y) * r.x) / den;
      if (t >= 0 && t <= 1 && u >= 0 && u <= 1) ys.push_back(e.a.y + t * r.y);
    }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<double> cov(static_cast<std::size_t>(W) * H, 0.0);
  struct At {
    double xm, xa, xb;
    int dir;
  };
  std::vector<At> at;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const double ya = ys[k], yb = ys[k + 1];
    if (ya < 0 || yb > H) continue;
    const double ym = 0.5 * (ya + yb);
    const int row = static_cast<int>(std::floor(ym));
    at.clear();
    for (const Edge& e : edges)
      if (e.a.y <= ya && e.b.y >= yb) at.push_back({e.x(ym), e.x(ya), e.x(yb), e.dir});
    std::sort(at.begin(), at.end(), [](const At& p, const At& q) { return p.xm < q.xm; });
    int w = 0;
    for (std::size_t i = 0; i + 1 < at.size(); ++i) {
      w += at[i].dir;
      const bool in = rule == sr::FillRule::EvenOdd ? (w & 1) != 0 : w != 0;
      if (!in) continue;
      const oracle::Poly trap{{at[i].xa, ya}, {at[i + 1].xa, ya}, {at[i + 1].xb, yb}, {at[i].xb, yb}};
      const double x0 = std::min(at[i].xa, at[i].xb), x1 = std::max(at[i + 1].xa, at[i + 1].xb);
      for (int px = std::max(0, static_cast<int>(std::floor(x0))); px < std::min(W, static_cast<int>(std::ceil(x1))); ++px)
        cov[static_cast<std::size_t>(row) * W + px] += oracle::polygon_area(oracle::clip_to_box(trap, px, row, px + 1, row + 1));
    }
  }
  return cov;
}

std::vector<sr::Vec2> to_vec(const std::vector<oracle::P2>& p) {
  std::vector<sr::Vec2> v;
  for (auto q : p) v.push_back({q.x, q.y});
  return v;
}

// Max error of the rendered fill against the oracle, for both fill rules.
void check_fill(const std::vector<std::vector<oracle::P2>>& contours, int W, int H, double& worst) {
  std::vector<std::vector<sr::Vec2>> cs;
  for (const auto& c : contours) cs.push_back(to_vec(c));
  for (sr::FillRule rule : {sr::FillRule::NonZero, sr::FillRule::EvenOdd}) {
    auto got = testutil::rendered_coverage(W, H, [&](sr::Scene& s) { s.fill_polygon(cs, rule, {1, 1, 1, 1}); });
    auto want = fill_oracle(contours, rule, W, H);
    auto e = testutil::compare(got, want);
    INFO((rule == sr::FillRule::EvenOdd ? "even-odd" : "nonzero") << ": max error " << e.max << " at pixel " << e.worst);
    REQUIRE(e.max <= 1e-5);
    worst = std::max(worst, e.max);
  }
}

}  // namespace

TEST_CASE("the fill oracle agrees with known areas: a pentagram's centre is filled by nonzero only") {
  // Independent check of the oracle itself: the pentagram's area is five points plus the centre.
  std::vector<oracle::P2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = oracle::kPi / 2 + 4 * oracle::kPi * i / 5;
    star.push_back({16 + 12 * std::cos(a), 16 - 12 * std::sin(a)});
  }
  auto sum = [](const std::vector<double>& c) {
    double t = 0;
    for (double v : c) t += v;
    return t;
  };
  // R = 12: star area 5 r R sin(36 deg) ... in closed form via the inner radius r.
  const double R = 12, r = R * std::cos(2 * oracle::kPi / 5) / std::cos(oracle::kPi / 5);
  const double star_area = 5 * R * r * std::sin(oracle::kPi / 5);
  const double pentagon = 2.5 * r * r * std::sin(2 * oracle::kPi / 5);
  CHECK(sum(fill_oracle({star}, sr::FillRule::NonZero, 32, 32)) == Approx(star_area).epsilon(1e-12));
  CHECK(sum(fill_oracle({star}, sr::FillRule::EvenOdd, 32, 32)) == Approx(star_area - pentagon).epsilon(1e-12));
}

TEST_CASE("fills with many mutual crossings in one pixel row are exact, nonzero and even-odd") {
  std::mt19937_64 rng(1202);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    std::vector<oracle::P2> c;
    const int n = 20 + 8 * k;
    for (int i = 0; i < n; ++i) {
      // mostly flat zig-zags: every edge crosses most others within a few rows
      const double y = k % 2 ? 2 + 28 * u(rng) : 12 + 6 * u(rng);
      c.push_back({1 + 30 * u(rng), y});
    }
    INFO("case " << k);
    check_fill({c}, 32, 32, worst);
  }
  WARN("worst max error " << worst);
}

TEST_CASE("fills where many edges cross at one point and edges coincide are exact") {
  double worst = 0;
  // Lines through one exactly representable point: P_i -> 2c - P_i all pass through c = (16, 16).
  for (int n : {3, 5, 8, 13}) {
    std::vector<oracle::P2> c;
    for (int i = 0; i < n; ++i) {
      const double a = oracle::kPi * (i + 0.37) / n;
      const double dx = std::round(1024 * 13 * std::cos(a)) / 1024, dy = std::round(1024 * 13 * std::sin(a)) / 1024;
      c.push_back({16 + dx, 16 + dy});
      c.push_back({16 - dx, 16 - dy});
    }
    INFO("lines through one point: " << n);
    check_fill({c}, 32, 32, worst);
  }
  // Vertices on a coarse lattice: collinear and coincident edges, crossings at shared points,
  // vertices exactly on pixel rows; several contours, some sharing whole edges.
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> g(0, 8);
  for (int k = 0; k < 12; ++k) {
    std::vector<std::vector<oracle::P2>> cs;
    const double step = k % 3 == 0 ? 4 : (k % 3 == 1 ? 3.5 : 3.25);
    for (int m = 0; m < 1 + k % 4; ++m) {
      std::vector<oracle::P2> c;
      for (int i = 0; i < 6 + 2 * (k % 3); ++i) c.push_back({1 + step * g(rng), 1 + step * g(rng)});
      cs.push_back(c);
    }
    if (k % 4 == 3) cs.push_back(cs[0]);  // a contour drawn twice: its edges coincide exactly
    INFO("lattice case " << k);
    check_fill(cs, 32, 32, worst);
  }
  WARN("worst max error " << worst);
}

TEST_CASE("a contour drawn twice is filled once by nonzero and not at all by even-odd") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<sr::Vec2> c;
  for (int i = 0; i < 40; ++i) c.push_back({2 + 28 * u(rng), 2 + 28 * u(rng)});
  auto once = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({c}, sr::FillRule::NonZero, {1, 1, 1, 1}); });
  auto twice = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({c, c}, sr::FillRule::NonZero, {1, 1, 1, 1}); });
  auto eo = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.fill_polygon({c, c}, sr::FillRule::EvenOdd, {1, 1, 1, 1}); });
  CHECK(testutil::compare(once, twice).max <= 1e-6);
  double most = 0;
  for (double v : eo) most = std::max(most, v);
  CHECK(most <= 1e-6);
}

TEST_CASE("dense random strokes, many crossings per row, are their exact union") {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  const sr::Join joins[] = {sr::Join::Miter, sr::Join::Round, sr::Join::Bevel};
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    std::vector<oracle::P2> pts;
    for (int i = 0; i < 40; ++i) pts.push_back({2 + 28 * u(rng), k % 2 ? 2 + 28 * u(rng) : 10 + 12 * u(rng)});
    const double width = 0.4 + 1.2 * u(rng);
    sr::StrokeStyle st;
    st.width = width;
    st.join = joins[k % 3];
    std::vector<sr::Vec2> v = to_vec(pts);
    auto got = testutil::rendered_coverage(32, 32, [&](sr::Scene& s) { s.stroke_polyline(v, false, st, {1, 1, 1, 1}); });
    auto want = oracle::union_coverage(
        oracle::stroke_pieces(pts, false, width, static_cast<oracle::Join>(k % 3), 4, oracle::Cap::Butt), 32, 32);
    auto e = testutil::compare(got, want);
    INFO("case " << k << ": max error " << e.max << " at pixel " << e.worst);
    REQUIRE(e.max <= 1e-4);
    worst = std::max(worst, e.max);
  }
  WARN("worst max error " << worst);
}

TEST_CASE("a random polyline of 10^4 uniform points renders in far less than its old quadratic time") {
  // ~2.5 10^7 crossings on a 1024 x 1024 canvas. A sweep testing every pair of chains in a row
  // at every event took minutes here; the incremental sweep takes seconds. The limit is CPU
  // time, generous (10x in sanitizer and unoptimized builds), so only a return of the blow-up
  // fails it.
  std::vector<sr::Vec2> pts;
  std::mt19937_64 rng(10000);
  std::uniform_real_distribution<double> u(0, 1024);
  for (int i = 0; i < 10000; ++i) pts.push_back({u(rng), u(rng)});
  sr::Scene s(1024, 1024, {0, 0, 0, 0});
  sr::StrokeStyle st;
  st.width = 1;
  s.stroke_polyline(pts, false, st, {1, 1, 1, 1});
  const std::clock_t t0 = std::clock();
  auto img = sr::rasterize(s, 1);
  const double cpu = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  WARN("10^4 uniform points: " << cpu << " s CPU");
  CHECK(cpu < 20 * kSlowBuild);
  // most of the canvas is covered: the union, not a sum of overlaps, stays <= 1 everywhere
  float most = 0;
  for (int y = 0; y < 1024; y += 7)
    for (int x = 0; x < 1024; x += 7) most = std::max(most, img.pixel(x, y)[3]);
  CHECK(most <= 1.0f + 1e-6f);
}
