// Path: exact quadratic elevation, flattening within the requested tolerance, affine maps.
#include <splinefig/renderer/path.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using splinefig::render::Path;
using splinefig::render::Vec2;

namespace {
// De Casteljau at t, an evaluation independent of the Bernstein sums flatten() uses.
Vec2 casteljau(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double t) {
  auto lerp = [t](Vec2 p, Vec2 q) { return Vec2{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)}; };
  Vec2 ab = lerp(a, b), bc = lerp(b, c), cd = lerp(c, d);
  Vec2 abc = lerp(ab, bc), bcd = lerp(bc, cd);
  return lerp(abc, bcd);
}
double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}
}  // namespace

TEST_CASE("quad_to stores the exact cubic elevation") {
  Path p;
  p.move_to({0, 0});
  p.quad_to({3, 6}, {6, 0});
  REQUIRE(p.verbs().size() == 2);
  REQUIRE(p.points().size() == 4);
  // (p0 + 2c)/3 = (2, 4), (p + 2c)/3 = (4, 4): the quadratic's midpoint (3, 3) is the cubic's.
  CHECK(p.points()[1].x == 2.0);
  CHECK(p.points()[1].y == 4.0);
  CHECK(p.points()[2].x == 4.0);
  CHECK(p.points()[2].y == 4.0);
  const Vec2 m = casteljau(p.points()[0], p.points()[1], p.points()[2], p.points()[3], 0.5);
  CHECK(m.x == 3.0);
  CHECK(m.y == 3.0);
}

TEST_CASE("flatten keeps every curve point within the tolerance of the polyline") {
  const Vec2 a{0, 0}, b{100, 300}, c{-200, 250}, d{80, -40};
  Path p;
  p.move_to(a);
  p.cubic_to(b, c, d);
  for (double tol : {1.0, 0.1, 1e-3}) {
    const auto flat = p.flatten(tol);
    REQUIRE(flat.contours.size() == 1);
    REQUIRE(flat.closed == std::vector<bool>{false});
    const auto& poly = flat.contours[0];
    CHECK(poly.front().x == a.x);
    CHECK(poly.back().y == d.y);
    double worst = 0;
    for (int i = 0; i <= 20000; ++i) {
      const Vec2 q = casteljau(a, b, c, d, i / 20000.0);
      double best = 1e300;
      for (std::size_t j = 0; j + 1 < poly.size(); ++j) best = std::min(best, segment_distance(q, poly[j], poly[j + 1]));
      worst = std::max(worst, best);
    }
    CHECK(worst <= tol);
    CHECK(worst > tol / 50);  // and not wastefully finer than asked
  }
}

TEST_CASE("flatten reports closed and open subpaths and drops a repeated closing point") {
  Path p;
  p.move_to({0, 0});
  p.line_to({10, 0});
  p.line_to({10, 10});
  p.line_to({0, 0});
  p.close();
  p.move_to({20, 20});
  p.line_to({30, 20});
  const auto flat = p.flatten(0.1);
  REQUIRE(flat.contours.size() == 2);
  CHECK(flat.closed == std::vector<bool>{true, false});
  CHECK(flat.contours[0].size() == 3);
  CHECK(flat.contours[1].size() == 2);
  CHECK_THROWS_AS(p.flatten(0.0), std::invalid_argument);
}

TEST_CASE("transformed maps control points by the affine map") {
  Path p;
  p.move_to({1, 2});
  p.cubic_to({3, 4}, {5, 6}, {7, 8});
  const Path q = p.transformed(2, 0, 0, -1, 10, 20);  // x' = 2x + 10, y' = -y + 20
  REQUIRE(q.points().size() == 4);
  CHECK(q.points()[0].x == 12.0);
  CHECK(q.points()[0].y == 18.0);
  CHECK(q.points()[3].x == 24.0);
  CHECK(q.points()[3].y == 12.0);
}
