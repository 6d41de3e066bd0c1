// Drawing on several threads in blocks of rows (rasterize.cpp): an item's rows found before its
// geometry is built (renderer/src/item_reach.hpp) hold all of it, small items that fall inside
// one block or across two are drawn the same on any thread count, and the work limit of an item
// drawn by two blocks is its total, as on one thread.
#include <catch2/catch.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include "renderer/src/item_reach.hpp"
#include "renderer/src/prepare.hpp"

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace splinefig;
using render::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;

// Random items of every kind around (cx, cy), small enough to stay inside a 1024^2 canvas:
// polylines with sharp turns (miter tips up to the limit), every join, cap and dash, paths with
// cubics, text at any angle, disks, rings, markers, fills and images.
void add_random_item(render::Scene& s, std::mt19937_64& rng, double cx, double cy, double size) {
  std::uniform_real_distribution<double> u(0, 1);
  auto pt = [&] { return Vec2{cx + size * (u(rng) - 0.5), cy + size * (u(rng) - 0.5)}; };
  const render::Color ink{static_cast<float>(u(rng)), 0.3f, static_cast<float>(u(rng)), 0.7f};
  render::StrokeStyle st;
  st.width = 0.5 + 8 * u(rng);
  st.join = static_cast<render::Join>(rng() % 3);
  st.cap = static_cast<render::Cap>(rng() % 3);
  st.miter_limit = 1 + 9 * u(rng);
  if (rng() % 4 == 0) st.dashes = {1 + 6 * u(rng), 1 + 3 * u(rng)};
  switch (rng() % 9) {
    case 0:
    case 1: {
      // A zigzag: turns of up to nearly 180 degrees, so miter tips reach h times the limit.
      std::vector<Vec2> p{pt()};
      const int n = 2 + static_cast<int>(rng() % 6);
      for (int k = 1; k < n; ++k) p.push_back(k % 2 ? pt() : Vec2{p.back().x + size * (u(rng) - 0.5) * 0.1, p[k - 1].y});
      s.stroke_polyline(p, rng() % 5 == 0, st, ink);
      break;
    }
    case 2: {
      render::Path path;
      path.move_to(pt());
      path.cubic_to(pt(), pt(), pt());
      path.line_to(pt());
      if (rng() % 2) path.close();
      if (rng() % 2) s.stroke_path(path, st, ink);
      else s.fill_path(path, render::FillRule::NonZero, ink);
      break;
    }
    case 3: {
      render::TextStyle ts;
      ts.size = 6 + 20 * u(rng);
      ts.angle = 360 * u(rng);
      ts.valign = static_cast<render::VAlign>(rng() % 4);
      s.text("Ag|y", pt(), ts);
      break;
    }
    case 4: s.fill_circle(pt(), 0.5 * size * u(rng), ink); break;
    case 5: s.stroke_circle(pt(), 0.4 * size * u(rng), st, ink); break;
    case 6: s.marker(static_cast<render::Marker>(rng() % 5), pt(), size * u(rng), ink); break;
    case 7: s.fill_polygon({{pt(), pt(), pt(), pt()}}, render::FillRule::EvenOdd, ink); break;
    default: {
      auto img = std::make_shared<Image>(3, 2, 4);
      for (std::size_t k = 0; k < img->pixels.size(); ++k) img->pixels[k] = static_cast<float>(k % 4 == 3 ? 1 : u(rng));
      s.image(img, pt(), pt(), rng() % 2 ? render::Sampling::Nearest : render::Sampling::Bilinear);
    }
  }
}

bool same_bytes(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// How item 2 of the scene fares at the work limit: "drawn", or the refusal's message.
std::string outcome(render::Scene& scene, double limit, int threads) {
  scene.set_max_crossings(limit);
  try {
    (void)render::rasterize(scene, threads);
    return "drawn";
  } catch (const std::length_error& e) {
    return e.what();
  }
}

}  // namespace

TEST_CASE("an item's rows found before its geometry is built hold all of its geometry", "[renderer][threads]") {
  std::mt19937_64 rng(20261207);
  const render::detail::Compositor comp(render::BlendSpace::linear);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    render::Scene s(1024, 1024);
    add_random_item(s, rng, 512, 512, 4 + 120.0 * (trial % 7) / 6);
    const render::DrawItem& item = s.items()[0];
    double y0 = 0, y1 = 0;
    REQUIRE(render::detail::item_y_range(item, y0, y1));
    render::detail::Geometry g;
    render::detail::Prepared p;
    render::detail::prepare_item(item, nullptr, comp, {0, 0}, {0, 0, 1024, 1024}, g, p, 1024);
    if (p.raster) {
      CHECK(std::floor(y0) <= p.row0);
      CHECK(std::ceil(y1) >= p.row1);
      ++checked;
      continue;
    }
    if (p.shape.empty()) continue;
    INFO("trial " << trial << ", kind " << item.index() << ": geometry [" << p.shape.ymin << ", " << p.shape.ymax
                  << "], found [" << y0 << ", " << y1 << "]");
    CHECK(p.shape.ymin >= y0);
    CHECK(p.shape.ymax <= y1);
    ++checked;
  }
  CHECK(checked > 2500);
}

