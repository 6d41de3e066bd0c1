#include <splinefig/renderer/path.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace splinefig::render {

void Path::move_to(Vec2 p) {
  verbs_.push_back(Verb::Move);
  points_.push_back(p);
  current_ = start_ = p;
  open_ = true;
}

void Path::line_to(Vec2 p) {
  if (!open_) move_to(current_);
  verbs_.push_back(Verb::Line);
  points_.push_back(p);
  current_ = p;
}

void Path::quad_to(Vec2 c, Vec2 p) {
  const Vec2 p0 = current_;
  cubic_to({(p0.x + 2 * c.x) / 3, (p0.y + 2 * c.y) / 3}, {(p.x + 2 * c.x) / 3, (p.y + 2 * c.y) / 3}, p);
}

void Path::cubic_to(Vec2 c1, Vec2 c2, Vec2 p) {
  if (!open_) move_to(current_);
  verbs_.push_back(Verb::Cubic);
  points_.push_back(c1);
  points_.push_back(c2);
  points_.push_back(p);
  current_ = p;
}

void Path::close() {
  if (!open_) return;
  verbs_.push_back(Verb::Close);
  current_ = start_;
  open_ = false;
}

namespace {
// Subdivisions of a cubic so that each chord is within `tol` of the curve: the deviation of a
// cubic from its chord is bounded by (3/4) max |second difference| of the control polygon
// divided by n^2 for n uniform pieces (the standard bound for the Bernstein form).
int cubic_pieces(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double tol) {
  const double ax = p0.x - 2 * p1.x + p2.x, ay = p0.y - 2 * p1.y + p2.y;
  const double bx = p1.x - 2 * p2.x + p3.x, by = p1.y - 2 * p2.y + p3.y;
  const double m = std::max(std::hypot(ax, ay), std::hypot(bx, by));
  const double n = std::ceil(std::sqrt(0.75 * m / tol));
  if (!(n >= 1)) return 1;
  return static_cast<int>(std::min(n, 1e6));
}
}  // namespace

std::size_t Path::flattened_size(double tolerance) const {
  if (!(tolerance > 0)) throw DrawError("Path::flattened_size: tolerance must be positive");
  std::size_t n = 0, k = 0;
  Vec2 cur{};
  for (Verb v : verbs_) {
    switch (v) {
      case Verb::Move:
      case Verb::Line:
        cur = points_[k++];
        ++n;
        break;
      case Verb::Cubic:
        n += static_cast<std::size_t>(cubic_pieces(cur, points_[k], points_[k + 1], points_[k + 2], tolerance));
        cur = points_[k + 2];
        k += 3;
        break;
      case Verb::Close: break;
    }
  }
  return n;
}

Path::Flat Path::flatten(double tolerance) const {
  if (!(tolerance > 0)) throw DrawError("Path::flatten: tolerance must be positive");
  Flat out;
  std::size_t k = 0;
  Vec2 cur{};
  auto finish = [&](bool closed) {
    if (!out.contours.empty() && out.closed.size() < out.contours.size()) out.closed.push_back(closed);
  };
  for (Verb v : verbs_) {
    switch (v) {
      case Verb::Move:
        finish(false);
        cur = points_[k++];
        out.contours.push_back({cur});
        break;
      case Verb::Line:
        cur = points_[k++];
        out.contours.back().push_back(cur);
        break;
      case Verb::Cubic: {
        const Vec2 p0 = cur, p1 = points_[k], p2 = points_[k + 1], p3 = points_[k + 2];
        k += 3;
        const int n = cubic_pieces(p0, p1, p2, p3, tolerance);
        auto& c = out.contours.back();
        for (int i = 1; i <= n; ++i) {
          const double t = static_cast<double>(i) / n, s = 1 - t;
          const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
          c.push_back(i == n ? p3
                             : Vec2{b0 * p0.x + b1 * p1.x + b2 * p2.x + b3 * p3.x,
                                    b0 * p0.y + b1 * p1.y + b2 * p2.y + b3 * p3.y});
        }
        cur = p3;
        break;
      }
      case Verb::Close: {
        auto& c = out.contours.back();
        if (c.size() > 1 && c.back().x == c.front().x && c.back().y == c.front().y) c.pop_back();
        finish(true);
        break;
      }
    }
  }
  finish(false);
  return out;
}

Path Path::transformed(double a, double b, double c, double d, double e, double f) const {
  Path out = *this;
  for (Vec2& p : out.points_) p = Vec2{a * p.x + c * p.y + e, b * p.x + d * p.y + f};
  const Vec2 cu = current_, st = start_;
  out.current_ = {a * cu.x + c * cu.y + e, b * cu.x + d * cu.y + f};
  out.start_ = {a * st.x + c * st.y + e, b * st.x + d * st.y + f};
  return out;
}

}  // namespace splinefig::render
