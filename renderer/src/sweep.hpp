#pragma once
// Exact scan conversion with fill-rule (union) semantics, one horizontal strip at a time.
//
// Within a strip [y0, y1] the chains are cut at every event: a chain starting or ending, or two
// chains crossing. Between two consecutive events no two chains cross, so they keep one
// left-to-right order; summing dir along it gives the winding number of every gap, and a chain
// is a boundary of the filled region exactly where the fill rule's verdict changes across it.
// Only those boundary pieces go to the sink, signed +1 where the region begins (to their right)
// and -1 where it ends. An exact-area accumulator fed with them yields the area of
// {rule(winding)}, not the integral of the winding number, so overlapping parts of one shape
// count once.
//
// The strip's chains fall into clusters: runs whose x ranges in the strip overlap, taken left
// to right. No chain of one cluster can cross a chain of another, so each cluster is swept on
// its own, starting from the winding on its left. That winding changes only where a chain left
// of it starts or ends without a partner there (a horizontal edge across the gap), so a cluster
// inherits few events, usually none. A cluster is swept incrementally (sweep_cluster): the
// order is kept between events and only neighbours are tested for crossings, so a strip costs
// O((chains + crossings) log chains), however densely a path crosses itself.
//
// Sink concept: void edge(double xa, double ya, double xb, double yb, double sign), ya < yb.
#include "chains.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace splinefig::render::detail {

// (key, index) pairs (a height, an x) in increasing order: the same order as std::pair's,
// without its three-way comparison of doubles.
struct KeyThenIndex {
  bool operator()(const std::pair<double, std::uint32_t>& a, const std::pair<double, std::uint32_t>& b) const {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  }
};

