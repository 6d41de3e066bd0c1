#include "sweep.hpp"

namespace splinefig::render::detail {

// One span per active chain meeting the strip: its height range and x range there; byx_
// lists them by xmin.
void StripSweep::build_spans(double y0, double y1) {
  const auto& ch = g_->chains;
  const auto& v = g_->verts;
  spans_.clear();
  for (std::size_t i = 0; i < active_.size(); ++i) {
    const Chain& c = ch[active_[i]];
    std::size_t& k = cursor_[i];
    while (k + 1 < c.last && v[k + 1].y <= y0) ++k;
    Span s;
    s.chain = active_[i];
    s.k = k;
    s.dir = c.dir;
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
  pending_.clear();
  for (std::uint32_t i = 0; i < spans_.size(); ++i) pending_.push_back({spans_[i].xmin, i});
  sort_small(pending_.begin(), pending_.end());
  byx_.resize(spans_.size());
  for (std::size_t i = 0; i < byx_.size(); ++i) byx_[i] = pending_[i].second;
}

// The events of the cluster byx_[c0, c1), sorted and distinct: the strip's ends, where its
// spans start, end or change order, and where the winding on its left changes.
void StripSweep::cluster_events(std::size_t c0, std::size_t c1, double y0, double y1) {
  events_.clear();
  events_.push_back(y0);
  events_.push_back(y1);
  for (std::size_t c = c0; c < c1; ++c) {
    const Span& s = spans_[byx_[c]];
    if (s.ta > y0) events_.push_back(s.ta);
    if (s.tb < y1) events_.push_back(s.tb);
  }
  for (const Step& st : steps_) events_.push_back(st.y);
  // Order changes between spans whose x ranges meet (a sweep over xmin). Ranges that only
  // touch count too: a span can run along another's extreme x for a while and then leave it
  // (both on the clip box's side), and inside a cluster that is a change of order.
  for (std::size_t i = c0; i < c1; ++i) {
    const Span& a = spans_[byx_[i]];
    for (std::size_t j = i + 1; j < c1 && spans_[byx_[j]].xmin <= a.xmax; ++j) crossings(a, spans_[byx_[j]]);
  }
  if (events_.size() > 2) {
    sort_small(events_.begin(), events_.end());
    events_.erase(std::unique(events_.begin(), events_.end()), events_.end());
  }
}

// Adds the cluster byx_[c0, c1) to the winding on the left of the clusters after it: dir from
// where each span starts to where it ends. Steps that cancel (two chains meeting at a vertex)
// are dropped, so later clusters get no events from them.
void StripSweep::add_steps(std::size_t c0, std::size_t c1, double y0, double y1) {
  const std::size_t n = steps_.size();
  for (std::size_t c = c0; c < c1; ++c) {
    const Span& s = spans_[byx_[c]];
    if (s.ta > y0) steps_.push_back({s.ta, s.dir});
    else base_ += s.dir;
    if (s.tb < y1) steps_.push_back({s.tb, -s.dir});
  }
  if (steps_.size() == n) return;
  sort_small(steps_.begin(), steps_.end());
  std::size_t m = 0;
  for (std::size_t i = 0; i < steps_.size();) {
    Step st = steps_[i++];
    while (i < steps_.size() && steps_[i].y == st.y) st.delta += steps_[i++].delta;
    if (st.delta != 0) steps_[m++] = st;
  }
  steps_.resize(m);
}

// Adds to events_ every height in the common range of a and b where their order changes.
// Between consecutive vertex heights of either chain both are linear, so their gap is too:
// sampling the gap at those heights finds every sign change, and the root is interpolated.
void StripSweep::crossings(const Span& a, const Span& b) {
  const double lo = std::max(a.ta, b.ta), hi = std::min(a.tb, b.tb);
  if (!(hi > lo)) return;
  const auto& v = g_->verts;
  const std::size_t la = g_->chains[a.chain].last, lb = g_->chains[b.chain].last;
  std::size_t ka = a.k, kb = b.k;
  double y = lo;
  double d = x_on(a, ka, y) - x_on(b, kb, y);
  int last_sign = d > 0 ? 1 : (d < 0 ? -1 : 0);
  double y_prev = y, d_prev = d;
  while (y < hi) {
    // next sample: the lowest vertex height above y of either chain, or hi
    while (ka + 1 < la && v[ka + 1].y <= y) ++ka;
    while (kb + 1 < lb && v[kb + 1].y <= y) ++kb;
    double yn = hi;
    if (v[ka + 1].y > y) yn = std::min(yn, v[ka + 1].y);
    if (v[kb + 1].y > y) yn = std::min(yn, v[kb + 1].y);
    y = yn;
    double dn = x_at(ka, y) - x_at(kb, y);
    int s = dn > 0 ? 1 : (dn < 0 ? -1 : 0);
    // Every change of order is an event: a crossing (interpolated), and the two ends of a
    // stretch where the chains coincide (e.g. both projected onto the clip box's side).
    if (s != last_sign) {
      if (s != 0 && last_sign != 0) {
        double yc = y_prev + (y - y_prev) * (d_prev / (d_prev - dn));
        events_.push_back(std::clamp(yc, y_prev, y));
      } else {
        events_.push_back(s == 0 ? y : y_prev);
      }
    }
    last_sign = s;
    y_prev = y;
    d_prev = dn;
  }
}

}  // namespace splinefig::render::detail