TEST_CASE("a miter tip at its limit lies inside the rows found for its stroke", "[renderer][threads]") {
  // Two segments meeting at (100, 100) at an angle whose miter ratio is just under the limit: the
  // tip lies h / sin(theta / 2) below the vertex, with theta the angle between the segments.
  const double theta = 2 * std::asin(1 / 3.9), h = 5;  // miter ratio 3.9, limit 4
  render::StrokeStyle st;
  st.width = 2 * h;
  st.join = render::Join::Miter;
  st.miter_limit = 4;
  const Vec2 v{100, 100};
  const std::vector<Vec2> p{{v.x - 60 * std::sin(theta / 2), v.y - 60 * std::cos(theta / 2)},
                            v,
                            {v.x + 60 * std::sin(theta / 2), v.y - 60 * std::cos(theta / 2)}};
  render::Scene s(200, 200);
  s.stroke_polyline(p, false, st, {0, 0, 0, 1});
  double y0 = 0, y1 = 0;
  REQUIRE(render::detail::item_y_range(s.items()[0], y0, y1));
  const double tip = v.y + h / std::sin(theta / 2);  // 119.5
  CHECK(y1 >= tip);
  CHECK(y1 <= tip + 2);  // and not far past it
}

TEST_CASE("small items inside one block of rows, across two, and long ones draw the same on any thread count",
          "[renderer][threads]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  render::Scene s(1024, 1024, {1, 1, 1, 1});
  s.set_coverage_tolerance(1.0 / 1024);
  // A long stroke under everything, drawn by every block.
  std::vector<Vec2> curve;
  for (int k = 0; k <= 4000; ++k) {
    const double t = 2 * kPi * k / 4000;
    curve.push_back({512 + 480 * std::sin(3 * t + kPi / 2), 512 + 480 * std::sin(4 * t)});
  }
  render::StrokeStyle cs;
  cs.width = 3;
  s.stroke_polyline(curve, false, cs, {0.2f, 0.2f, 0.9f, 0.8f});
  for (int i = 0; i < 6000; ++i) add_random_item(s, rng, 40 + 944 * u(rng), 40 + 944 * u(rng), 4 + 60 * u(rng));
  // A dense item across the rows where blocks meet on 2 and 4 threads (256 and 240), drawn from
  // its pieces in some bands: its report is the same on any thread count too.
  std::vector<Vec2> dense;
  for (int k = 0; k < 4000; ++k) dense.push_back({300 + 200 * u(rng), 226 + 44 * u(rng)});
  render::StrokeStyle ds;
  s.stroke_polyline(dense, false, ds, {0, 0, 0, 0.9f});
  render::RasterReport ref_report;
  const Image ref = render::rasterize(s, 1, &ref_report);
  REQUIRE_FALSE(ref_report.items.empty());
  for (int threads : {2, 3, 4, 8}) {
    INFO(threads << " threads");
    render::RasterReport report;
    const Image img = render::rasterize(s, threads, &report);
    CHECK(same_bytes(img, ref));
    REQUIRE(report.items.size() == ref_report.items.size());
    for (std::size_t k = 0; k < report.items.size(); ++k) {
      CHECK(report.items[k].index == ref_report.items[k].index);
      CHECK(report.items[k].bands == ref_report.items[k].bands);
      CHECK(report.items[k].piece_bands == ref_report.items[k].piece_bands);
    }
  }
}

TEST_CASE("an item drawn by two blocks of rows is refused exactly when its total work passes the limit",
          "[renderer][threads][work]") {
  // A zigzag across rows 236 to 276, where blocks meet on 2 threads (256) and on 4 (240); inside
  // one block on 3. Its outline crosses itself at every turn; coverage exact, so the sweep does
  // all of its work.
  std::vector<Vec2> zz;
  for (int i = 0; i < 800; ++i) zz.push_back({10 + 230.0 * i / 800, i % 2 ? 236.0 : 276.0});
  render::StrokeStyle st;
  st.width = 1.5;
  render::Scene scene(256, 1024);
  scene.set_coverage_tolerance(0);
  scene.fill_circle({10, 10}, 5, {0, 0, 0, 1});
  scene.stroke_polyline(zz, false, st, {0, 0, 0, 1});
  scene.stroke_polyline(zz, false, st, {1, 0, 0, 1});
  // The least limit under which one thread draws it, found by bisection.
  double lo = 1, hi = 1e9;
  REQUIRE(outcome(scene, lo, 1) != "drawn");
  REQUIRE(outcome(scene, hi, 1) == "drawn");
  while (hi - lo > 1) {
    const double mid = std::floor(0.5 * (lo + hi));
    (outcome(scene, mid, 1) == "drawn" ? hi : lo) = mid;
  }
  INFO("drawn from a limit of " << hi);
  REQUIRE(hi > 1000);
  const std::string refused = outcome(scene, lo, 1);
  CHECK(refused.rfind("item 2 (stroked polyline)", 0) == 0);
  for (int threads : {2, 3, 4}) {
    INFO(threads << " threads");
    CHECK(outcome(scene, hi, threads) == "drawn");
    CHECK(outcome(scene, lo, threads) == refused);
    CHECK(outcome(scene, 0.5 * hi, threads) == outcome(scene, 0.5 * hi, 1));
  }
}
