#include "item_reach.hpp"

#include <splinefig/renderer/path.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <variant>

namespace splinefig::render::detail {
namespace {

constexpr double kMargin = 1.0;  // pixels, far beyond the rounding of any outline vertex

template <class Points>
void extend(const Points& pts, double& lo, double& hi) {
  for (const Vec2& q : pts) {
    lo = std::min(lo, q.y);
    hi = std::max(hi, q.y);
  }
}

void extend(Vec2 q, double& lo, double& hi) {
  lo = std::min(lo, q.y);
  hi = std::max(hi, q.y);
}

// How far a stroke's pieces (stroke.hpp) reach from its points: half the width, times sqrt 2 at
// a square cap's corners and at most the miter limit at a miter join's tip (a longer miter is
// bevelled). The outline lies in the pieces' union: its inner corners lie within the pieces too.
double pen_reach(const StrokeStyle& st, bool joins) {
  double f = st.cap == Cap::Square ? std::numbers::sqrt2 : 1.0;
  if (joins && st.join == Join::Miter) f = std::max(f, st.miter_limit);
  return 0.5 * st.width * f;
}

}  // namespace

bool item_y_range(const DrawItem& item, double& y0, double& y1) {
  double lo = INFINITY, hi = -INFINITY;
  // How far the geometry reaches beyond the heights of the points gathered.
  const double reach = std::visit(
      [&](const auto& it) -> double {
        using T = std::decay_t<decltype(it)>;
        if constexpr (std::is_same_v<T, StrokeItem>) {
          extend(it.points, lo, hi);
          return pen_reach(it.style, it.closed || it.points.size() > 2);
        } else if constexpr (std::is_same_v<T, FillItem>) {
          for (const auto& c : it.contours) extend(c, lo, hi);
          return 0.0;
        } else if constexpr (std::is_same_v<T, PathFillItem>) {
          // A Bezier lies in the hull of its control points, and so do its flattened points.
          extend(it.path->points(), lo, hi);
          return 0.0;
        } else if constexpr (std::is_same_v<T, PathStrokeItem>) {
          extend(it.path->points(), lo, hi);
          return pen_reach(it.style, true);
        } else if constexpr (std::is_same_v<T, TextItem>) {
          extend(it.outline->points(), lo, hi);
          return 0.0;
        } else if constexpr (std::is_same_v<T, DiskItem>) {
          extend(it.centre, lo, hi);
          return it.radius;
        } else if constexpr (std::is_same_v<T, RingItem>) {
          extend(it.centre, lo, hi);  // its outline, or the stroke of a polygon on the circle
          return it.radius + pen_reach(it.style, true);
        } else if constexpr (std::is_same_v<T, MarkerItem>) {
          extend(it.centre, lo, hi);
          return it.size;  // every marker shape lies within s / sqrt(2) of its centre
        } else {
          extend(it.p0, lo, hi);
          extend(it.p1, lo, hi);
          return 0.0;
        }
      },
      item);
  y0 = lo - reach - kMargin;
  y1 = hi + reach + kMargin;
  return std::isfinite(y0) && std::isfinite(y1) && y0 <= y1;
}

}  // namespace splinefig::render::detail
