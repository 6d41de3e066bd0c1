// The outline's size is bounded before it is built: stroke_vertex_bound (renderer/src/stroke.hpp)
// against the vertices stroke_path really appends, a hairpin join's arc against its count by
// hand, and Scene's refusal at kMaxOutlineVertices for every kind of item.
#include <catch2/catch.hpp>
#include <splinefig/base/limits.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include "renderer/src/stroke.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace splinefig;
using render::Vec2;
namespace d = render::detail;

namespace {

const d::Box kCanvas{0, 0, 800, 500};
const d::Box kNear{-16, -16, 816, 516};  // as Scene estimates

std::size_t built(const std::vector<Vec2>& pts, bool closed, const render::StrokeStyle& s) {
  d::Geometry g;
  d::ChainBuilder b(g, kCanvas);
  d::stroke_path(pts, closed, s, b);
  return g.verts.size();
}

render::StrokeStyle style(double width, render::Join join, render::Cap cap, std::vector<double> dashes = {}) {
  render::StrokeStyle s;
  s.width = width;
  s.join = join;
  s.cap = cap;
  s.dashes = render::DashPattern(std::move(dashes));
  return s;
}

// n points alternating between x = 10 and x = 790, rising by `dy` a point.
std::vector<Vec2> hairpins(int n, double dy) {
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) p.push_back({i % 2 ? 790.0 : 10.0, 10 + dy * i});
  return p;
}

}  // namespace

TEST_CASE("a hairpin round join's arc: the bound counts the chords a 1e-4 px sagitta allows, by hand") {
  // A turn of pi on a pen of half-width h = 1: chords of angle 2 acos(1 - 1e-4) = 0.0282847 rad,
  // so ceil(pi / 0.0282847) = 112 chords and 111 interior vertices (two joins' worth of corners
  // and the inner side are at most 5 more).
  const double chord = 2 * std::acos(1 - 1e-4);
  REQUIRE(std::ceil(std::numbers::pi / chord) == 112);
  const auto s = style(2, render::Join::Round, render::Cap::Butt);
  const std::vector<Vec2> one{{10, 10}, {790, 11}, {10, 12}};
  const double bound = d::stroke_vertex_bound(one, false, s, kNear);
  const std::size_t real = built(one, false, s);
  INFO("bound " << bound << ", built " << real);
  CHECK(real >= 111 + 4);  // the arc's interior and the four offset ends
  CHECK(bound >= double(real));
  CHECK(bound <= 2 * (112 + 5 + 2 * 6 + 2 * 3 + 8));  // the arc, the join's corners, two butt caps, the points
}

TEST_CASE("stroke_vertex_bound is at least the outline stroke_path builds, and near it for hairpins") {
  using J = render::Join;
  using C = render::Cap;
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u(-100, 900), w(0.1, 30);
  for (J join : {J::Round, J::Miter, J::Bevel})
    for (C cap : {C::Round, C::Butt, C::Square})
      for (int dashed = 0; dashed < 2; ++dashed)
        for (int trial = 0; trial < 12; ++trial) {
          const double width = w(rng);
          auto s = style(width, join, cap, dashed ? std::vector<double>{width * (0.2 + trial), 3.0} : std::vector<double>{});
          std::vector<Vec2> pts;
          if (trial % 4 == 0) pts = hairpins(60, 2.5);
          else if (trial % 4 == 1) for (int i = 0; i < 50; ++i) pts.push_back({u(rng), u(rng)});
          else if (trial % 4 == 2) for (int i = 0; i < 50; ++i) pts.push_back({u(rng) * 1e9, u(rng) - 1e12});  // far off
          else pts = {{400, 250}, {400, 250}};  // one point: a dot
          for (int closed = 0; closed < 2; ++closed) {
            const double bound = d::stroke_vertex_bound(pts, closed, s, kNear);
            const std::size_t real = built(pts, closed, s);
            INFO("join " << int(join) << " cap " << int(cap) << " dashed " << dashed << " trial " << trial << " closed "
                         << closed << ": bound " << bound << ", built " << real);
            CHECK(bound >= double(real));
            if (trial % 4 == 0 && join == J::Round && !dashed) CHECK(bound <= 1.5 * double(real) + 200);
          }
        }
}

TEST_CASE("the bound of a huge pen's round joins and caps is thousands, not the 1e-9 rad chords' billions") {
  // A pen of width 1e9 takes the distance-scaled arc steps (geometry.hpp): a few hundred vertices
  // a join, where the fine step alone would count pi / 1e-9.
  const auto s = style(1e9, render::Join::Round, render::Cap::Round);
  const std::vector<Vec2> pts{{0, 0}, {800, 0}, {0, 500}, {800, 500}};
  const double bound = d::stroke_vertex_bound(pts, false, s, kNear);
  const std::size_t real = built(pts, false, s);
  INFO("bound " << bound << ", built " << real);
  CHECK(bound >= double(real));
  CHECK(bound < 1e5);
}

