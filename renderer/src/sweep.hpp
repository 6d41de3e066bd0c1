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
// The strip's chains fall into clusters: runs whose x ranges in the strip overlap, taken left
// to right. No chain of one cluster can cross a chain of another, so each cluster is swept on
// its own, with its own events, starting from the winding on its left. That winding changes
// only where a chain left of it starts or ends without a partner there (a horizontal edge
// across the gap), so a cluster inherits few events, usually none: the cost of a strip grows
// with the events and chains of each cluster, not with those of the whole row.
//
// Sink concept: void edge(double xa, double ya, double xb, double yb, double sign), ya < yb.
#include "chains.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace splinefig::render::detail {

// Sorts [first, last) by `less`; insertion sort for the few elements a strip usually has.
template <class It, class Less = std::less<>>
void sort_small(It first, It last, Less less = {}) {
  if (last - first < 2) return;
  if (last - first > 16) {
    std::sort(first, last, less);
    return;
  }
  for (It i = first + 1; i != last; ++i) {
    auto key = *i;
    It j = i;
    for (; j != first && less(key, *(j - 1)); --j) *j = *(j - 1);
    *j = key;
  }
}

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
    first_end_ = INFINITY;
  }

  // Strips must come in increasing y order. Returns false once nothing is left below.
  template <class Sink>
  bool strip(double y0, double y1, Sink& sink);

 private:
  struct Span {
    std::size_t chain, k;  // chain; first edge meeting the strip
    double ta, tb, xmin, xmax;
    int dir;
  };
  // A span during its cluster's sweep: its current edge (x = ax + (y - ay) slope up to ny),
  // its x in the current sub-strip, and its boundary status.
  struct Live {
    double x, ax, ay, slope, ny, tb;
    double open_y;  // where the current boundary status began
    std::size_t k, last;
    std::uint32_t span;
    int dir;
    int sign;  // boundary status in the current sub-strip: +1 begins, -1 ends, 0 none
    void load(const std::vector<Vec2>& v, std::size_t edge) {
      k = edge;
      const Vec2 a = v[edge], b = v[edge + 1];
      ax = a.x;
      ay = a.y;
      ny = b.y;
      slope = (b.x - a.x) / (b.y - a.y);
    }
    bool operator<(const Live& o) const { return x < o.x || (x == o.x && span < o.span); }
  };
  // A change of the winding number left of a cluster: `delta` from height y on.
  struct Step {
    double y;
    int delta;
    bool operator<(const Step& o) const { return y < o.y; }
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
  bool update_active(double y0, double y1);
  template <class Sink>
  void emit_simple(double y0, double y1, Sink& sink);
  void build_spans(double y0, double y1);
  void crossings(const Span& a, const Span& b);
  void cluster_events(std::size_t c0, std::size_t c1, double y0, double y1);
  void add_steps(std::size_t c0, std::size_t c1, double y0, double y1);
  template <class Sink>
  void sweep_cluster(std::size_t c0, std::size_t c1, double y1, Sink& sink);
  template <class Sink>
  void emit(const Span& s, double ya, double yb, double sign, Sink& sink) const;
  bool inside(int w) const { return s_->rule == FillRule::EvenOdd ? (w & 1) != 0 : w != 0; }

  const Geometry* g_ = nullptr;
  const Shape* s_ = nullptr;
  std::size_t next_ = 0;
  std::vector<std::size_t> active_;  // chain indices
  std::vector<std::size_t> cursor_;  // per active chain: first edge not entirely above
  double first_end_ = INFINITY;      // the lowest ymax among the active chains
  std::vector<Span> spans_;
  std::vector<std::uint32_t> byx_;   // spans_ by xmin: clusters are runs of overlapping x ranges
  std::vector<double> events_;       // of the current cluster
  std::vector<Step> steps_;          // winding changes left of the current cluster, by y
  int base_ = 0;                     // winding left of the current cluster at the strip's top
  std::vector<std::pair<double, std::uint32_t>> pending_;  // the cluster's spans by ta
  std::vector<Live> live_;           // the current sub-strip's spans, left to right
};

// Drops finished chains, adds those starting before the strip's bottom. False if none is left.
inline bool StripSweep::update_active(double y0, double y1) {
  const auto& ch = g_->chains;
  const auto& v = g_->verts;
  if (first_end_ <= y0) {
    std::size_t n = 0;
    first_end_ = INFINITY;
    for (std::size_t i = 0; i < active_.size(); ++i) {
      const double ymax = ch[active_[i]].ymax;
      if (ymax > y0) {
        first_end_ = std::min(first_end_, ymax);
        active_[n] = active_[i];
        cursor_[n] = cursor_[i];
        ++n;
      }
    }
    active_.resize(n);
    cursor_.resize(n);
  }
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
      first_end_ = std::min(first_end_, c.ymax);
    }
    ++next_;
  }
  return !active_.empty();
}

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

// |winding| <= 1: every chain is a boundary, its sign is dir times the inside winding.
template <class Sink>
void StripSweep::emit_simple(double y0, double y1, Sink& sink) {
  const auto& ch = g_->chains;
  const auto& v = g_->verts;
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
}

