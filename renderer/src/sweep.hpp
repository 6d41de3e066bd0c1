#pragma once
// Exact scan conversion with fill-rule (union) semantics, one horizontal strip at a time.
//
// Within a strip [y0, y1] the chains are cut at every event: a chain starting or ending, or two
// chains crossing (found exactly: between consecutive vertex heights of two chains the gap
// x_a(y) - x_b(y) is linear, so a sign change locates the crossing). Between two consecutive
// events no two chains cross, so they keep one left-to-right order; walking it while summing
// dir gives the winding number of every gap, and a chain is a boundary of the filled region
// exactly where the fill rule's verdict changes across it. Only those boundary pieces go to the
// sink, signed +1 where the region begins (to their right) and -1 where it ends. An exact-area
// accumulator fed with them yields the area of {rule(winding)}, not the integral of the winding
// number, so overlapping parts of one shape count once.
//
// Sink concept: void edge(double xa, double ya, double xb, double yb, double sign), ya < yb.
#include "chains.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace splinefig::render::detail {

struct Shape {
  std::size_t chain_begin = 0, chain_end = 0;  // in Geometry::chains, sorted by ymin
  FillRule rule = FillRule::NonZero;
  bool simple = false;  // |winding| <= 1 everywhere (a convex or simple contour): no sweep needed
  int orient = 1;       // for simple shapes: the winding number inside (+1 or -1)
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  bool empty() const { return chain_begin == chain_end; }
};

class StripSweep {
 public:
  // Starts a shape; buffers are kept across shapes.
  void reset(const Geometry& g, const Shape& s) {
    g_ = &g;
    s_ = &s;
    next_ = s.chain_begin;
    active_.clear();
    cursor_.clear();
  }

  // Strips must come in increasing y order. Returns false once nothing is left below.
  template <class Sink>
  bool strip(double y0, double y1, Sink& sink);

 private:
  struct Span {
    std::size_t chain, k, cur;  // chain; first edge meeting the strip; cursor for x_on
    double ta, tb, xmin, xmax;
    int dir;
    int sign;       // boundary status in the current sub-strip: +1 begins, -1 ends, 0 none
    bool listed;    // in order_
    double open_y;  // where the current boundary status began
  };
  double x_at(std::size_t k, double y) const {
    const Vec2 a = g_->verts[k], b = g_->verts[k + 1];
    if (y <= a.y) return a.x;
    if (y >= b.y) return b.x;
    return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
  }
  // x of the span's chain at height y within [ta, tb]; k is a cursor moved forward.
  double x_on(const Span& s, std::size_t& k, double y) const {
    const std::size_t last = g_->chains[s.chain].last;
    while (k + 1 < last && g_->verts[k + 1].y < y) ++k;
    return x_at(k, y);
  }
  void crossings(const Span& a, const Span& b);
  template <class Sink>
  void emit(const Span& s, double ya, double yb, double sign, Sink& sink) const;
  bool inside(int w) const { return s_->rule == FillRule::EvenOdd ? (w & 1) != 0 : w != 0; }

  const Geometry* g_ = nullptr;
  const Shape* s_ = nullptr;
  std::size_t next_ = 0;
  std::vector<std::size_t> active_;  // chain indices
  std::vector<std::size_t> cursor_;  // per active chain: first edge not entirely above
  std::vector<Span> spans_;
  std::vector<double> events_;
  std::vector<std::uint32_t> order_;
  std::vector<std::pair<double, std::uint32_t>> keyed_;
};

template <class Sink>
void StripSweep::emit(const Span& s, double ya, double yb, double sign, Sink& sink) const {
  const auto& v = g_->verts;
  const std::size_t last = g_->chains[s.chain].last;
  std::size_t k = s.k;
  while (k + 1 < last && v[k + 1].y <= ya) ++k;
  for (; k < last && v[k].y < yb; ++k) {
    double lo = std::max(ya, v[k].y), hi = std::min(yb, v[k + 1].y);
    if (hi <= lo) continue;
    sink.edge(x_at(k, lo), lo, x_at(k, hi), hi, sign);
  }
}

