#pragma once
// A path of lines and cubic Bezier segments (quadratics are stored as their exact cubic
// elevation), in canvas pixels. It is what glyph outlines and exact spline pieces are made of:
// the rasterizer flattens it within a chord tolerance, a vector writer keeps its segments.
#include <splinefig/renderer/renderer.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace splinefig::render {

class Path {
 public:
  enum class Verb : std::uint8_t { Move, Line, Cubic, Close };

  void move_to(Vec2 p);
  void line_to(Vec2 p);
  void quad_to(Vec2 c, Vec2 p);  // stored as the cubic (p0 + 2c)/3, (p + 2c)/3, p
  void cubic_to(Vec2 c1, Vec2 c2, Vec2 p);
  void close();

  // Verbs in order; Move and Line take one point, Cubic three, Close none.
  const std::vector<Verb>& verbs() const { return verbs_; }
  const std::vector<Vec2>& points() const { return points_; }
  bool empty() const { return verbs_.empty(); }

  // Each subpath as a polyline whose distance from the true curve is at most `tolerance`
  // pixels (a closed subpath repeats no point: its closing edge is implicit).
  // `closed[i]` says whether subpath i ended with close().
  struct Flat {
    std::vector<std::vector<Vec2>> contours;
    std::vector<bool> closed;
  };
  Flat flatten(double tolerance) const;
  // The points flatten(tolerance) would give, counted without making them.
  std::size_t flattened_size(double tolerance) const;

  // The path mapped by x' = a x + c y + e, y' = b x + d y + f (exact for Beziers).
  Path transformed(double a, double b, double c, double d, double e, double f) const;

 private:
  std::vector<Verb> verbs_;
  std::vector<Vec2> points_;
  Vec2 current_{}, start_{};
  bool open_ = false;
};

}  // namespace splinefig::render
