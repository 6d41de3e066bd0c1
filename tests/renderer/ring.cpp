// A stroked circle is the annulus between radii r - w/2 and r + w/2: its coverage sums to the
// annulus's area, 4 pi r h (pi (r + h)^2 when the pen covers the centre), and pixels well inside
// the hole or outside the outer circle are empty.
#include <catch2/catch.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <cmath>
#include <numbers>

using namespace splinefig;

namespace {

struct Sums {
  double total = 0, hole = 0, outside = 0;
};

Sums ring_coverage(double cx, double cy, double r, double width) {
  render::Scene s(64, 64, {0, 0, 0, 0});
  render::StrokeStyle st;
  st.width = width;
  s.stroke_circle({cx, cy}, r, st, {0, 0, 0, 1});
  const Image img = render::rasterize(s, 1);
  Sums out;
  const double h = width / 2;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double a = img.pixels[(static_cast<std::size_t>(y) * 64 + x) * 4 + 3];
      out.total += a;
      // the pixel's farthest and nearest points from the centre
      const double fx = std::max(std::abs(x - cx), std::abs(x + 1 - cx)), fy = std::max(std::abs(y - cy), std::abs(y + 1 - cy));
      const double nx = std::max({0.0, x - cx, cx - x - 1}), ny = std::max({0.0, y - cy, cy - y - 1});
      if (std::hypot(fx, fy) < r - h) out.hole += a;
      if (std::hypot(nx, ny) > r + h) out.outside += a;
    }
  return out;
}

}  // namespace

TEST_CASE("a stroked circle covers its annulus: area 4 pi r h, nothing in the hole or beyond", "[renderer][ring]") {
  for (auto [cx, cy, r, w] : {std::tuple{31.3, 30.7, 20.0, 3.0}, {32.0, 32.0, 9.25, 0.5}, {20.5, 40.1, 2.5, 1.0},
                              {33.7, 31.2, 20.5, 11.0}}) {
    const Sums s = ring_coverage(cx, cy, r, w);
    const double h = w / 2, area = 4 * std::numbers::pi * r * h;
    INFO("r " << r << " width " << w << ": " << s.total << " against " << area);
    // The circles are polygons within 1e-4 px of the arcs: the area is off by at most that times
    // the two perimeters.
    CHECK(std::abs(s.total - area) <= 1e-4 * 2 * std::numbers::pi * (2 * r) + 1e-6 * area);
    CHECK(s.hole == 0);
    CHECK(s.outside == 0);
  }
  // A pen wider than the diameter covers the disk of radius r + h.
  const Sums d = ring_coverage(32.2, 31.9, 3, 10);
  CHECK(std::abs(d.total - std::numbers::pi * 8 * 8) <= 1e-4 * 2 * std::numbers::pi * 8 + 1e-6 * d.total);
  CHECK(d.outside == 0);
}
