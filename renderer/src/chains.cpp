#include "chains.hpp"

#include <algorithm>

namespace splinefig::render::detail {

void ChainBuilder::move_to(Vec2 p) {
  if (open_contour_) close();
  p = Vec2{p.x - shift_.x, p.y - shift_.y};
  start_ = cur_ = p;
  open_contour_ = true;
}

void ChainBuilder::close() {
  if (!open_contour_) return;
  if (!(cur_ == start_)) segment_to(start_);
  end_chain();
  open_contour_ = false;
}

void ChainBuilder::leave_open() {
  end_chain();
  open_contour_ = false;
}

void ChainBuilder::line_to_slow(Vec2 b) {
  if (!open_contour_) {
    start_ = cur_;
    open_contour_ = true;
  }
  segment_to(b);
}

void ChainBuilder::segment_to(Vec2 b) {
  Vec2 a = cur_;
  cur_ = b;
  if (a == b) return;
  const double x0 = clip_.x0, x1 = clip_.x1;
  if (a.x >= x0 && a.x <= x1 && b.x >= x0 && b.x <= x1 && a.y >= clip_.y0 && a.y <= clip_.y1 &&
      b.y >= clip_.y0 && b.y <= clip_.y1) {
    edge(a, b);  // entirely inside: the common case
    return;
  }
  // Split at the box's sides, then project x onto [x0, x1].
  double ts[4];
  int nt = 0;
  ts[nt++] = 0;
  if ((a.x < x0) != (b.x < x0)) ts[nt++] = (x0 - a.x) / (b.x - a.x);
  if ((a.x > x1) != (b.x > x1)) ts[nt++] = (x1 - a.x) / (b.x - a.x);
  if (nt == 3 && ts[1] > ts[2]) std::swap(ts[1], ts[2]);
  ts[nt++] = 1;
  Vec2 prev = a;
  for (int k = 1; k < nt; ++k) {
    Vec2 q = k == nt - 1 ? b : Vec2{a.x + ts[k] * (b.x - a.x), a.y + ts[k] * (b.y - a.y)};
    if (k < nt - 1) {
      // Put the split point exactly on the side it crosses.
      q.x = std::abs(q.x - x0) < std::abs(q.x - x1) ? x0 : x1;
    }
    Vec2 pa{std::clamp(prev.x, x0, x1), prev.y}, pb{std::clamp(q.x, x0, x1), q.y};
    clip_y(pa, pb);
    prev = q;
  }
}

void ChainBuilder::clip_y(Vec2 a, Vec2 b) {
  const double y0 = clip_.y0, y1 = clip_.y1;
  if (a.y == b.y) { end_chain(); return; }
  if (std::max(a.y, b.y) <= y0 || std::min(a.y, b.y) >= y1) { end_chain(); return; }
  auto at = [&](double y) {
    double t = (y - a.y) / (b.y - a.y);
    return Vec2{a.x + t * (b.x - a.x), y};
  };
  Vec2 p = a, q = b;
  if (p.y < y0) p = at(y0); else if (p.y > y1) p = at(y1);
  if (q.y < y0) q = at(y0); else if (q.y > y1) q = at(y1);
  edge(p, q);
}

void ChainBuilder::edge(Vec2 a, Vec2 b) {
  if (a.y == b.y) { end_chain(); return; }
  int dir = b.y > a.y ? 1 : -1;
  if (in_chain_ && dir == chain_dir_ && g_.verts.back() == a) {
    g_.verts.push_back(b);
    return;
  }
  end_chain();
  in_chain_ = true;
  chain_dir_ = dir;
  chain_first_ = g_.verts.size();
  g_.verts.push_back(a);
  g_.verts.push_back(b);
}

void ChainBuilder::end_chain() {
  if (!in_chain_) return;
  in_chain_ = false;
  Chain c;
  c.first = chain_first_;
  c.last = g_.verts.size() - 1;
  c.dir = chain_dir_;
  auto* v = g_.verts.data();
  if (c.dir < 0) std::reverse(v + c.first, v + c.last + 1);
  c.ymin = v[c.first].y;
  c.ymax = v[c.last].y;
  c.xmin = c.xmax = v[c.first].x;
  for (std::size_t k = c.first + 1; k <= c.last; ++k) {
    c.xmin = std::min(c.xmin, v[k].x);
    c.xmax = std::max(c.xmax, v[k].x);
    c.xdy += 0.5 * (v[k - 1].x + v[k].x) * (v[k].y - v[k - 1].y);
  }
  if (g_.chains.size() == g_.chains.capacity()) reserve_huge(g_.chains, std::max<std::size_t>(64, 2 * g_.chains.capacity()));
  g_.chains.push_back(c);
}

}  // namespace splinefig::render::detail
