// The sweep's work limit: a lower bound on an item's crossings (renderer/src/work_estimate.hpp),
// checked against crossings counted independently, and the refusal it drives.
#include <catch2/catch.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/renderer/renderer.hpp>

#include "renderer/src/prepare.hpp"
#include "renderer/src/work_estimate.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

using namespace splinefig;
using render::Vec2;

namespace {

// Proper crossings of a closed polygon's edges with each other, by testing every pair
// (orientation signs; the random points used here are in general position).
double brute_force_crossings(const std::vector<Vec2>& p) {
  const std::size_t n = p.size();
  auto orient = [](Vec2 a, Vec2 b, Vec2 c) {
    const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return (d > 0) - (d < 0);
  };
  double count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % n];
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      const Vec2 c = p[j], d = p[(j + 1) % n];
      if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0) ++count;
    }
  }
  return count;
}

// A scene's first item through the renderer's own preparation on the whole canvas: the chains
// the sweep would get.
struct PreparedItem {
  render::detail::Geometry g;
  render::detail::Prepared p;
  int height = 0;
};
PreparedItem prepare_first(const render::Scene& scene) {
  PreparedItem it;
  it.height = scene.height();
  const render::detail::Compositor comp(render::BlendSpace::linear);
  render::detail::prepare_item(scene.items()[0], nullptr, comp, {0, 0}, {0, 0, double(scene.width()), double(it.height)}, it.g,
                               it.p, it.height);
  return it;
}

// The lower bound on an item's crossings, in bands of 16 rows as the rasterizer asks for it.
double bound_of(const PreparedItem& it) {
  return render::detail::crossings_lower_bound(it.g, it.p.shape, 0, it.height, 16, INFINITY);
}

// The lower bound for one filled polygon on a canvas of w x h.
double bound_for(const std::vector<Vec2>& contour, int w, int h) {
  render::Scene scene(w, h);
  scene.fill_polygon({contour}, render::FillRule::NonZero, {0, 0, 0, 1});
  return bound_of(prepare_first(scene));
}

std::vector<Vec2> random_points(std::mt19937_64& rng, int n, double side) {
  std::uniform_real_distribution<double> u(0, side);
  std::vector<Vec2> pts(static_cast<std::size_t>(n));
  for (Vec2& q : pts) q = {u(rng), u(rng)};
  return pts;
}

}  // namespace

TEST_CASE("the crossing bound never exceeds the crossings counted pair by pair, and finds most of them",
          "[renderer][work]") {
  // A star polygon {p/q} (p points, every q-th joined) crosses itself p (q - 1) times. The bound
  // misses crossings in bands where a chain begins or ends, and a pair crossing twice in one band
  // (its order the same at top and bottom): the two chains down each side of {97/2} cross every
  // few rows, so it finds only 0.4 of them; the others 0.7 to 0.85.
  for (auto [pts, q, share] : {std::tuple{101, 7, 0.7}, {211, 30, 0.7}, {97, 2, 0.4}}) {
    std::vector<Vec2> star;
    for (int i = 0; i < pts; ++i) {
      const double t = 2 * std::numbers::pi * ((i * q) % pts) / pts + 0.1234;
      star.push_back({256 + 240 * std::cos(t), 256 + 240 * std::sin(t)});
    }
    const double exact = double(pts) * (q - 1);
    REQUIRE(brute_force_crossings(star) == exact);  // the independent count agrees with the formula
    const double b = bound_for(star, 512, 512);
    INFO("star {" << pts << "/" << q << "}: bound " << b << " of " << exact);
    CHECK(b <= exact);
    CHECK(b >= share * exact);
  }
  std::mt19937_64 rng(20261203);
  for (int n : {50, 200, 600}) {
    const auto poly = random_points(rng, n, 300);
    const double exact = brute_force_crossings(poly), b = bound_for(poly, 300, 300);
    INFO(n << " random points: bound " << b << " of " << exact);
    CHECK(b <= exact);
    CHECK(b >= 0.7 * exact);
  }
}

TEST_CASE("an item whose crossings reach the work limit is refused before it is swept, naming the first such item",
          "[renderer][work]") {
  // Exact coverage asked for (tolerance 0): no band may be drawn from the pieces instead
  // (piece_coverage.cpp checks the work limit there).
  std::mt19937_64 rng(7);
  const auto dense = random_points(rng, 3000, 512);  // about 4e6 crossings
  render::StrokeStyle style;
  style.width = 1;
  for (int threads : {1, 2, 3}) {
    render::Scene scene(512, 512);
    scene.fill_circle({10, 10}, 5, {0, 0, 0, 1});
    scene.stroke_polyline(dense, false, style, {0, 0, 0, 1});
    scene.stroke_polyline(dense, false, style, {1, 0, 0, 1});
    scene.set_max_crossings(1e5);
    scene.set_coverage_tolerance(0);
    try {
      (void)render::rasterize(scene, threads);
      FAIL("not refused on " << threads << " threads");
    } catch (const std::length_error& e) {
      const std::string m = e.what();
      INFO(m);
      CHECK(m.find("item 2 (stroked polyline)") == 0);
      CHECK(m.find("refused past 1e+05 crossings") != std::string::npos);
      CHECK(m.find('\n') == std::string::npos);
    }
  }
  // Under the limit, and with no limit, the same item is drawn.
  render::Scene small(512, 512);
  small.stroke_polyline(std::vector<Vec2>(dense.begin(), dense.begin() + 100), false, style, {0, 0, 0, 1});
  small.set_max_crossings(1e5);
  CHECK_NOTHROW(render::rasterize(small, 1));
  CHECK_THROWS_AS(render::Scene(8, 8).set_max_crossings(NAN), std::invalid_argument);
  CHECK_THROWS_AS(render::Scene(8, 8).set_max_crossings(-1), std::invalid_argument);
}

