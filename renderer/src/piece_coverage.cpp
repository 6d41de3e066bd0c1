#include "piece_coverage.hpp"

#include <algorithm>
#include <cmath>

namespace splinefig::render::detail {
namespace {

void slab_extent(std::span<const Vec2> poly, double y0, SlabExtent& e) {
  const double y1 = y0 + 1;
  std::fill(std::begin(e.l), std::end(e.l), INFINITY);
  std::fill(std::begin(e.r), std::end(e.r), -INFINITY);
  e.x0 = INFINITY;
  e.x1 = -INFINITY;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = poly[i], q = poly[i + 1 == n ? 0 : i + 1];
    if (p.y >= y0 && p.y <= y1) {
      e.x0 = std::min(e.x0, p.x);
      e.x1 = std::max(e.x1, p.x);
    }
    const double lo = std::min(p.y, q.y), hi = std::max(p.y, q.y);
    if (hi < y0 || lo > y1 || lo == hi) continue;
    const double dxdy = (q.x - p.x) / (q.y - p.y);
    for (int k = 0; k <= kSubSlabs; ++k) {
      const double y = y0 + static_cast<double>(k) / kSubSlabs;
      if ((p.y <= y) != (q.y <= y)) {
        const double x = p.x + (y - p.y) * dxdy;
        e.l[k] = std::min(e.l[k], x);
        e.r[k] = std::max(e.r[k], x);
      }
    }
  }
  e.x0 = std::min({e.x0, e.l[0], e.l[kSubSlabs]});
  e.x1 = std::max({e.x1, e.r[0], e.r[kSubSlabs]});
}

// Rounding margin of the inner intervals (see the header).
constexpr double kInnerMargin = 1e-9;
// The grid the inner intervals' starts are rounded up to, in points per pixel (a power of 2:
// q / kGrid is exact).
constexpr int kGrid = 16;

}  // namespace

PieceCoverage::PieceCoverage(ConvexPieces pieces, int width, int height, int band_rows)
    : pieces_(std::move(pieces)), width_(width) {
  const int bands = (height + band_rows - 1) / band_rows;
  band_start_.assign(static_cast<std::size_t>(bands) + 1, 0);
  auto band_range = [&](const Box& b, int& b0, int& b1) {
    const double r0 = std::clamp(std::floor(b.y0), 0.0, static_cast<double>(height));
    const double r1 = std::clamp(std::ceil(b.y1), 0.0, static_cast<double>(height));
    b0 = static_cast<int>(r0) / band_rows;
    b1 = (static_cast<int>(r1) + band_rows - 1) / band_rows;  // exclusive
  };
  for (const Box& b : pieces_.bounds) {
    int b0, b1;
    band_range(b, b0, b1);
    for (int k = b0; k < b1; ++k) ++band_start_[static_cast<std::size_t>(k) + 1];
  }
  for (std::size_t k = 1; k < band_start_.size(); ++k) band_start_[k] += band_start_[k - 1];
  by_band_.resize(band_start_.back());
  std::vector<std::size_t> fill(band_start_.begin(), band_start_.end() - 1);
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    int b0, b1;
    band_range(pieces_.bounds[i], b0, b1);
    for (int k = b0; k < b1; ++k) by_band_[fill[static_cast<std::size_t>(k)]++] = static_cast<std::uint32_t>(i);
  }
}

std::uint64_t PieceCoverage::draw(int b, int r0, int r1, BoxBand& band, Scratch& s, std::uint64_t budget) const {
  std::uint64_t work = 0;
  const std::uint32_t* ids = by_band_.data() + band_start_[static_cast<std::size_t>(b)];
  const std::size_t n = band_start_[static_cast<std::size_t>(b) + 1] - band_start_[static_cast<std::size_t>(b)];
  if (s.state.size() != static_cast<std::size_t>(width_)) s.state.assign(static_cast<std::size_t>(width_), 0);
  for (int r = r0; r < r1 && work <= budget; ++r) row(r, ids, n, band, s, work, budget);
  return work;
}