// The spans byx_[c0, c1) form one cluster: no other span's x range overlaps theirs, so no
// other span crosses them and the winding left of them changes only at steps_. Between
// consecutive events no two of them cross: they keep one left-to-right order, and walking it
// from the winding on their left gives every gap's winding. A span's boundary status is
// emitted only when it changes, so a boundary running through several sub-strips reaches the
// sink as one piece.
template <class Sink>
void StripSweep::sweep_cluster(std::size_t c0, std::size_t c1, double y1, Sink& sink) {
  const auto& v = g_->verts;
  // Spans by the height where they start; each is live from its ta to its tb.
  pending_.clear();
  for (std::size_t c = c0; c < c1; ++c) pending_.push_back({spans_[byx_[c]].ta, byx_[c]});
  sort_small(pending_.begin(), pending_.end());
  std::size_t next = 0, step = 0;
  int left = base_;
  live_.clear();
  double first_end = y1;  // the lowest tb among the live spans
  const int mask = s_->rule == FillRule::EvenOdd ? 1 : ~0;  // inside(w) is (w & mask) != 0
  for (std::size_t e = 0; e + 1 < events_.size(); ++e) {
    const double ya = events_[e], yb = events_[e + 1];
    if (!(yb > ya)) continue;
    while (step < steps_.size() && steps_[step].y <= ya) left += steps_[step++].delta;
    // Close the spans that ended, open those that start.
    if (first_end < yb) {
      std::size_t n = 0;
      first_end = y1;
      for (std::size_t l = 0; l < live_.size(); ++l) {
        const Live& L = live_[l];
        if (L.tb >= yb) {
          first_end = std::min(first_end, L.tb);
          live_[n++] = L;
        } else if (L.sign != 0) {
          emit(spans_[L.span], L.open_y, ya, L.sign, sink);
        }
      }
      live_.resize(n);
    }
    for (; next < pending_.size() && pending_[next].first <= ya; ++next) {
      const Span& s = spans_[pending_[next].second];
      Live L;
      L.span = pending_[next].second;
      L.k = s.k;
      L.last = g_->chains[s.chain].last;
      L.dir = s.dir;
      L.sign = 0;
      L.tb = s.tb;
      L.open_y = ya;
      L.load(v, L.k);
      first_end = std::min(first_end, L.tb);
      live_.push_back(L);
    }
    // x at mid-height, then insertion sort by (x, span): linear when the order barely changed.
    const double ym = 0.5 * (ya + yb);
    for (Live& L : live_) {
      while (L.ny < ym && L.k + 1 < L.last) L.load(v, L.k + 1);
      L.x = L.ax + (ym - L.ay) * L.slope;
    }
    for (std::size_t i = 1; i < live_.size(); ++i) {
      if (!(live_[i] < live_[i - 1])) continue;
      const Live key = live_[i];
      std::size_t j = i;
      do {
        live_[j] = live_[j - 1];
        --j;
      } while (j > 0 && key < live_[j - 1]);
      live_[j] = key;
    }
    int w = left;
    bool before = (w & mask) != 0;
    for (Live& L : live_) {
      w += L.dir;
      const bool after = (w & mask) != 0;
      const int sign = before == after ? 0 : (after ? 1 : -1);
      before = after;
      if (sign != L.sign) {
        if (L.sign != 0) emit(spans_[L.span], L.open_y, ya, L.sign, sink);
        L.sign = sign;
        L.open_y = ya;
      }
    }
  }
  for (const Live& L : live_)
    if (L.sign != 0) emit(spans_[L.span], L.open_y, std::min(L.tb, y1), L.sign, sink);
}

template <class Sink>
bool StripSweep::strip(double y0, double y1, Sink& sink) {
  if (!update_active(y0, y1)) return next_ < s_->chain_end;
  if (s_->simple) {
    emit_simple(y0, y1, sink);
    return true;
  }
  build_spans(y0, y1);
  if (spans_.empty()) return true;
  steps_.clear();
  base_ = 0;
  // Clusters left to right: a span joins the cluster while its x range overlaps the cluster's.
  std::size_t c0 = 0;
  while (c0 < byx_.size()) {
    std::size_t c1 = c0 + 1;
    double xmax = spans_[byx_[c0]].xmax;
    while (c1 < byx_.size() && spans_[byx_[c1]].xmin < xmax) xmax = std::max(xmax, spans_[byx_[c1++]].xmax);
    const Span& s = spans_[byx_[c0]];
    if (c1 == c0 + 1 && steps_.empty() && s.ta == y0 && s.tb == y1) {
      // A lone span through the whole strip under a constant winding: no events.
      const bool before = inside(base_), after = inside(base_ + s.dir);
      if (before != after) emit(s, y0, y1, after ? 1 : -1, sink);
      base_ += s.dir;
      c0 = c1;
      continue;
    }
    cluster_events(c0, c1, y0, y1);
    sweep_cluster(c0, c1, y1, sink);
    add_steps(c0, c1, y0, y1);
    c0 = c1;
  }
  return true;
}

}  // namespace splinefig::render::detail