TEST_CASE("10^5 uniformly random points on 1024^2 are refused at the default limit when coverage must be exact",
          "[renderer][work]") {
  std::mt19937_64 rng(11);
  render::Scene scene(1024, 1024);
  REQUIRE(scene.max_crossings() == kMaxSweepCrossings);
  scene.set_coverage_tolerance(0);  // a quarter of an hour of sweeping
  scene.stroke_polyline(random_points(rng, 100000, 1024), false, render::StrokeStyle{}, {0, 0, 0, 1});
  CHECK_THROWS_WITH(render::rasterize(scene, 1), Catch::Contains("item 1 (stroked polyline)") &&
                                                     Catch::Contains("refused past 2.68e+08 crossings"));
}

namespace {

// A stroke up and down between rows y0 and y1, `n` turns across 490 columns: its outline's
// chains run from turn to turn, and the neighbouring joins overlap and cross each other.
std::vector<Vec2> zigzag(int n, double y0, double y1) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) p.push_back({10 + 490.0 * i / n, i % 2 ? y0 : y1});
  return p;
}

// The sweep of one item alone, counted by the sweep itself (renderer/src/sweep.hpp: work()).
std::uint64_t sweep_work(const PreparedItem& it) {
  struct Null {
    void edge(double, double, double, double, double) {}
  } sink;
  render::detail::StripSweep sweep;
  sweep.reset(it.g, it.p.shape);
  for (int y = 0; y < it.height; y += 16) sweep.strip(y, std::min(y + 16, it.height), sink);
  return sweep.work();
}

}  // namespace

TEST_CASE("the sweep counts at least one unit of work per crossing", "[renderer][work]") {
  std::mt19937_64 rng(5);
  for (int n : {50, 200, 600}) {
    const auto poly = random_points(rng, n, 300);
    render::Scene scene(300, 300);
    scene.fill_polygon({poly}, render::FillRule::NonZero, {0, 0, 0, 1});
    const double exact = brute_force_crossings(poly);
    INFO(n << " random points: " << exact << " crossings");
    CHECK(static_cast<double>(sweep_work(prepare_first(scene))) >= exact);
  }
}

TEST_CASE("the bound sees the crossings of chains that begin or end inside a band", "[renderer][work]") {
  // A tall zigzag's chains run from turn to turn, through every band between, and the joins at
  // its turns overlap their neighbours' (3000 turns, 0.16 px apart, width 1.5). The crossings
  // there are near the chains' ends, in bands the chains do not run through: the whole-band
  // count finds 2990 of them, the stretches from the chains' last beginning and first end
  // 38918. The exact count is between them and the sweep's work (at least one unit each).
  render::Scene one(512, 512);
  render::StrokeStyle style;
  style.width = 1.5;
  one.stroke_polyline(zigzag(3000, 40, 470), false, style, {0, 0, 0, 1});
  const PreparedItem it = prepare_first(one);
  const double bound = bound_of(it), work = static_cast<double>(sweep_work(it));
  INFO("bound " << bound << ", sweep work " << work);
  CHECK(bound >= 3e4);
  CHECK(bound <= work);
}

TEST_CASE("an item whose crossings hide from the bound is stopped at the work limit by the sweep, naming the first such item",
          "[renderer][work]") {
  // A zigzag within one band (rows 196 to 204 of the band 192-208): every chain begins and ends
  // inside it, where the bound sees none of their crossings.
  const auto zz = zigzag(3000, 196, 204);
  render::StrokeStyle style;
  style.width = 1.5;
  {
    render::Scene one(512, 512);
    one.stroke_polyline(zz, false, style, {0, 0, 0, 1});
    const PreparedItem it = prepare_first(one);
    const double bound = bound_of(it), work = static_cast<double>(sweep_work(it));
    INFO("bound " << bound << ", sweep work " << work);
    REQUIRE(bound < 3e4);
    REQUIRE(work > 1e5);
  }
  for (const auto& filter : {splinefig::Kernel::box(), splinefig::Kernel::tent()}) {
    for (int threads : {1, 2, 3}) {
      render::Scene scene(512, 512, {1, 1, 1, 1}, filter);
      scene.fill_circle({10, 10}, 5, {0, 0, 0, 1});
      scene.stroke_polyline(zz, false, style, {0, 0, 0, 1});
      scene.stroke_polyline(zz, false, style, {1, 0, 0, 1});
      scene.set_max_crossings(3e4);
      try {
        (void)render::rasterize(scene, threads);
        FAIL("not stopped on " << threads << " threads");
      } catch (const std::length_error& e) {
        const std::string m = e.what();
        INFO(m);
        CHECK(m.find("item 2 (stroked polyline): its exact union was stopped at the work limit of the sweep, 3e+04 events") ==
              0);
        CHECK(m.find('\n') == std::string::npos);
      }
    }
  }
  // With the limit above its work, the same zigzag is drawn, the same bytes on any thread count.
  render::Scene scene(512, 512);
  scene.stroke_polyline(zz, false, style, {0, 0, 0, 1});
  scene.set_max_crossings(1e6);
  const auto one = render::rasterize(scene, 1);
  CHECK(render::rasterize(scene, 3).pixels == one.pixels);
}
