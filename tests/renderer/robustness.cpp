// Determinism across thread counts, coordinates far outside the canvas, and bad input.
#include "coverage_helpers.hpp"
#include <oracle/union_coverage.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

namespace sr = splinefig::render;

namespace {

sr::Scene busy_scene(splinefig::Kernel filter) {
  sr::Scene s(150, 130, {1, 1, 1, 1}, filter);
  std::vector<sr::Vec2> curve;
  for (int k = 0; k <= 20000; ++k) {
    double t = 2 * 3.141592653589793 * k / 20000;
    curve.push_back({75 + 70 * std::sin(3 * t + 1.5707963), 65 + 60 * std::sin(4 * t)});
  }
  sr::StrokeStyle st;
  st.width = 1.5;
  st.join = sr::Join::Round;
  s.stroke_polyline(curve, false, st, {0.1f, 0.2f, 0.7f, 0.8f});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int w = 0; w < 30; ++w) {
    std::vector<sr::Vec2> walk{{150 * u(rng), 130 * u(rng)}};
    for (int j = 0; j < 40; ++j) {
      double a = 6.283185307 * u(rng);
      walk.push_back({walk.back().x + 3 * std::cos(a), walk.back().y + 3 * std::sin(a)});
    }
    sr::StrokeStyle ws;
    ws.width = 2;
    ws.dashes = {4, 2};
    s.stroke_polyline(walk, w % 3 == 0, ws, {0.8f, 0.1f, 0.1f, 0.6f});
  }
  s.fill_polygon({{{10, 10}, {140, 30}, {20, 120}}, {{30, 30}, {60, 90}, {120, 40}}}, sr::FillRule::EvenOdd, {0, 0.5f, 0, 0.3f});
  s.fill_circle({100, 90}, 25.3, {0.9f, 0.7f, 0, 0.5f});
  s.marker(sr::Marker::Diamond, {40, 100}, 12, {0, 0, 0, 1});
  s.text("splinefig", {75, 120}, sr::TextStyle{12, {0, 0, 0, 1}, sr::HAlign::Center});
  return s;
}

}  // namespace

TEST_CASE("output is byte-identical for any thread count") {
  for (const auto& filter : {splinefig::Kernel::box(), splinefig::Kernel::tent()}) {
    sr::Scene s = busy_scene(filter);
    auto ref = sr::rasterize(s, 1);
    for (int threads : {2, 3, 7, 0}) {
      auto img = sr::rasterize(s, threads);
      INFO("filter " << filter.name() << ", threads " << threads);
      REQUIRE(img.pixels.size() == ref.pixels.size());
      REQUIRE(std::memcmp(img.pixels.data(), ref.pixels.data(), ref.pixels.size() * sizeof(float)) == 0);
    }
  }
}

TEST_CASE("a segment with endpoints at 1e12 is clipped exactly, like the same line drawn short") {
  // The line through (10.3, 20.6) with direction (2, 1), butt ends far outside the canvas.
  const double dx = 2 / std::sqrt(5.0), dy = 1 / std::sqrt(5.0);
  auto line = [&](double reach) {
    return std::vector<sr::Vec2>{{10.3 - reach * dx, 20.6 - reach * dy}, {10.3 + reach * dx, 20.6 + reach * dy}};
  };
  sr::StrokeStyle st;
  st.width = 3.3;
  auto far = testutil::rendered_coverage(64, 48, [&](sr::Scene& s) { s.stroke_polyline(line(1e12), false, st, {1, 1, 1, 1}); });
  auto near = testutil::rendered_coverage(64, 48, [&](sr::Scene& s) { s.stroke_polyline(line(200), false, st, {1, 1, 1, 1}); });
  auto e = testutil::compare(far, near);
  CHECK(e.max <= 1e-3);
  // and the short one is right: against the oracle
  auto pts = line(200);
  auto want = oracle::union_coverage(oracle::stroke_pieces({{pts[0].x, pts[0].y}, {pts[1].x, pts[1].y}}, false, 3.3,
                                                           oracle::Join::Miter, 4, oracle::Cap::Butt), 64, 48);
  CHECK(testutil::compare(near, want).max <= 1e-6);
}

