// Path items of a Scene: filled and stroked paths, flattened at rasterization time, against
// exact areas; and the read-only view of the recorded items.
#include "coverage_helpers.hpp"

#include <splinefig/renderer/path.hpp>

#include <catch2/catch.hpp>

#include <numeric>
#include <string>
#include <type_traits>
#include <variant>

using namespace splinefig::render;

namespace {
double total(const std::vector<double>& c) { return std::accumulate(c.begin(), c.end(), 0.0); }
}  // namespace

TEST_CASE("fill_path: a parabolic segment has the area of Archimedes' quadrature") {
  // The quadratic from (10, 50) through control (40, -10) to (70, 50) with its chord: the
  // region between the parabola and the chord is 2/3 of chord x height, and the parabola's
  // vertex lies halfway to the control point (height 30): 2/3 * 60 * 30 = 1200 px^2.
  Path p;
  p.move_to({10, 50});
  p.quad_to({40, -10}, {70, 50});
  p.close();
  const auto cov = testutil::rendered_coverage(80, 60, [&](Scene& s) { s.fill_path(p, FillRule::NonZero, {1, 1, 1, 1}); });
  CHECK(total(cov) == Approx(1200.0).margin(0.05));
}

TEST_CASE("fill_path: a closed path with two subpaths obeys the fill rule") {
  Path p;  // two nested squares of the same orientation: 30x30 outer, 10x10 inner
  p.move_to({5, 5}), p.line_to({35, 5}), p.line_to({35, 35}), p.line_to({5, 35}), p.close();
  p.move_to({15, 15}), p.line_to({25, 15}), p.line_to({25, 25}), p.line_to({15, 25}), p.close();
  const auto nz = testutil::rendered_coverage(40, 40, [&](Scene& s) { s.fill_path(p, FillRule::NonZero, {1, 1, 1, 1}); });
  const auto eo = testutil::rendered_coverage(40, 40, [&](Scene& s) { s.fill_path(p, FillRule::EvenOdd, {1, 1, 1, 1}); });
  CHECK(total(nz) == Approx(900.0).margin(1e-6));
  CHECK(total(eo) == Approx(800.0).margin(1e-6));
}

TEST_CASE("stroke_path: a straight cubic strokes like the line, subpaths are one union") {
  // Control points on the line at thirds: the cubic is the segment itself, so the stroke is the
  // 40 x 4 rectangle (butt caps). A second subpath crossing it adds its own rectangle minus the
  // 4 x 4 overlap, which is covered once (union), not twice.
  StrokeStyle st;
  st.width = 4;
  Path p;
  p.move_to({10, 30}), p.cubic_to({70.0 / 3, 30}, {110.0 / 3, 30}, {50, 30});
  const auto one = testutil::rendered_coverage(60, 60, [&](Scene& s) { s.stroke_path(p, st, {1, 1, 1, 1}); });
  CHECK(total(one) == Approx(160.0).margin(1e-6));
  p.move_to({30, 10}), p.line_to({30, 50});
  const auto two = testutil::rendered_coverage(60, 60, [&](Scene& s) { s.stroke_path(p, st, {1, 1, 1, 0.5f}); });
  // Alpha 0.5 over transparent: coverage * 0.5 wherever covered, once.
  CHECK(total(two) == Approx(0.5 * (160.0 + 160.0 - 16.0)).margin(1e-5));
  double worst = 0;
  for (double c : two) worst = std::max(worst, c);
  CHECK(worst == Approx(0.5).margin(1e-6));
}

TEST_CASE("stroke_path: a round stroke of a quarter circle Bezier is an annulus sector") {
  // The standard cubic quarter circle (k = 0.5522847498) deviates from the circle by at most
  // 2.7e-4 of the radius; with radius 40 that is 0.011 px, under 0.5 px^2 of area over the arc.
  const double r = 40, k = 0.5522847498307936;
  Path p;
  p.move_to({10 + r, 10}), p.cubic_to({10 + r, 10 + k * r}, {10 + k * r, 10 + r}, {10, 10 + r});
  StrokeStyle st;
  st.width = 6;
  const auto cov = testutil::rendered_coverage(70, 70, [&](Scene& s) { s.stroke_path(p, st, {1, 1, 1, 1}); });
  const double exact = 0.25 * 3.14159265358979 * ((r + 3) * (r + 3) - (r - 3) * (r - 3));
  CHECK(total(cov) == Approx(exact).margin(1.0));
}

