// Occupancy grid for label placement, and clipping of polylines and polygons to a box.
#include "draw.hpp"

#include <algorithm>
#include <cmath>

namespace splinefig::figures::detail {

Occupancy::Occupancy(int width, int height)
    : w_(std::max(1, width)),
      h_(std::max(1, height)),
      covered_(static_cast<size_t>(w_) * h_, 0),
      starts_(static_cast<size_t>(w_ + 1) * h_, 0) {}

void Occupancy::span(int y, int x0, int x1) {
  // A cell's running sum counts the spans over it: at most the spans marked, which are resolved
  // before they could reach 2^31.
  if (pending_ >= (std::uint64_t(1) << 30)) resolve();
  std::int32_t* row = &starts_[static_cast<size_t>(y) * (w_ + 1)];
  ++row[x0];
  --row[x1 + 1];
  ++pending_;
  pending_y0_ = std::min(pending_y0_, y);
  pending_y1_ = std::max(pending_y1_, y);
}

void Occupancy::resolve() {
  if (pending_ == 0) return;
  // Only the rows that hold spans: a label's rectangle marked between two reads costs its rows.
  for (int y = pending_y0_; y <= pending_y1_; ++y) {
    std::int32_t* row = &starts_[static_cast<size_t>(y) * (w_ + 1)];
    std::uint8_t* cov = &covered_[static_cast<size_t>(y) * w_];
    std::int32_t over = 0;
    for (int x = 0; x < w_; ++x) {
      over += row[x];
      row[x] = 0;
      cov[x] |= over > 0;
    }
    row[w_] = 0;
  }
  pending_ = 0;
  pending_y0_ = h_;
  pending_y1_ = -1;
}

void Occupancy::mark_point(Vec2 p, double radius) {
  if (!(std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6 && radius < 1e4)) return;  // far off the canvas
  int x0 = std::max(0, static_cast<int>(std::floor(p.x - radius)));
  int x1 = std::min(w_ - 1, static_cast<int>(std::floor(p.x + radius)));
  int y0 = std::max(0, static_cast<int>(std::floor(p.y - radius)));
  int y1 = std::min(h_ - 1, static_cast<int>(std::floor(p.y + radius)));
  if (x0 > x1) return;
  for (int y = y0; y <= y1; ++y) span(y, x0, x1);
}

void Occupancy::mark_polyline(const std::vector<Vec2>& pts, double radius) {
  // The marks of a segment (a square every 1.5 px at most) have x ranges that overlap or touch
  // one another (they are at least 2 radius - 1 >= 1 cells wide and their centres at most 1.5
  // apart), so in each row the marks covering it, a run of consecutive marks, cover one span:
  // from the least of its ends' left edges to the greatest of their right edges. Each row of a
  // segment is then one span whatever its number of marks, the same cells as marking each.
  std::vector<int> mx0, mx1, my0, my1;
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    Vec2 a = pts[i], b = pts[i + 1];
    double len = std::hypot(b.x - a.x, b.y - a.y);
    if (!std::isfinite(len) || len > 1e5) continue;
    int n = std::max(1, static_cast<int>(std::ceil(len / 1.5)));
    const bool near = std::abs(a.x) < 1e6 && std::abs(a.y) < 1e6 && std::abs(b.x) < 1e6 && std::abs(b.y) < 1e6;
    if (!(radius >= 1) || !near) {  // marks one by one (each checks how far off it is)
      for (int k = 0; k < n; ++k) mark_point({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n}, radius);
      continue;
    }
    if (!(radius < 1e4)) continue;  // as mark_point: too large to mean anything
    // Each mark's square, unclipped (as mark_point computes it before clamping), in the order
    // of increasing y.
    mx0.resize(static_cast<size_t>(n));
    mx1.resize(static_cast<size_t>(n));
    my0.resize(static_cast<size_t>(n));
    my1.resize(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
      const Vec2 p{a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n};
      const size_t j = static_cast<size_t>(b.y >= a.y ? k : n - 1 - k);
      mx0[j] = static_cast<int>(std::floor(p.x - radius));
      mx1[j] = static_cast<int>(std::floor(p.x + radius));
      my0[j] = static_cast<int>(std::floor(p.y - radius));
      my1[j] = static_cast<int>(std::floor(p.y + radius));
    }
    // my0 and my1 do not decrease with j: the marks over row y are those from the first whose
    // my1 reaches y to the last whose my0 does not pass it.
    size_t lo = 0, hi = 0;
    const int ya = std::max(0, my0.front()), yb = std::min(h_ - 1, my1.back());
    for (int y = ya; y <= yb; ++y) {
      while (lo < mx0.size() && my1[lo] < y) ++lo;
      while (hi + 1 < mx0.size() && my0[hi + 1] <= y) ++hi;
      if (lo > hi || lo >= mx0.size()) continue;
      const int x0 = std::max(0, std::min(mx0[lo], mx0[hi])), x1 = std::min(w_ - 1, std::max(mx1[lo], mx1[hi]));
      if (x0 <= x1) span(y, x0, x1);
    }
  }
  if (!pts.empty()) mark_point(pts.back(), radius);
}

