#include "sweep.hpp"

namespace splinefig::render::detail {

// One span per active chain meeting the strip: its height range and x range there; byx_
// lists them by xmin.
void StripSweep::build_spans(double y0, double y1) {
  const auto& ch = g_->chains;
  const auto& v = g_->verts;
  spans_.clear();
  edges_ = 0;
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
    edges_ += j - k + 1;
    double xb = x_at(std::min(j, c.last - 1), s.tb);
    s.xmin = std::min(s.xmin, xb);
    s.xmax = std::max(s.xmax, xb);
    spans_.push_back(s);
  }
  pending_.clear();
  for (std::uint32_t i = 0; i < spans_.size(); ++i) pending_.push_back({spans_[i].xmin, i});
  sort_small(pending_.begin(), pending_.end(), KeyThenIndex{});
  byx_.resize(spans_.size());
  for (std::size_t i = 0; i < byx_.size(); ++i) byx_[i] = pending_[i].second;
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
  // The steps before n are sorted already: sort the new ones and merge.
  sort_small(steps_.begin() + static_cast<std::ptrdiff_t>(n), steps_.end());
  if (n > 0 && steps_[n].y < steps_[n - 1].y) {
    merged_.resize(steps_.size());
    std::merge(steps_.begin(), steps_.begin() + static_cast<std::ptrdiff_t>(n), steps_.begin() + static_cast<std::ptrdiff_t>(n),
               steps_.end(), merged_.begin());
    steps_.swap(merged_);
  }
  std::size_t m = 0;
  for (std::size_t i = 0; i < steps_.size();) {
    Step st = steps_[i++];
    while (i < steps_.size() && steps_[i].y == st.y) st.delta += steps_[i++].delta;
    if (st.delta != 0) steps_[m++] = st;
  }
  steps_.resize(m);
}

}  // namespace splinefig::render::detail
