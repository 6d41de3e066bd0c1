// The grid that label placement reads (figures/src/paint/draw.hpp, Occupancy): after marking
// polylines, points and rectangles, exactly the cells that the marks' squares cover, each mark
// laid down cell by cell here (a square of half-size `radius` every 1.5 px at most along each
// segment), whatever the spans the grid keeps.
#include <catch2/catch.hpp>

#include "figures/src/paint/draw.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace sfd = splinefig::figures::detail;
using splinefig::render::Vec2;

namespace {

struct Cells {
  int w, h;
  std::vector<char> on;
  Cells(int w_, int h_) : w(w_), h(h_), on(static_cast<size_t>(w_) * h_, 0) {}
  void square(Vec2 p, double r) {
    if (!(std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6 && r < 1e4)) return;
    for (int y = std::max(0, int(std::floor(p.y - r))); y <= std::min(h - 1, int(std::floor(p.y + r))); ++y)
      for (int x = std::max(0, int(std::floor(p.x - r))); x <= std::min(w - 1, int(std::floor(p.x + r))); ++x)
        on[static_cast<size_t>(y) * w + x] = 1;
  }
  void polyline(const std::vector<Vec2>& pts, double r) {
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      const Vec2 a = pts[i], b = pts[i + 1];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      if (!std::isfinite(len) || len > 1e5) continue;
      const int n = std::max(1, int(std::ceil(len / 1.5)));
      for (int k = 0; k < n; ++k) square({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n}, r);
    }
    if (!pts.empty()) square(pts.back(), r);
  }
};

// Every cell of the canvas, one by one, and a rectangle partly off it.
void check_same(sfd::Occupancy& occ, const Cells& ref) {
  int wrong = 0;
  for (int y = 0; y < ref.h; ++y)
    for (int x = 0; x < ref.w; ++x) {
      const long got = occ.count(sfd::Rect{double(x), double(y), double(x), double(y)});
      wrong += got != ref.on[static_cast<size_t>(y) * ref.w + x];
    }
  CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("the occupancy grid covers exactly the squares of every mark", "[figures][occupancy]") {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-40, 200), rad(1, 30);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 160, h = 120;
    sfd::Occupancy occ(w, h);
    Cells ref(w, h);
    const double r = trial % 4 == 0 ? 1.0 : rad(rng);
    std::vector<Vec2> pts;
    for (int i = 0; i < 30; ++i) pts.push_back({u(rng), u(rng)});
    if (trial % 5 == 0) pts.push_back({pts.back().x, pts.back().y + 50});  // vertical
    if (trial % 5 == 1) pts.push_back({pts.back().x + 50, pts.back().y});  // horizontal
    if (trial % 7 == 0) pts.push_back({3e6, 5});                           // far off, and back
    if (trial % 7 == 0) pts.push_back({20, 30});
    occ.mark_polyline(pts, r);
    ref.polyline(pts, r);
    const Vec2 q{u(rng), u(rng)};
    occ.mark_point(q, 2.5);
    ref.square(q, 2.5);
    INFO("trial " << trial << ", radius " << r);
    check_same(occ, ref);
  }
}

TEST_CASE("marks made after the grid was read are seen by the next read", "[figures][occupancy]") {
  sfd::Occupancy occ(50, 40);
  Cells ref(50, 40);
  occ.mark_polyline({{5, 5}, {45, 35}}, 2);
  ref.polyline({{5, 5}, {45, 35}}, 2);
  check_same(occ, ref);
  occ.mark_rect(sfd::Rect{10, 30, 20, 35});
  for (int y = 30; y <= 35; ++y)
    for (int x = 10; x <= 20; ++x) ref.on[static_cast<size_t>(y) * 50 + x] = 1;
  occ.mark_point({40, 5}, 3);
  ref.square({40, 5}, 3);
  check_same(occ, ref);
  // Off the canvas, a rectangle's cells count 4 each.
  CHECK(occ.count(sfd::Rect{-2, 0, -1, 0}) == 8);
}