void Occupancy::mark_rect(const Rect& r) {
  int x0 = static_cast<int>(std::clamp(std::floor(r.left), 0.0, w_ - 1.0));
  int x1 = static_cast<int>(std::clamp(std::ceil(r.right), -1.0, w_ - 1.0));
  int y0 = static_cast<int>(std::clamp(std::floor(r.top), 0.0, h_ - 1.0));
  int y1 = static_cast<int>(std::clamp(std::ceil(r.bottom), -1.0, h_ - 1.0));
  if (x0 > x1) return;
  for (int y = y0; y <= y1; ++y) span(y, x0, x1);
}

long Occupancy::count(const Rect& r) {
  resolve();
  // Cells off the canvas count 4 each (worse than data); the rest count if marked.
  const double area = std::max(0.0, std::ceil(r.right) - std::floor(r.left) + 1) *
                      std::max(0.0, std::ceil(r.bottom) - std::floor(r.top) + 1);
  if (!(area < 1e9)) return 1L << 40;
  int x0 = static_cast<int>(std::clamp(std::floor(r.left), 0.0, w_ - 1.0));
  int x1 = static_cast<int>(std::clamp(std::ceil(r.right), -1.0, w_ - 1.0));
  int y0 = static_cast<int>(std::clamp(std::floor(r.top), 0.0, h_ - 1.0));
  int y1 = static_cast<int>(std::clamp(std::ceil(r.bottom), -1.0, h_ - 1.0));
  long on = 0, n = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      ++on;
      n += covered_[static_cast<size_t>(y) * w_ + x];
    }
  return n + 4 * (static_cast<long>(area) - on);
}

std::vector<std::vector<Vec2>> clip_polyline(const std::vector<Vec2>& pts, bool closed, const Rect& r) {
  bool inside = std::all_of(pts.begin(), pts.end(), [&](Vec2 p) { return r.contains(p); });
  if (inside) return {pts};
  std::vector<Vec2> path = pts;
  if (closed && !pts.empty()) path.push_back(pts.front());
  std::vector<std::vector<Vec2>> runs;
  std::vector<Vec2> run;
  auto flush = [&] {
    if (run.size() >= 2) runs.push_back(run);
    run.clear();
  };
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    // Liang-Barsky on segment a + t (b - a), t in [0, 1].
    Vec2 a = path[i], b = path[i + 1];
    double dx = b.x - a.x, dy = b.y - a.y, t0 = 0, t1 = 1;
    bool visible = true;
    auto edge = [&](double p, double q) {
      if (p == 0) {
        if (q < 0) visible = false;
        return;
      }
      double t = q / p;
      if (p < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
    };
    edge(-dx, a.x - r.left);
    edge(dx, r.right - a.x);
    edge(-dy, a.y - r.top);
    edge(dy, r.bottom - a.y);
    if (!visible || t0 > t1) {
      flush();
      continue;
    }
    Vec2 ca{a.x + t0 * dx, a.y + t0 * dy}, cb{a.x + t1 * dx, a.y + t1 * dy};
    if (t0 > 0) flush();
    if (run.empty()) run.push_back(ca);
    run.push_back(cb);
    if (t1 < 1) flush();
  }
  flush();
  return runs;
}

std::vector<Vec2> clip_polygon(const std::vector<Vec2>& pts, const Rect& r) {
  // Sutherland-Hodgman against the four half-planes.
  std::vector<Vec2> poly = pts;
  auto clip = [&](auto inside, auto cross) {
    std::vector<Vec2> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      bool ia = inside(a), ib = inside(b);
      if (ia) out.push_back(a);
      if (ia != ib) out.push_back(cross(a, b));
    }
    poly = std::move(out);
  };
  auto at_x = [](Vec2 a, Vec2 b, double x) { double t = (x - a.x) / (b.x - a.x); return Vec2{x, a.y + t * (b.y - a.y)}; };
  auto at_y = [](Vec2 a, Vec2 b, double y) { double t = (y - a.y) / (b.y - a.y); return Vec2{a.x + t * (b.x - a.x), y}; };
  clip([&](Vec2 p) { return p.x >= r.left; }, [&](Vec2 a, Vec2 b) { return at_x(a, b, r.left); });
  clip([&](Vec2 p) { return p.x <= r.right; }, [&](Vec2 a, Vec2 b) { return at_x(a, b, r.right); });
  clip([&](Vec2 p) { return p.y >= r.top; }, [&](Vec2 a, Vec2 b) { return at_y(a, b, r.top); });
  clip([&](Vec2 p) { return p.y <= r.bottom; }, [&](Vec2 a, Vec2 b) { return at_y(a, b, r.bottom); });
  return poly;
}

}  // namespace splinefig::figures::detail