// Sorts [first, last) by `less`; insertion sort for the few elements a strip usually has.
template <class It, class Less = std::less<>>
void sort_small(It first, It last, Less less = {}) {
  if (last - first < 2) return;
  if (last - first > 32) {
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

// A clip path's chains are the shape's own, with dir scaled by kClipWeight: the winding w of a
// gap is then ws + kClipWeight * wc (the shape's and the clip's windings, |ws| < kClipWeight / 2
// while the shape has fewer chains than that), so one sweep resolves the intersection exactly.
inline constexpr int kClipShift = 16, kClipWeight = 1 << kClipShift;
inline constexpr std::size_t kMaxClippedChains = kClipWeight / 2 - 1;  // each part; |wc| then fits too

struct Shape {
  std::size_t chain_begin = 0, chain_end = 0;  // in Geometry::chains, sorted by ymin
  FillRule rule = FillRule::NonZero;
  bool clipped = false;                         // chains with |dir| = kClipWeight are a clip path's
  FillRule clip_rule = FillRule::NonZero;
  bool simple = false;  // |winding| <= 1 everywhere (a convex or simple contour): no sweep needed
  int orient = 1;       // for simple shapes: the winding number inside (+1 or -1)
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  // The integral of the winding number over the clip box, in absolute value (-dir xdy summed over
  // the chains, prepare_item): for a stroke, whose winding is >= 0 everywhere, no band of rows
  // holds more (winding_area, work_estimate.hpp). Infinity while not known (an outline built
  // band by band, outline_stream.hpp).
  double ink = INFINITY;
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
    work_ = 0;
    limit_ = budget_;
    mask_ = s.rule == FillRule::EvenOdd ? 1 : ~0;
    clip_mask_ = s.clip_rule == FillRule::EvenOdd ? 1 : ~0;
  }

  // Strips must come in increasing y order. Returns false once nothing is left below.
  template <class Sink>
  bool strip(double y0, double y1, Sink& sink);

  // The sweep's work since reset(): one unit per event (a crossing, a turn at a vertex, a span
  // starting or ending), per span placed in a cluster's order and per step of re-walking or
  // re-indexing that order. Once it passes the budget the sweep stops where it is (strip()
  // returns false and over() is true): the strips' output is then incomplete, and the caller
  // refuses the item. The bound makes every sweep finish, whatever the estimate made before
  // it saw (work_estimate.hpp bounds only crossings of chains through whole bands).
  void set_budget(std::uint64_t units) { budget_ = limit_ = units; }
  std::uint64_t work() const { return work_; }
  bool over() const { return work_ > limit_; }
  // A second limit, per strip: with a ratio q > 0 a strip also stops once its own work passes
  // q times its chain edges and spans, plus kStripSlack (a strip whose outline crosses itself
  // far more often than it has edges: the caller resolves it another way, piece_coverage.hpp).
  // strip_over() says the strip stopped at this limit and not at the budget. The edges and
  // spans of a strip do not depend on where the sweep started, so neither does the verdict.
  void set_strip_ratio(double q) { ratio_ = q; }
  bool strip_over() const { return work_ > limit_ && work_ <= budget_; }
  static constexpr std::uint64_t kStripSlack = 1 << 14;

 private:
  struct Span {
    std::size_t chain, k;  // chain; first edge meeting the strip
    double ta, tb, xmin, xmax;
    int dir;
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
  bool update_active(double y0, double y1);
  template <class Sink>
  void emit_simple(double y0, double y1, Sink& sink);
  template <class Sink>
  void sweep_spans(double y0, double y1, Sink& sink);
  // Above this many chain edges per span and row, a strip is swept row by row (strip()).
  static constexpr double kDenseEdgesPerRow = 2;
  void build_spans(double y0, double y1);
  void add_steps(std::size_t c0, std::size_t c1, double y0, double y1);
  template <class Sink>
  void emit(const Span& s, double ya, double yb, double sign, Sink& sink) const { emit(s.k, s.chain, ya, yb, sign, sink); }
  // The chain's pieces between heights ya and yb, its edges searched from edge k on.
  template <class Sink>
  void emit(std::size_t k, std::size_t chain, double ya, double yb, double sign, Sink& sink) const;
  template <class Sink>
  void sweep_cluster(std::size_t c0, std::size_t c1, double y0, double y1, Sink& sink);
  template <class Sink>
  void set_status(std::uint32_t id, int w_left, double y, Sink& sink);
  template <class Sink>
  void rewalk(std::size_t lo, std::size_t hi, double y, Sink& sink);
  void check_pair(std::size_t p, double y);
  void push_event(double y, std::uint32_t type, std::uint32_t node, std::uint32_t stamp = 0);
  // Whether a gap of winding w is filled: the fill rule of w, or, for a clipped shape, the
  // shape's rule of its part and the clip's rule of the clip's part.
  bool inside(int w) const {
    if (!s_->clipped) return (w & mask_) != 0;
    const int wc = (w + kClipWeight / 2) >> kClipShift, ws = w - wc * kClipWeight;
    return (ws & mask_) != 0 && (wc & clip_mask_) != 0;
  }

  const Geometry* g_ = nullptr;
  const Shape* s_ = nullptr;
  std::size_t next_ = 0;
  std::vector<std::size_t> active_;  // chain indices
  std::vector<std::size_t> cursor_;  // per active chain: first edge not entirely above
  double first_end_ = INFINITY;      // the lowest ymax among the active chains
  std::vector<Span> spans_;
  std::size_t edges_ = 0;            // chain edges meeting the strip, over all spans
  std::vector<std::uint32_t> byx_;   // spans_ by xmin: clusters are runs of overlapping x ranges
  std::vector<Step> steps_;          // winding changes left of the current cluster, by y
  std::vector<Step> merged_;         // scratch for add_steps
  int base_ = 0;                     // winding left of the current cluster at the strip's top
  std::vector<std::pair<double, std::uint32_t>> pending_;  // the spans by xmin

  // The sweep of a cluster: its spans (by their index in the cluster), their left-to-right order
  // at the current height and each one's place in it, and the events still to come, a min-heap
  // by (y, kind).
  struct Node {
    double ax, ay, slope, ny, ta, tb;  // current edge: x = ax + (y - ay) slope up to ny; span in [ta, tb]
    double open_y;                 // where the current boundary status began
    std::size_t k, last, open_k;   // current edge, the chain's last vertex, the edge at open_y
    std::size_t chain;
    int dir, sign, w;              // w: the winding right of the span
    std::uint32_t stamp;           // counts the checks of the pair with its right neighbour
    double x(double y) const { return ax + (y - ay) * slope; }
    void load(const Vertices& v, std::size_t edge) {
      k = edge;
      const Vec2 a = v[edge], b = v[edge + 1];
      ax = a.x;
      ay = a.y;
      ny = b.y;
      slope = (b.x - a.x) / (b.y - a.y);
    }
  };
  // The heap's events (starts and ends come from starts_ and ends_): a span's chain turning at a
  // vertex, and two neighbours crossing; at one height vertices come first.
  enum : std::uint32_t { kVertex = 0, kCross = 1 };
  // An event: its height, its kind (top two bits of key) and node (the rest: a strip never holds
  // 2^30 spans, their records alone would take 48 GB). A crossing is of the node and its right
  // neighbour, valid while the node's stamp is unchanged (every change of either's edge or of
  // the pair bumps it).
  struct Event {
    double y;
    std::uint32_t key, stamp;
    std::uint32_t type() const { return key >> 30; }
    std::uint32_t node() const { return key & ((1u << 30) - 1); }
    // A total order (height, kind, node, stamp): which event comes first never depends on the
    // heap's layout, so dropping stale events (purge_events) changes nothing drawn.
    bool operator>(const Event& o) const {
      if (y != o.y) return y > o.y;
      if (key != o.key) return key > o.key;  // the kind is in the top bits: vertices first
      return stamp > o.stamp;
    }
  };
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> ord_;   // node ids, left to right
  std::vector<std::uint32_t> pos_;   // per node: its index in ord_, or kNone while not live
  std::vector<Event> heap_;                                // vertices and crossings
  std::vector<std::pair<double, std::uint32_t>> starts_;  // spans starting inside the strip, by y
  std::vector<std::pair<double, std::uint32_t>> ends_;    // spans ending inside the strip, by y
  std::vector<std::pair<std::uint32_t, std::uint32_t>> adds_;  // spans starting at one height: (gap, node)
  std::size_t ic0_ = 0;              // the cluster's first index in byx_
  int left_ = 0;                     // the winding left of the cluster at the current height
  std::uint64_t work_ = 0, budget_ = ~std::uint64_t{0};  // see work()
  std::uint64_t limit_ = ~std::uint64_t{0};              // min(budget_, the strip's limit)
  double ratio_ = 0;                                      // see set_strip_ratio
  int mask_ = ~0, clip_mask_ = ~0;   // the fill rules as masks: nonzero ~0, even-odd 1
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
void StripSweep::emit(std::size_t k, std::size_t chain, double ya, double yb, double sign, Sink& sink) const {
  const auto& v = g_->verts;
  const std::size_t last = g_->chains[chain].last;
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

// A cluster, swept incrementally (Bentley-Ottmann inside the strip). Between events the
// spans keep one left-to-right order (ord_); each span knows the winding on its right, so its
// boundary status follows from its own and its left neighbour's. Events, lowest first:
//  - a span ends or starts: it leaves or enters the order at its place (binary search by x, then
//    slope), and the windings are re-walked from there until they agree with the old ones again
//    (at once for the pair of chains meeting at a vertex);
//  - a span's chain turns at a vertex: its new edge is checked against its two neighbours;
//  - two neighbours cross: they swap, and only their two windings and statuses change;
//  - the winding on the cluster's left changes (steps_, rare): every winding is re-walked.
// Only neighbours are tested for crossings (a converging pair's crossing on their current edges,
// if it comes before either edge ends), so a strip costs O((spans + crossings) log spans).
template <class Sink>
void StripSweep::sweep_cluster(std::size_t c0, std::size_t c1, double y0, double y1, Sink& sink) {
  const auto& v = g_->verts;
  const std::size_t n = c1 - c0;
  ic0_ = c0;
  left_ = base_;
  nodes_.resize(n);
  pos_.assign(n, kNone);
  ord_.clear();
  heap_.clear();
  starts_.clear();
  ends_.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    const Span& s = spans_[byx_[c0 + i]];
    Node& N = nodes_[i];
    N.last = g_->chains[s.chain].last;
    N.load(v, s.k);
    while (N.ny <= s.ta && N.k + 1 < N.last) N.load(v, N.k + 1);
    N.ta = s.ta;
    N.tb = s.tb;
    N.dir = s.dir;
    N.sign = 0;
    N.w = 0;
    N.stamp = 0;
    N.open_y = s.ta;
    N.open_k = N.k;
    N.chain = s.chain;
    if (s.ta > y0) {
      starts_.push_back({s.ta, i});
    } else {
      ord_.push_back(i);
      if (N.ny < N.tb) push_event(N.ny, kVertex, i);
    }
    if (s.tb < y1) ends_.push_back({s.tb, i});
  }
  sort_small(starts_.begin(), starts_.end(), KeyThenIndex{});
  sort_small(ends_.begin(), ends_.end(), KeyThenIndex{});
  work_ += n;
  // The order at the strip's top: by x, spans leaving one point by slope.
  std::sort(ord_.begin(), ord_.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Node &A = nodes_[a], &B = nodes_[b];
    const double xa = A.x(y0), xb = B.x(y0);
    if (xa != xb) return xa < xb;
    if (A.slope != B.slope) return A.slope < B.slope;
    return a < b;
  });
  for (std::size_t p = 0; p < ord_.size(); ++p) pos_[ord_[p]] = static_cast<std::uint32_t>(p);
  rewalk(0, ord_.size(), y0, sink);
  for (std::size_t p = 0; p + 1 < ord_.size(); ++p) check_pair(p, y0);
  // Events come from four sources, each in y order: the steps of the winding on the left, the
  // spans' ends and starts (sorted once), and the heap of vertices and crossings. At one height
  // they are taken in that order.
  std::size_t step = 0, ie = 0, is = 0;
  const auto greater = std::greater<>{};
  for (;;) {
    if (work_ > limit_) return;
    const double ys = step < steps_.size() ? steps_[step].y : INFINITY;
    const double ye = ie < ends_.size() ? ends_[ie].first : INFINITY;
    const double yt = is < starts_.size() ? starts_[is].first : INFINITY;
    const double yh = heap_.empty() ? INFINITY : heap_.front().y;
    const double y = std::min(std::min(ys, ye), std::min(yt, yh));
    if (y == INFINITY) break;
    if (ys == y) {
      for (; step < steps_.size() && steps_[step].y == y; ++step) left_ += steps_[step].delta;
      rewalk(0, ord_.size(), y, sink);
      continue;
    }
    if (ye == y || yt == y) {
      // Every span ending, then every span starting at this height, each kind in one pass over
      // the order (a height where thousands of chains end, the turns of a dense zigzag, costs
      // one pass, not one per chain); then one re-walk of the windings over the stretch they
      // touched [lo, hi] and on until the windings agree with the old ones again.
      std::size_t lo = ord_.size(), hi = 0;
      if (ye == y) {
        std::size_t first = ord_.size();
        for (; ie < ends_.size() && ends_[ie].first == y; ++ie) {
          const std::uint32_t id = ends_[ie].second;
          Node& N = nodes_[id];
          if (N.sign != 0) emit(N.open_k, N.chain, N.open_y, y, N.sign, sink);
          first = std::min<std::size_t>(first, pos_[id]);
          pos_[id] = kNone;
          ++work_;
        }
        // The order without them; a removed span's right neighbour is where the windings change.
        std::size_t o = first;
        for (std::size_t j = first; j < ord_.size(); ++j) {
          const std::uint32_t id = ord_[j];
          if (pos_[id] == kNone) {
            lo = std::min(lo, o);
            hi = std::max(hi, o);
            continue;
          }
          ord_[o] = id;
          pos_[id] = static_cast<std::uint32_t>(o++);
        }
        work_ += ord_.size() - first;
        ord_.resize(o);
      }
      if (yt == y) {
        // Each new span's place: the gap of the current order it goes into (by x, then slope),
        // new spans sharing a gap in that same order; then one merge.
        adds_.clear();
        for (; is < starts_.size() && starts_[is].first == y; ++is) {
          const std::uint32_t id = starts_[is].second;
          Node& N = nodes_[id];
          const double x = N.x(y);
          const auto at = std::upper_bound(ord_.begin(), ord_.end(), id, [&](std::uint32_t a, std::uint32_t b) {
            const Node &A = nodes_[a], &B = nodes_[b];
            const double xb = B.x(y);
            if (x != xb) return x < xb;
            if (A.slope != B.slope) return A.slope < B.slope;
            return a < b;
          });
          adds_.push_back({static_cast<std::uint32_t>(at - ord_.begin()), id});
          N.sign = 0;
          N.open_y = y;
          N.open_k = N.k;
          if (N.ny < N.tb) push_event(N.ny, kVertex, id);
          ++work_;
        }
        std::sort(adds_.begin(), adds_.end(), [&](const std::pair<std::uint32_t, std::uint32_t>& a,
                                                  const std::pair<std::uint32_t, std::uint32_t>& b) {
          if (a.first != b.first) return a.first < b.first;
          const Node &A = nodes_[a.second], &B = nodes_[b.second];
          const double xa = A.x(y), xb = B.x(y);
          if (xa != xb) return xa < xb;
          if (A.slope != B.slope) return A.slope < B.slope;
          return a.second < b.second;
        });
        // A removal's gap moves right by the spans inserted at or before it.
        if (lo <= hi) {
          std::size_t before_lo = 0, before_hi = 0;
          for (const auto& a : adds_) {
            before_lo += a.first <= lo;
            before_hi += a.first <= hi;
          }
          lo += before_lo;
          hi += before_hi;
        }
        const std::size_t from = adds_.front().first, old_n = ord_.size();
        ord_.resize(old_n + adds_.size());
        // Merge from the back: old entries move right by the new ones placed before them.
        std::size_t j = old_n, k = adds_.size(), out = ord_.size();
        while (k > 0) {
          const std::size_t gap = adds_[k - 1].first;
          while (j > gap) ord_[--out] = ord_[--j];
          ord_[--out] = adds_[--k].second;
        }
        for (std::size_t q = from; q < ord_.size(); ++q) pos_[ord_[q]] = static_cast<std::uint32_t>(q);
        work_ += ord_.size() - from;
        lo = std::min(lo, from);
        for (const auto& a : adds_) hi = std::max<std::size_t>(hi, pos_[a.second]);
      }
      if (lo > hi) continue;
      rewalk(lo, hi, y, sink);
      for (std::size_t p = lo > 0 ? lo - 1 : 0; p <= hi && p < ord_.size(); ++p) check_pair(p, y);
      continue;
    }
    const Event e = heap_.front();
    ++work_;
    std::pop_heap(heap_.begin(), heap_.end(), greater);
    heap_.pop_back();
    if (e.type() == kCross) {
      const std::uint32_t a = e.node();
      if (pos_[a] == kNone || nodes_[a].stamp != e.stamp || pos_[a] + 1 >= ord_.size()) continue;
      const std::size_t p = pos_[a];
      const std::uint32_t b = ord_[p + 1];
      Node &A = nodes_[a], &B = nodes_[b];
      ord_[p] = b;
      ord_[p + 1] = a;
      pos_[b] = static_cast<std::uint32_t>(p);
      pos_[a] = static_cast<std::uint32_t>(p + 1);
      const int wl = p > 0 ? nodes_[ord_[p - 1]].w : left_;
      B.w = wl + B.dir;
      set_status(b, wl, y, sink);
      A.w = B.w + A.dir;
      set_status(a, B.w, y, sink);
      if (p > 0) check_pair(p - 1, y);
      check_pair(p, y);
      check_pair(p + 1, y);
    } else {  // a vertex
      const std::uint32_t id = e.node();
      Node& N = nodes_[id];
      N.load(v, N.k + 1);
      if (N.ny < N.tb) push_event(N.ny, kVertex, id);
      const std::size_t p = pos_[id];
      if (p > 0) check_pair(p - 1, y);
      check_pair(p, y);
    }
  }
  for (const std::uint32_t id : ord_) {
    const Node& N = nodes_[id];
    if (N.sign != 0) emit(N.open_k, N.chain, N.open_y, std::min(N.tb, y1), N.sign, sink);
  }
}

inline void StripSweep::push_event(double y, std::uint32_t type, std::uint32_t node, std::uint32_t stamp) {
  // A crossing event goes stale whenever its pair changes, and stays in the heap until its
  // height comes: where many pairs change often (thousands of joins overlapping at the turns of
  // a dense zigzag) stale events would outnumber live ones without bound. The live ones are at
  // most one turn and one crossing per span, so the heap is swept of stale ones whenever it
  // grows past four per span: amortised O(1) per push, and the heap stays O(spans).
  if (heap_.size() >= 4 * nodes_.size() + 64) {
    std::erase_if(heap_, [&](const Event& e) {
      if (e.type() != kCross) return false;
      const std::uint32_t a = e.node();
      return pos_[a] == kNone || nodes_[a].stamp != e.stamp;
    });
    std::make_heap(heap_.begin(), heap_.end(), std::greater<>{});
    work_ += nodes_.size();
  }
  heap_.push_back({y, type << 30 | node, stamp});
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>{});
}

// Schedules the crossing of the neighbours ord_[p] (left) and ord_[p + 1] at or after y, if
// they converge and meet before either's current edge ends (else the vertex or end event there
// checks them again); any crossing scheduled for ord_[p] before is void from now on. A pair
// found out of order while converging swaps at once; a diverging pair never swaps, so no two
// spans swap back and forth at one height.
inline void StripSweep::check_pair(std::size_t p, double y) {
  if (p >= ord_.size()) return;
  const std::uint32_t a = ord_[p];
  Node& A = nodes_[a];
  ++A.stamp;
  if (p + 1 >= ord_.size()) return;
  const Node& B = nodes_[ord_[p + 1]];
  const double rel = A.slope - B.slope;
  if (!(rel > 0)) return;
  double yc = y + (B.x(y) - A.x(y)) / rel;
  if (!(yc >= y)) yc = y;
  const double lim = std::min(std::min(A.ny, B.ny), std::min(A.tb, B.tb));
  if (!(yc < lim)) return;
  push_event(yc, kCross, a, A.stamp);
}

// The boundary status of node id from the winding on its left and its own (on its right);
// the piece it ends is emitted.
template <class Sink>
void StripSweep::set_status(std::uint32_t id, int w_left, double y, Sink& sink) {
  Node& N = nodes_[id];
  const bool before = inside(w_left), after = inside(N.w);
  const int sign = before == after ? 0 : (after ? 1 : -1);
  if (sign == N.sign) return;
  if (N.sign != 0) emit(N.open_k, N.chain, N.open_y, y, N.sign, sink);
  N.sign = sign;
  N.open_y = y;
  N.open_k = N.k;
}

// Recomputes the windings from ord_[lo] on: through ord_[hi] at least, then until a span's
// winding is what it was (everything right of it is then unchanged too).
template <class Sink>
void StripSweep::rewalk(std::size_t lo, std::size_t hi, double y, Sink& sink) {
  int w = lo > 0 ? nodes_[ord_[lo - 1]].w : left_;
  for (std::size_t j = lo; j < ord_.size(); ++j) {
    const std::uint32_t id = ord_[j];
    Node& N = nodes_[id];
    const int nw = w + N.dir;
    if (j > hi && nw == N.w) break;
    N.w = nw;
    set_status(id, w, y, sink);
    w = nw;
    ++work_;
  }
}

template <class Sink>
bool StripSweep::strip(double y0, double y1, Sink& sink) {
  limit_ = budget_;  // the strip's own limit, if any, is set below from its edges
  if (over()) return false;
  if (!update_active(y0, y1)) return next_ < s_->chain_end;
  if (s_->simple) {
    emit_simple(y0, y1, sink);
    return true;
  }
  build_spans(y0, y1);
  if (spans_.empty()) return true;
  if (ratio_ > 0) {
    const double own = ratio_ * static_cast<double>(edges_ + spans_.size()) + static_cast<double>(kStripSlack);
    const double cap = static_cast<double>(budget_ - std::min(budget_, work_));
    limit_ = own < cap ? work_ + static_cast<std::uint64_t>(own) : budget_;
  }
  if (y1 - y0 > 1 && edges_ > kDenseEdgesPerRow * (y1 - y0) * static_cast<double>(spans_.size())) {
    // Chains with many vertices per row: a strip a row high keeps most of them lone spans,
    // which need no event queue; the union is the same whichever strips it is resolved in.
    for (double y = y0; y < y1; y = std::min(y + 1, y1)) {
      if (!update_active(y, std::min(y + 1, y1))) continue;
      build_spans(y, std::min(y + 1, y1));
      if (!spans_.empty()) sweep_spans(y, std::min(y + 1, y1), sink);
      if (over()) return false;
    }
    return true;
  }
  sweep_spans(y0, y1, sink);
  return !over();
}

// The spans of the strip, cluster by cluster from the left.
template <class Sink>
void StripSweep::sweep_spans(double y0, double y1, Sink& sink) {
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
    sweep_cluster(c0, c1, y0, y1, sink);
    if (over()) return;
    add_steps(c0, c1, y0, y1);
    c0 = c1;
  }
}

}  // namespace splinefig::render::detail