void PieceCoverage::row(int r, const std::uint32_t* ids, std::size_t n, BoxBand& band, Scratch& s, std::uint64_t& work,
                        std::uint64_t budget) const {
  const double y0 = r, y1 = r + 1.0, W = width_;
  for (auto& in : s.inner) in.clear();
  s.outer.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = ids[k];
    const Box& bb = pieces_.bounds[i];
    if (bb.y1 <= y0 || bb.y0 >= y1) continue;
    ++work;
    SlabExtent& e = s.extent;
    slab_extent(pieces_.piece(i), y0, e);
    const double x0 = std::max(e.x0, 0.0), x1 = std::min(e.x1, W);
    if (!(x0 < x1)) continue;  // no area on the canvas in this row
    s.outer.push_back({x0, x1, i});
    for (int k = 0; k < kSubSlabs; ++k) {
      const double ya = y0 + static_cast<double>(k) / kSubSlabs, yb = y0 + static_cast<double>(k + 1) / kSubSlabs;
      if (!(bb.y0 < ya && bb.y1 > yb)) continue;
      const double lo = std::max({e.l[k], e.l[k + 1], 0.0}) + kInnerMargin;
      const double hi = std::min({e.r[k], e.r[k + 1], W}) - kInnerMargin;
      if (lo < hi) s.inner[static_cast<std::size_t>(k)].push_back({lo, hi});
    }
  }
  if (s.outer.empty()) return;
  // The outer intervals by the column they start in (a counting sort: a run [a, b) of whole
  // columns meets those with x0 < b, which is floor(x0) < b), and the columns they meet (a
  // difference array): state 1.
  auto& st = s.state;
  auto& count = s.count;
  count.assign(static_cast<std::size_t>(width_) + 2, 0);
  int cmin = width_, cmax = 0;
  for (const Scratch::Outer& o : s.outer) {
    const int c0 = static_cast<int>(o.x0), c1 = std::min(static_cast<int>(std::ceil(o.x1)), width_);
    ++count[static_cast<std::size_t>(c0) + 1];
    cmin = std::min(cmin, c0);
    cmax = std::max(cmax, c1);
  }
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  s.sorted.resize(s.outer.size());
  for (const Scratch::Outer& o : s.outer) s.sorted[count[static_cast<std::size_t>(o.x0)]++] = o;
  s.outer.swap(s.sorted);
  auto& diff = s.count;  // reused: count's work is done
  std::fill(diff.begin() + cmin, diff.begin() + cmax + 1, 0);
  for (const Scratch::Outer& o : s.outer) {
    ++diff[static_cast<std::size_t>(o.x0)];
    --diff[static_cast<std::size_t>(std::min(static_cast<int>(std::ceil(o.x1)), width_))];
  }
  for (int c = cmin, open = 0; c < cmax; ++c) {
    open += diff[static_cast<std::size_t>(c)];
    if (open > 0) st[static_cast<std::size_t>(c)] = 1;
  }
  // A column is solid when each sub-slab's inner intervals cover it: state 1 + k after k. The
  // union of a sub-slab's intervals is found on a grid of 1/kGrid px: each interval's start
  // rounded up to it (so the union found lies inside the true one), the farthest end kept per
  // grid point, then one pass along the grid.
  auto& reach = s.reach;
  if (reach.size() != static_cast<std::size_t>(width_) * kGrid + 1)
    reach.assign(static_cast<std::size_t>(width_) * kGrid + 1, -INFINITY);
  for (int slab = 0; slab < kSubSlabs; ++slab) {
    auto& in = s.inner[static_cast<std::size_t>(slab)];
    if (in.empty()) continue;
    std::size_t qlo = reach.size(), qhi = 0;
    for (const auto& [lo, hi] : in) {
      const std::size_t q = static_cast<std::size_t>(std::ceil(lo * kGrid));
      if (q >= reach.size()) continue;
      reach[q] = std::max(reach[q], hi);
      qlo = std::min(qlo, q);
      qhi = std::max(qhi, q);
    }
    double a = 0, e = -INFINITY;
    auto certify = [&] {
      if (!(e > a)) return;  // no run yet (e = -inf), or one with nothing in it
      const int c0 = static_cast<int>(std::ceil(a)), c1 = static_cast<int>(std::floor(e));
      for (int c = c0; c < c1; ++c)
        if (st[static_cast<std::size_t>(c)] == 1 + slab) ++st[static_cast<std::size_t>(c)];
    };
    for (std::size_t q = qlo; q <= qhi && qlo <= qhi; ++q) {
      const double end = reach[q];
      if (end == -INFINITY) continue;
      reach[q] = -INFINITY;
      const double start = static_cast<double>(q) / kGrid;
      if (start <= e) {
        e = std::max(e, end);
        continue;
      }
      certify();
      a = start;
      e = end;
    }
    certify();
  }
  // Runs of solid columns: +1 at the run's left side, -1 at its right. Runs to resolve: the
  // pieces meeting the run (outer interval overlapping it), clipped to its box and swept.
  BoxRow& out = band.row(r);
  std::size_t next = 0;
  s.live.clear();
  for (int c = cmin; c < cmax;) {
    const std::uint8_t kind = std::min<std::uint8_t>(st[static_cast<std::size_t>(c)], 1);
    const bool solid = st[static_cast<std::size_t>(c)] == 1 + kSubSlabs;
    int e = c + 1;
    while (e < cmax && std::min<std::uint8_t>(st[static_cast<std::size_t>(e)], 1) == kind &&
           (st[static_cast<std::size_t>(e)] == 1 + kSubSlabs) == solid)
      ++e;
    if (solid) {
      out.edge(c, y0, c, y1, 1);
      out.edge(e, y0, e, y1, -1);
    } else if (kind == 1 && work <= budget) {
      const double a = c, b = e;
      for (; next < s.outer.size() && s.outer[next].x0 < b; ++next) s.live.push_back(static_cast<std::uint32_t>(next));
      std::erase_if(s.live, [&](std::uint32_t k) { return s.outer[k].x1 <= a; });
      s.g.verts.clear();
      s.g.chains.clear();
      ChainBuilder cb(s.g, Box{a, y0, b, y1});
      for (const std::uint32_t k : s.live) {
        const std::span<const Vec2> poly = pieces_.piece(s.outer[k].piece);
        cb.move_to(poly[0]);
        for (std::size_t j = 1; j < poly.size(); ++j) cb.line_to(poly[j]);
        cb.close();
      }
      std::sort(s.g.chains.begin(), s.g.chains.end(),
                [](const Chain& x, const Chain& y) { return x.ymin < y.ymin || (x.ymin == y.ymin && x.first < y.first); });
      Shape sh;
      sh.chain_end = s.g.chains.size();
      sh.rule = FillRule::NonZero;
      if (!sh.empty()) {
        s.sweep.reset(s.g, sh);
        s.sweep.set_budget(budget - work);
        s.sweep.strip(y0, y1, band);
        work += s.sweep.work() + s.live.size();
      }
    }
    for (int k = c; k < e; ++k) st[static_cast<std::size_t>(k)] = 0;
    c = e;
  }
}

}  // namespace splinefig::render::detail
