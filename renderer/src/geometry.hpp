#pragma once
// Shared internal geometry: boxes, vector arithmetic, and the arc polygonization that round
// joins, round caps, circles and disks use.
//
// Arcs become polygons whose vertices lie on the circle. A chord of angle a deviates from the
// arc by the sagitta r (1 - cos(a/2)); we keep it below kArcTolerance (1e-4 px), so the area
// error in any pixel is below 1.5e-4 (the arc's length inside a pixel is at most ~1.5 px),
// far below 1/255. Far from the canvas the step grows with the distance to it, so a circle of
// radius 1e12 costs a few hundred vertices, not billions, and no chord can cut the canvas.
#include <splinefig/renderer/renderer.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace splinefig::render::detail {

inline constexpr double kArcTolerance = 1e-4;

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double length(Vec2 a) { return std::hypot(a.x, a.y); }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double distance(Vec2 p) const {
    double dx = std::max({x0 - p.x, 0.0, p.x - x1});
    double dy = std::max({y0 - p.y, 0.0, p.y - y1});
    return std::hypot(dx, dy);
  }
};

// The largest chord angle whose sagitta on a circle of radius r stays below kArcTolerance.
inline double fine_arc_step(double r) {
  if (r <= kArcTolerance) return std::numbers::pi / 2;
  double s = 2.0 * std::acos(1.0 - kArcTolerance / r);
  return std::clamp(s, 1e-9, std::numbers::pi / 2);
}

// Calls emit(point) for the interior vertices of the arc of centre c and radius r from angle
// a0 through the signed angle `sweep` (the end points themselves are the caller's). `near` is
// the region where accuracy matters (the canvas plus a margin).
template <class Emit>
void arc_interior(Vec2 c, double r, double a0, double sweep, const Box& near, Emit&& emit) {
  if (!(r > 0) || sweep == 0) return;
  const double total = std::abs(sweep), sgn = sweep > 0 ? 1.0 : -1.0;
  const double fine = fine_arc_step(r);
  if (total <= fine) return;
  // Uniform fine steps when the whole arc's disk is near the canvas (the common case).
  if (near.distance(c) <= r + 1.0 && r < 1e6) {
    const int n = static_cast<int>(std::ceil(total / fine));
    const double step = sweep / n;
    for (int k = 1; k < n; ++k) {
      double a = a0 + step * k;
      emit(Vec2{c.x + r * std::cos(a), c.y + r * std::sin(a)});
    }
    return;
  }
  double t = 0;
  for (;;) {
    double a = a0 + sgn * t;
    Vec2 p{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    double step = std::max(fine, 0.5 * near.distance(p) / r);
    t += step;
    if (t >= total - 1e-12 * total) return;
    double an = a0 + sgn * t;
    emit(Vec2{c.x + r * std::cos(an), c.y + r * std::sin(an)});
  }
}

// An upper bound on the vertices arc_interior(c, r, a0, sweep, near, ...) emits, computed
// without emitting them. Every step is at least `fine`, so ceil(|sweep| / fine) always holds;
// near the canvas that is the count. Otherwise (a disk far from `near`, or r >= 1e6) a step
// from a point at distance d from `near` is at least 0.5 d / r of angle: nearer than
// delta = 2 r fine the step is `fine`, and the arc within distance D of the box (a convex set)
// is at most its perimeter long, perim + 2 pi D; counting the steps from each band of
// distance [2^k delta, 2^(k+1) delta) gives the second bound, a few thousand steps for any
// radius.
inline double arc_vertex_bound(Vec2 c, double r, double sweep, const Box& near) {
  if (!(r > 0) || sweep == 0) return 0;
  const double total = std::abs(sweep), fine = fine_arc_step(r);
  if (total <= fine) return 0;
  const double uniform = std::ceil(total / fine);
  const double dc = near.distance(c);
  if (dc <= r + 1.0 && r < 1e6) return uniform;
  double bound = uniform;
  if (dc > r) bound = std::min(bound, total / std::max(fine, 0.5 * (dc - r) / r) + 2);
  const double delta = 2 * r * fine;
  const double perim = 2 * ((near.x1 - near.x0) + (near.y1 - near.y0));
  const double levels = std::ceil(std::log2(std::max(2.0, (dc + r + 1) / delta))) + 1;
  return std::min(bound, (perim + 4 * std::numbers::pi * delta) / (r * fine) + 4 * perim / delta +
                             (8 * std::numbers::pi + 2) * levels + 2);
}

}  // namespace splinefig::render::detail