TEST_CASE("Scene refuses an outline past kMaxOutlineVertices before building it, naming the call") {
  // 2^26 / 110 hairpins of a pen of width 2 (about 120 vertices each) is past the limit.
  const int over = static_cast<int>(kMaxOutlineVertices / 110);
  const auto s = style(2, render::Join::Round, render::Cap::Round);
  {
    render::Scene scene(800, 500);
    const auto pts = hairpins(over, 480.0 / over);
    const double bound = d::stroke_vertex_bound(pts, false, s, kNear);
    REQUIRE(bound > kMaxOutlineVertices);
    CHECK_THROWS_WITH(scene.stroke_polyline(pts, false, s, {0, 0, 0, 1}),
                      Catch::StartsWith("stroke_polyline: its outline would have about ") &&
                          Catch::Contains("over the limit of 2^26"));
  }
  {
    // Just under: recorded. Two of them are past the scene's limit together.
    render::Scene scene(800, 500);
    int n = over;
    std::vector<Vec2> pts;
    double bound = 0;
    do {
      n = n * 31 / 32;
      pts = hairpins(n, 480.0 / n);
      bound = d::stroke_vertex_bound(pts, false, s, kNear);
    } while (bound > kMaxOutlineVertices);
    INFO("n " << n << ", bound " << bound);
    CHECK(bound > 0.9 * kMaxOutlineVertices);
    CHECK_NOTHROW(scene.stroke_polyline(pts, false, s, {0, 0, 0, 1}));
    CHECK_THROWS_WITH(scene.stroke_polyline(pts, false, s, {0, 0, 0, 1}),
                      Catch::StartsWith("stroke_polyline: the scene's outlines would have about ") &&
                          Catch::Contains("over the limit of 2^26"));
  }
}

TEST_CASE("round caps on many dashes, circles, markers and flattened paths count against the limit too") {
  render::Scene scene(1000, 1000);
  // 18000 passes of 980 px with dashes [30, 30] and round caps of a pen 40 wide: 3e5 dashes, a
  // dash work of 8.7e5 (under 2^20), each dash's two caps about 500 vertices each.
  std::vector<Vec2> zig;
  for (int i = 0; i < 18000; ++i) zig.push_back({i % 2 ? 990.0 : 10.0, 10 + 0.049 * i});
  CHECK_THROWS_WITH(scene.stroke_polyline(zig, false, style(40, render::Join::Miter, render::Cap::Round, {30, 30}), {0, 0, 0, 1}),
                    Catch::StartsWith("stroke_polyline: its outline would have about "));
  // A dashed circle of radius 400 with dashes of 0.01 px and round caps of a pen 60 wide: 1.3e5
  // dashes, each cap about 600 vertices.
  CHECK_THROWS_WITH(scene.stroke_circle({500, 500}, 400, style(60, render::Join::Round, render::Cap::Round, {0.01, 0.01}), {0, 0, 0, 1}),
                    Catch::StartsWith("stroke_circle: its outline would have about "));
  // A cubic of control points 1e14 apart flattens to 1e6 chords; 100 of them are 1e8 points.
  render::Path path;
  path.move_to({0, 0});
  for (int i = 0; i < 100; ++i) path.cubic_to({1e14, 0}, {-1e14, 1}, {0, 2});
  CHECK(path.flattened_size(1e-4) == 100 * 1000000 + 1);
  CHECK_THROWS_WITH(scene.fill_path(path, render::FillRule::NonZero, {0, 0, 0, 1}), Catch::StartsWith("fill_path: its outline would have about "));
  CHECK_THROWS_WITH(scene.stroke_path(path, style(1, render::Join::Miter, render::Cap::Butt), {0, 0, 0, 1}),
                    Catch::StartsWith("stroke_path: its outline would have about "));
  // Circle markers of 200 px (about 2200 vertices each): 30000 of them fill the scene's budget.
  std::size_t drawn = 0;
  try {
    for (; drawn < 40000; ++drawn) scene.marker(render::Marker::Circle, {500, 500}, 200, {0, 0, 0, 1});
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("marker: the scene's outlines would have about "));
  }
  INFO("markers recorded: " << drawn);
  CHECK(drawn > 25000);
  CHECK(drawn < 35000);
}

TEST_CASE("a large legitimate stroke under the limit still draws") {
  // 200 hairpins 2.4 px apart of a pen of width 1, round joins and caps, on 800 x 500: recorded
  // and drawn; down the middle column each 2.4 px of height holds 1 px of ink, so the column's
  // mean over the passes is 1 - 1 / 2.4 (by hand), within the rows' ends.
  render::Scene scene(800, 500, {1, 1, 1, 1});
  const auto pts = hairpins(200, 2.4);
  scene.stroke_polyline(pts, false, style(1, render::Join::Round, render::Cap::Round), {0, 0, 0, 1});
  const Image img = render::rasterize(scene, 2);
  double sum = 0;
  for (int y = 12; y < 12 + 2 * 96; ++y) sum += img.pixels[(static_cast<std::size_t>(y) * 800 + 400) * 4];
  CHECK(sum / (2 * 96) == Approx(1 - 1 / 2.4).margin(0.03));
  CHECK(img.pixels[(static_cast<std::size_t>(499) * 800 + 400) * 4] == Approx(1.0f));
}