template <class Sink>
bool StripSweep::strip(double y0, double y1, Sink& sink) {
  const auto& ch = g_->chains;
  const auto& v = g_->verts;
  // Active set: drop finished chains, add those starting before the strip's bottom.
  std::size_t n = 0;
  for (std::size_t i = 0; i < active_.size(); ++i) {
    if (ch[active_[i]].ymax > y0) {
      active_[n] = active_[i];
      cursor_[n] = cursor_[i];
      ++n;
    }
  }
  active_.resize(n);
  cursor_.resize(n);
  while (next_ < s_->chain_end && ch[next_].ymin < y1) {
    const Chain& c = ch[next_];
    if (c.ymax > y0) {
      // first edge whose lower end is below y0 (binary search: bands may start mid-chain)
      std::size_t lo = c.first, hi = c.last - 1;
      while (lo < hi) {
        std::size_t mid = (lo + hi) / 2;
        if (v[mid + 1].y <= y0) lo = mid + 1; else hi = mid;
      }
      active_.push_back(next_);
      cursor_.push_back(lo);
    }
    ++next_;
  }
  if (active_.empty()) return next_ < s_->chain_end;

  if (s_->simple) {
    // |winding| <= 1: every chain is a boundary, its sign is dir times the inside winding.
    for (std::size_t i = 0; i < active_.size(); ++i) {
      const Chain& c = ch[active_[i]];
      std::size_t& k = cursor_[i];
      while (k + 1 < c.last && v[k + 1].y <= y0) ++k;
      const double ta = std::max(c.ymin, y0), tb = std::min(c.ymax, y1);
      const double sign = c.dir * s_->orient;
      for (std::size_t j = k; j < c.last && v[j].y < tb; ++j) {
        const double lo = std::max(ta, v[j].y), hi = std::min(tb, v[j + 1].y);
        if (hi > lo) sink.edge(x_at(j, lo), lo, x_at(j, hi), hi, sign);
      }
    }
    return true;
  }

  spans_.clear();
  for (std::size_t i = 0; i < active_.size(); ++i) {
    const Chain& c = ch[active_[i]];
    std::size_t& k = cursor_[i];
    while (k + 1 < c.last && v[k + 1].y <= y0) ++k;
    Span s;
    s.chain = active_[i];
    s.k = s.cur = k;
    s.dir = c.dir;
    s.sign = 0;
    s.listed = false;
    s.open_y = y0;
    s.ta = std::max(c.ymin, y0);
    s.tb = std::min(c.ymax, y1);
    if (s.tb <= s.ta) continue;
    double xa = x_at(k, s.ta);
    s.xmin = s.xmax = xa;
    std::size_t j = k;
    for (; j < c.last && v[j + 1].y < s.tb; ++j) {
      s.xmin = std::min(s.xmin, v[j + 1].x);
      s.xmax = std::max(s.xmax, v[j + 1].x);
    }
    double xb = x_at(std::min(j, c.last - 1), s.tb);
    s.xmin = std::min(s.xmin, xb);
    s.xmax = std::max(s.xmax, xb);
    spans_.push_back(s);
  }
  if (spans_.empty()) return true;

  events_.clear();
  events_.push_back(y0);
  events_.push_back(y1);
  for (const Span& s : spans_) {
    if (s.ta > y0) events_.push_back(s.ta);
    if (s.tb < y1) events_.push_back(s.tb);
  }
  // Crossings between spans whose x ranges overlap (sweep over xmin).
  if (spans_.size() > 1) {
    order_.resize(spans_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
      return spans_[a].xmin < spans_[b].xmin || (spans_[a].xmin == spans_[b].xmin && a < b);
    });
    for (std::size_t i = 0; i < order_.size(); ++i) {
      const Span& a = spans_[order_[i]];
      for (std::size_t j = i + 1; j < order_.size() && spans_[order_[j]].xmin < a.xmax; ++j)
        crossings(a, spans_[order_[j]]);
    }
  }
  if (events_.size() > 2) {
    std::sort(events_.begin(), events_.end());
    events_.erase(std::unique(events_.begin(), events_.end()), events_.end());
  }

  // Sub-strips between events. A span's boundary status is emitted only when it changes, so
  // a boundary running through several sub-strips reaches the sink as one piece.
  order_.clear();
  for (std::size_t e = 0; e + 1 < events_.size(); ++e) {
    const double ya = events_[e], yb = events_[e + 1];
    if (!(yb > ya)) continue;
    const double ym = 0.5 * (ya + yb);
    keyed_.clear();
    for (std::uint32_t i : order_) {  // keep the previous order: nearly sorted already
      Span& s = spans_[i];
      if (s.tb >= yb) keyed_.push_back({x_on(s, s.cur, ym), i});
      else {
        s.listed = false;
        if (s.sign != 0) emit(s, s.open_y, ya, s.sign, sink);
        s.sign = 0;
      }
    }
    for (std::uint32_t i = 0; i < spans_.size(); ++i) {
      Span& s = spans_[i];
      if (!s.listed && s.ta <= ya && s.tb >= yb) {
        s.listed = true;
        keyed_.push_back({x_on(s, s.cur, ym), i});
      }
    }
    // insertion sort by (x, index): linear when the order barely changed
    for (std::size_t a = 1; a < keyed_.size(); ++a) {
      auto key = keyed_[a];
      std::size_t b = a;
      while (b > 0 && key < keyed_[b - 1]) {
        keyed_[b] = keyed_[b - 1];
        --b;
      }
      keyed_[b] = key;
    }
    order_.clear();
    int w = 0;
    for (auto [x, i] : keyed_) {
      order_.push_back(i);
      Span& s = spans_[i];
      const bool before = inside(w);
      w += s.dir;
      const bool after = inside(w);
      const int sign = before == after ? 0 : (after ? 1 : -1);
      if (sign != s.sign) {
        if (s.sign != 0) emit(s, s.open_y, ya, s.sign, sink);
        s.sign = sign;
        s.open_y = ya;
      }
    }
  }
  for (std::uint32_t i : order_) {
    Span& s = spans_[i];
    if (s.sign != 0) emit(s, s.open_y, std::min(s.tb, y1), s.sign, sink);
    s.sign = 0;
  }
  return true;
}

}  // namespace splinefig::render::detail
