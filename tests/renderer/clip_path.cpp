// Clip paths (Scene::set_clip): a shape intersected with the clip region, exactly, checked
// against intersections worked out by hand and drawn as plain polygons, and against the
// unclipped drawing where the clip covers or misses a pixel whole.
#include <catch2/catch.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace splinefig;
using render::FillRule;
using render::Vec2;

namespace {

render::Path polygon_path(const std::vector<std::vector<Vec2>>& contours) {
  render::Path p;
  for (const auto& c : contours) {
    p.move_to(c[0]);
    for (std::size_t i = 1; i < c.size(); ++i) p.line_to(c[i]);
    p.close();
  }
  return p;
}

double alpha(const Image& img, int x, int y) { return img.pixels[(static_cast<std::size_t>(y) * img.width + x) * 4 + 3]; }

double max_alpha_difference(const Image& a, const Image& b) {
  double m = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) m = std::max(m, std::abs(alpha(a, x, y) - alpha(b, x, y)));
  return m;
}

constexpr render::Color kInk{0, 0, 0, 1}, kClear{0, 0, 0, 0};

}  // namespace

TEST_CASE("a rectangle clipped by a triangle is the polygon of their intersection", "[renderer][clip]") {
  // Rectangle [2.3, 13.6] x [1.7, 11.2]; triangle (0.5, 12.5), (15.5, 12.5), (8, 0.25), whose
  // sides are x = 0.5 + (12.5 - y) / k and x = 15.5 - (12.5 - y) / k with k = 12.25 / 7.5. The
  // rectangle's top (y = 1.7) cuts them at x = 0.5 + 10.8 / k and 15.5 - 10.8 / k; its sides meet
  // them at y = 12.5 - 1.8 k = 9.56 and 12.5 - 1.9 k = 9.397, above its bottom; the triangle's
  // base is below the rectangle. So the intersection is the hexagon:
  const double k = 12.25 / 7.5;
  const std::vector<Vec2> by_hand = {{0.5 + 10.8 / k, 1.7}, {15.5 - 10.8 / k, 1.7}, {13.6, 12.5 - 1.9 * k},
                                     {13.6, 11.2},          {2.3, 11.2},            {2.3, 12.5 - 1.8 * k}};
  for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    render::Scene clipped(16, 14, kClear), plain(16, 14, kClear);
    clipped.set_clip(polygon_path({{{0.5, 12.5}, {15.5, 12.5}, {8, 0.25}}}), rule);
    clipped.fill_polygon({{{2.3, 1.7}, {13.6, 1.7}, {13.6, 11.2}, {2.3, 11.2}}}, rule, kInk);
    plain.fill_polygon({by_hand}, FillRule::NonZero, kInk);
    CHECK(max_alpha_difference(render::rasterize(clipped, 1), render::rasterize(plain, 1)) < 1e-6);
  }
}

TEST_CASE("an even-odd clip of two nested squares leaves the ring between them", "[renderer][clip]") {
  render::Scene s(20, 20, kClear);
  s.set_clip(polygon_path({{{2.5, 2.5}, {17.5, 2.5}, {17.5, 17.5}, {2.5, 17.5}}, {{6.25, 6.25}, {13.75, 6.25}, {13.75, 13.75}, {6.25, 13.75}}}),
             FillRule::EvenOdd);
  s.fill_polygon({{{0, 0}, {20, 0}, {20, 20}, {0, 20}}}, FillRule::NonZero, kInk);
  s.clear_clip();
  s.fill_circle({19, 19}, 0.5, kInk);  // recorded after clear_clip: not clipped
  const Image img = render::rasterize(s, 1);
  // Per pixel, by hand: the ring's area in the pixel (outer edges at 2.5 and 17.5, inner at 6.25
  // and 13.75).
  auto cover = [](int i, double lo, double hi) { return std::clamp(std::min(i + 1.0, hi) - std::max(double(i), lo), 0.0, 1.0); };
  double worst = 0;
  for (int y = 0; y < 18; ++y)
    for (int x = 0; x < 18; ++x) {
      const double ring = cover(x, 2.5, 17.5) * cover(y, 2.5, 17.5) - cover(x, 6.25, 13.75) * cover(y, 6.25, 13.75);
      worst = std::max(worst, std::abs(alpha(img, x, y) - ring));
    }
  CHECK(worst < 1e-6);
  CHECK(alpha(img, 19, 19) > 0.1);
}

TEST_CASE("a clipped self-crossing stroke equals the unclipped one where the clip covers a pixel whole, and is empty where it misses it",
          "[renderer][clip]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(2, 62);
  std::vector<Vec2> walk;
  for (int i = 0; i < 60; ++i) walk.push_back({u(rng), u(rng)});
  render::StrokeStyle style;
  style.width = 2.5;
  const double x0 = 10.4, y0 = 8.6, x1 = 50.3, y1 = 41.8;
  for (int threads : {1, 3}) {
    render::Scene clipped(64, 64, kClear), plain(64, 64, kClear);
    clipped.set_clip(polygon_path({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}));
    clipped.stroke_polyline(walk, false, style, kInk);
    plain.stroke_polyline(walk, false, style, kInk);
    const Image c = render::rasterize(clipped, threads), p = render::rasterize(plain, threads);
    double inside = 0, outside = 0, edge = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const double a = alpha(c, x, y), b = alpha(p, x, y);
        if (x >= 11 && x + 1 <= 50 && y >= 9 && y + 1 <= 41) inside = std::max(inside, std::abs(a - b));
        else if (x + 1 <= 10 || x >= 51 || y + 1 <= 8 || y >= 42) outside = std::max(outside, a);
        else edge = std::max(edge, a - b);  // never more than the unclipped coverage
      }
    CHECK(inside == 0);
    CHECK(outside == 0);
    CHECK(edge <= 1e-6);
  }
}

TEST_CASE("clip paths: images refuse them, and the scene says it has clipped items", "[renderer][clip]") {
  // The triangle (1, 1), (7, 1), (7, 7): the pixels below its diagonal (y > x) are outside.
  render::Scene s(8, 8, kClear);
  s.fill_circle({4, 4}, 1, kInk);  // before the clip: not clipped
  CHECK_FALSE(s.clipped());
  s.set_clip(polygon_path({{{1, 1}, {7, 1}, {7, 7}}}));
  auto img = std::make_shared<Image>(1, 1, 4);
  CHECK_THROWS_AS(s.image(img, {0, 0}, {8, 8}, render::Scene::Sampling::Nearest), std::invalid_argument);
  CHECK_FALSE(s.clipped());  // nothing recorded under the clip yet
  s.fill_circle({4, 4}, 3, kInk);
  s.clear_clip();
  s.fill_circle({1.5, 6.5}, 0.5, kInk);  // after clear_clip: not clipped
  CHECK(s.clipped());
  CHECK(s.items().size() == 3);
  const Image out = render::rasterize(s, 1);
  CHECK(alpha(out, 3, 4) > 0.5);   // the first disk, outside the triangle
  CHECK(alpha(out, 2, 5) == 0);    // the clipped disk only, outside the triangle
  CHECK(alpha(out, 5, 2) > 0.99);  // the clipped disk, inside the triangle
  CHECK(alpha(out, 1, 6) > 0.5);   // the last disk, outside the triangle
}