TEST_CASE("path items reject what other items reject, naming the call") {
  Scene s(10, 10);
  Path p;
  p.move_to({0, 0}), p.line_to({std::nan(""), 1});
  CHECK_THROWS_WITH(s.fill_path(p, FillRule::NonZero, {}), Catch::Contains("fill_path") && Catch::Contains("not finite"));
  StrokeStyle bad;
  bad.width = -1;
  Path q;
  q.move_to({0, 0}), q.line_to({1, 1});
  CHECK_THROWS_WITH(s.stroke_path(q, bad, {}), Catch::Contains("stroke_path") && Catch::Contains("negative"));
  CHECK(s.items().empty());
}

namespace {
// One word per item, from the item's own fields.
std::string describe(const DrawItem& item) {
  return std::visit(
      [](const auto& it) -> std::string {
        using T = std::decay_t<decltype(it)>;
        if constexpr (std::is_same_v<T, StrokeItem>) return "stroke" + std::to_string(it.points.size()) + (it.closed ? "c" : "");
        else if constexpr (std::is_same_v<T, FillItem>) return "fill" + std::to_string(it.contours.size());
        else if constexpr (std::is_same_v<T, PathFillItem>)
          return "fillpath" + std::to_string(it.path->verbs().size()) + (it.rule == FillRule::EvenOdd ? "e" : "n");
        else if constexpr (std::is_same_v<T, PathStrokeItem>)
          return "strokepath" + std::to_string(it.path->points().size()) + "w" + std::to_string(static_cast<int>(it.style.width));
        else if constexpr (std::is_same_v<T, DiskItem>) return "disk" + std::to_string(static_cast<int>(it.radius));
        else if constexpr (std::is_same_v<T, RingItem>) return "ring" + std::to_string(static_cast<int>(it.radius));
        else if constexpr (std::is_same_v<T, MarkerItem>) return it.shape == Marker::Plus ? "plus" : "marker";
        else if constexpr (std::is_same_v<T, TextItem>) return "text:" + it.text + (it.outline->empty() ? "" : "+outline");
        else return "image" + std::to_string(it.image->width) + (it.sampling == Sampling::Nearest ? "n" : "b");
      },
      item);
}
}  // namespace

TEST_CASE("items() holds every item in drawing order with its arguments") {
  Scene s(20, 20, {0.5f, 0.5f, 0.5f, 1});
  const Vec2 line[3] = {{0, 0}, {5, 5}, {9, 0}};
  s.stroke_polyline(line, true, {}, {});
  s.fill_polygon({{{0, 0}, {1, 0}, {1, 1}}, {{2, 2}, {3, 2}, {3, 3}}}, FillRule::NonZero, {});
  Path p;
  p.move_to({1, 1}), p.cubic_to({2, 2}, {3, 2}, {4, 1});
  s.fill_path(p, FillRule::EvenOdd, {});
  StrokeStyle st;
  st.width = 3;
  s.stroke_path(p, st, {});
  s.fill_circle({5, 5}, 2, {});
  s.stroke_circle({5, 5}, 4, {}, {});
  s.marker(Marker::Plus, {3, 3}, 4, {});
  s.text("hi", {2, 2}, {});
  s.image(std::make_shared<const splinefig::Image>(splinefig::Image(3, 2, 4)), {0, 0}, {3, 2}, Scene::Sampling::Nearest);
  std::string log;
  for (const DrawItem& item : s.items()) log += describe(item) + " ";
  CHECK(log == "stroke3c fill2 fillpath2e strokepath4w3 disk2 ring4 plus text:hi+outline image3n ");
  CHECK(s.background().r == 0.5f);
  CHECK_FALSE(s.clipped());
}

TEST_CASE("marker_polygon: the square and diamond outlines have the documented sizes") {
  const auto sq = marker_polygon(Marker::Square, {10, 10}, 4);
  REQUIRE(sq.size() == 4);
  CHECK(sq[0].x == 8.0);
  CHECK(sq[2].y == 12.0);
  const auto di = marker_polygon(Marker::Diamond, {0, 0}, 2);
  REQUIRE(di.size() == 4);
  CHECK(di[1].x == 1.0);
  CHECK(marker_polygon(Marker::Circle, {0, 0}, 2).empty());
}
