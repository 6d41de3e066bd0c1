#include "work_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace splinefig::render::detail {
namespace {

// The number of pairs i < j with v[i] > v[j], sorting v (merge sort, with `tmp` as scratch).
double count_inversions(std::vector<double>& v, std::vector<double>& tmp) {
  const std::size_t n = v.size();
  tmp.resize(n);
  double count = 0;
  for (std::size_t width = 1; width < n; width *= 2) {
    for (std::size_t lo = 0; lo < n; lo += 2 * width) {
      const std::size_t mid = std::min(lo + width, n), hi = std::min(lo + 2 * width, n);
      std::size_t i = lo, j = mid, o = lo;
      while (i < mid && j < hi) {
        if (v[j] < v[i]) {
          count += static_cast<double>(mid - i);  // v[j] is below every element left in [i, mid)
          tmp[o++] = v[j++];
        } else {
          tmp[o++] = v[i++];
        }
      }
      while (i < mid) tmp[o++] = v[i++];
      while (j < hi) tmp[o++] = v[j++];
    }
    v.swap(tmp);
  }
  return count;
}

}  // namespace

double crossings_lower_bound(const Geometry& g, const Shape& s, int y0, int y1, int band, double stop_at,
                             std::size_t* chains) {
  if (s.simple || s.empty() || y1 <= y0) return 0;
  const auto& ch = g.chains;
  const auto& v = g.verts;
  struct Active {
    std::size_t chain, k;  // k: the edge holding the band's top
  };
  std::vector<Active> active;
  std::vector<std::pair<double, double>> spans, whole;  // (x at a stretch's top, x at its bottom)
  std::vector<double> bottoms, tmp;
  // The pairs of spans whose order at the bottom is the reverse of their order at the top.
  auto inversions = [&](std::vector<std::pair<double, double>>& sp) {
    if (sp.size() < 2) return 0.0;
    std::sort(sp.begin(), sp.end());
    bottoms.resize(sp.size());
    for (std::size_t i = 0; i < sp.size(); ++i) bottoms[i] = sp[i].second;
    return count_inversions(bottoms, tmp);
  };
  // x of chain c at height y, its edges searched from k on by bisection (y ascending: a chain of
  // a million vertices through 64 bands costs 64 searches, not a walk over its vertices); k is
  // left at the edge holding y.
  auto x_at = [&](const Chain& c, std::size_t& k, double y) {
    std::size_t lo = k, hi = c.last - 1;  // the first edge whose lower end is below y
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (v[mid + 1].y <= y) lo = mid + 1; else hi = mid;
    }
    k = lo;
    const Vec2 a = v[k], b = v[k + 1];
    if (y <= a.y) return a.x;
    if (y >= b.y) return b.x;
    return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
  };
  std::size_t next = s.chain_begin;
  double count = 0;
  for (int b0 = y0; b0 < y1 && count < stop_at; b0 += band) {
    const double top = b0, bottom = std::min(b0 + band, y1);
    std::size_t n = 0;
    for (const Active& a : active)
      if (ch[a.chain].ymax > top) active[n++] = a;
    active.resize(n);
    for (; next < s.chain_end && ch[next].ymin < bottom; ++next)
      if (ch[next].ymax > top) active.push_back({next, ch[next].first});
    if (chains) *chains = active.size();
    // Chains through the whole band: a pair in one order at its top and the other at its bottom
    // crosses inside it.
    spans.clear();
    double last_start = -INFINITY, first_end = INFINITY;
    for (Active& a : active) {
      const Chain& c = ch[a.chain];
      if (c.ymin > top && c.ymin < bottom) last_start = std::max(last_start, c.ymin);
      if (c.ymax < bottom && c.ymax > top) first_end = std::min(first_end, c.ymax);
      if (c.ymin > top || c.ymax < bottom) continue;
      const double xt = x_at(c, a.k, top);
      std::size_t kb = a.k;
      spans.push_back({xt, x_at(c, kb, bottom)});
    }
    count += inversions(spans);
    // Chains that begin inside the band: from the last of their beginnings to the band's bottom
    // every one of them is there, and the pairs inverted over that stretch that include one of
    // them (all inverted pairs less those of chains through the whole band) cross in it, where
    // no pair counted above is counted again. Chains that end inside the band likewise, from its
    // top to the first of their ends. Both stretches are empty for a band without such chains;
    // they find the crossings of joins that overlap where a dense zigzag turns, which the
    // whole-band count cannot see.
    for (int side = 0; side < 2; ++side) {
      const double from = side == 0 ? last_start : top, to = side == 0 ? bottom : first_end;
      if (!(from > top || to < bottom) || !(from < to)) continue;
      spans.clear();
      whole.clear();
      for (Active& a : active) {
        const Chain& c = ch[a.chain];
        if (c.ymin > from || c.ymax < to) continue;
        std::size_t ka = a.k, kb = a.k;
        const std::pair<double, double> sp{x_at(c, ka, from), x_at(c, kb, to)};
        spans.push_back(sp);
        if (c.ymin <= top && c.ymax >= bottom) whole.push_back(sp);
      }
      count += inversions(spans) - inversions(whole);
    }
  }
  return count;
}

double winding_area(const Geometry& g, const Shape& s, double y0, double y1) {
  // The winding number is the sum of dir over the chains left of a point, and the dirs of the
  // chains at any height sum to 0: so its integral over a row is -sum(dir * x) over the chains
  // there, and over the rows the same with x integrated over y.
  double sum = 0;
  const auto& v = g.verts;
  for (std::size_t c = s.chain_begin; c < s.chain_end && g.chains[c].ymin < y1; ++c) {
    const Chain& ch = g.chains[c];
    if (ch.ymax <= y0) continue;
    double part = 0;
    std::size_t lo = ch.first, hi = ch.last - 1;  // the first edge whose lower end is below y0
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (v[mid + 1].y <= y0) lo = mid + 1; else hi = mid;
    }
    for (std::size_t k = lo; k < ch.last; ++k) {
      const Vec2 a = v[k], b = v[k + 1];
      if (a.y >= y1) break;
      const double ya = std::max(a.y, y0), yb = std::min(b.y, y1);
      const double t = (b.x - a.x) / (b.y - a.y);
      part += 0.5 * ((a.x + (ya - a.y) * t) + (a.x + (yb - a.y) * t)) * (yb - ya);
    }
    sum -= ch.dir * part;
  }
  return std::abs(sum);
}

}  // namespace splinefig::render::detail