// Work proportional to the coordinates (a loop over 1e12 px of outline) would not end: a hang is
// the test runner's timeout (scripts/test: 300 s), not a timing assertion here, which a loaded
// machine could fail and a fast one pass with a quadratic loop.
TEST_CASE("huge shapes are drawn finite and clipped correctly") {
  // A disk of radius 1e12 whose top edge is the line y = 32: the rows below are covered.
  auto cov = testutil::rendered_coverage(64, 64, [&](sr::Scene& s) { s.fill_circle({32, 32 + 1e12}, 1e12, {1, 1, 1, 1}); });
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) REQUIRE(cov[y * 64 + x] == Approx(y >= 32 ? 1.0 : 0.0).margin(1e-3));
  // A zigzag with vertices at +-1e12 and round joins and caps, dashed, a huge ring, a huge fill.
  sr::Scene s(64, 64);
  std::vector<sr::Vec2> zig{{-1e12, -1e12}, {1e12, 30}, {-1e12, 1e12}, {1e12, -5e11}};
  sr::StrokeStyle st;
  st.width = 5;
  st.join = sr::Join::Round;
  st.cap = sr::Cap::Round;
  s.stroke_polyline(zig, false, st, {0, 0, 0, 1});
  st.dashes = {3, 1};
  s.stroke_polyline(zig, true, st, {1, 0, 0, 0.5f});
  s.stroke_circle({1e12, 1e12}, 1.4e12, st, {0, 0, 1, 1});
  st.width = 1e12;
  s.stroke_polyline(std::vector<sr::Vec2>{{0, 0}, {5, 5}}, false, st, {0, 1, 0, 0.2f});
  s.fill_polygon({{{-1e15, -1e15}, {1e15, 0}, {0, 1e15}}}, sr::FillRule::NonZero, {0.5f, 0.5f, 0.5f, 0.5f});
  auto img = sr::rasterize(s, 2);
  for (float v : img.pixels) REQUIRE(std::isfinite(v));
}

TEST_CASE("NaN and infinite input is rejected with std::invalid_argument naming it") {
  sr::Scene s(16, 16);
  std::vector<sr::Vec2> bad{{1, 2}, {NAN, 3}};
  sr::StrokeStyle st;
  REQUIRE_THROWS_WITH(s.stroke_polyline(bad, false, st, {}), Catch::Contains("point 1") && Catch::Contains("not finite"));
  REQUIRE_THROWS_AS(s.fill_polygon({{{0, 0}, {INFINITY, 1}, {1, 1}}}, sr::FillRule::NonZero, {}), std::invalid_argument);
  REQUIRE_THROWS_WITH(s.fill_circle({0, 0}, NAN, {}), Catch::Contains("radius"));
  REQUIRE_THROWS_WITH(s.fill_circle({0, 0}, -1, {}), Catch::Contains("negative"));
  // Numbers in messages are written as printf's %g writes them, as everywhere else in them.
  REQUIRE_THROWS_WITH(s.fill_circle({0, 0}, -1.5, {}), "fill_circle: radius -1.5 is negative");
  REQUIRE_THROWS_WITH(s.stroke_circle({0, 0}, -0.25, {}, {}), "stroke_circle: radius -0.25 is negative");
  REQUIRE_THROWS_WITH(s.marker(sr::Marker::Circle, {0, 0}, -2e-7, {}), "marker: size -2e-07 is negative");
  REQUIRE_THROWS_WITH(s.marker(sr::Marker::Circle, {NAN, 0}, 3, {}), Catch::Contains("centre"));
  REQUIRE_THROWS_WITH(s.text("x", {0, INFINITY}, {}), Catch::Contains("anchor"));
  st.width = NAN;
  REQUIRE_THROWS_WITH(s.stroke_polyline(std::vector<sr::Vec2>{{0, 0}, {1, 1}}, false, st, {}), Catch::Contains("width"));
  st.width = -2;
  REQUIRE_THROWS_WITH(s.stroke_circle({1, 1}, 3, st, {}), Catch::Contains("negative"));
  st.width = 1;
  // A dash pattern is checked where it is made: one that exists is valid.
  REQUIRE_THROWS_WITH(sr::DashPattern({1, NAN}), "dash length nan is not finite");
  REQUIRE_THROWS_WITH(sr::DashPattern({1, -2}), "dash length -2 is negative");
  REQUIRE_THROWS_WITH(sr::DashPattern({1e-6, 1e-6}), "dash pattern period 2e-06 px is below 0.001 px");
  REQUIRE_THROWS_WITH(sr::DashPattern({0, 0}), Catch::Contains("period 0 px"));
  REQUIRE_THROWS_WITH(sr::DashPattern({1, 2e15}), Catch::Contains("exceeds 1e+15"));
  // An odd list repeats to an even one (SVG), its period doubling: 3 on, 1 off, 2 on, 3 off, 1 on, 2 off.
  const sr::DashPattern odd{3, 1, 2};
  CHECK(std::vector<double>(odd.begin(), odd.end()) == std::vector<double>{3, 1, 2, 3, 1, 2});
  CHECK(odd.period() == 12);
  CHECK(sr::DashPattern{}.empty());
  CHECK(sr::DashPattern{}.period() == 0);
  CHECK(odd.scaled(0.5).period() == 6);
  REQUIRE_THROWS_WITH(odd.scaled(1e-5), Catch::Contains("below 0.001 px"));
  REQUIRE_THROWS_WITH(s.fill_circle({0, 0}, 1, {NAN, 0, 0, 1}), Catch::Contains("colour"));
  // magnitudes where doubles no longer resolve pixels (and differences overflow)
  REQUIRE_THROWS_WITH(s.fill_polygon({{{-1e300, 0}, {1e300, 0}, {0, 1}}}, sr::FillRule::NonZero, {}), Catch::Contains("1e15"));
  REQUIRE_THROWS_WITH(s.fill_circle({0, 0}, 1e200, {}), Catch::Contains("radius"));
  REQUIRE(s.items().empty());  // nothing half-added
}

TEST_CASE("canvas sizes outside 1..32768 a side or over 2^28 pixels are rejected") {
  REQUIRE_THROWS_WITH(sr::Scene(0, 10), Catch::Contains("empty"));
  REQUIRE_THROWS_WITH(sr::Scene(40000, 10), Catch::Contains("32768"));
  REQUIRE_THROWS_WITH(sr::Scene(20000, 20000), Catch::Contains("2^28"));
  REQUIRE_NOTHROW(sr::Scene(32768, 1));
}

TEST_CASE("degenerate paths: empty, one point, repeated points, zero width") {
  sr::StrokeStyle st;
  st.width = 4;
  st.cap = sr::Cap::Round;
  auto cov = testutil::rendered_coverage(16, 16, [&](sr::Scene& s) {
    s.stroke_polyline(std::vector<sr::Vec2>{}, false, st, {1, 1, 1, 1});
    s.stroke_polyline(std::vector<sr::Vec2>{{8, 8}, {8, 8}, {8, 8}}, false, st, {1, 1, 1, 1});  // a dot of diameter 4
  });
  double total = 0;
  for (double c : cov) total += c;
  CHECK(total == Approx(3.141592653589793 * 4).epsilon(1e-4));
  st.cap = sr::Cap::Butt;
  auto none = testutil::rendered_coverage(16, 16, [&](sr::Scene& s) {
    s.stroke_polyline(std::vector<sr::Vec2>{{8, 8}}, false, st, {1, 1, 1, 1});
    sr::StrokeStyle zero;
    zero.width = 0;
    s.stroke_polyline(std::vector<sr::Vec2>{{1, 1}, {15, 15}}, false, zero, {1, 1, 1, 1});
  });
  for (double c : none) REQUIRE(c == 0);
}
