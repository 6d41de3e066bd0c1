#include "outline_stream.hpp"

#include <splinefig/base/huge_pages.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace splinefig::render::detail {

bool OutlineStream::start(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip, Geometry& g,
                          Shape& s) {
  pieces_.emplace(pts, closed, style);
  if (pieces_->size() == 0) {
    pieces_.reset();
    return false;
  }
  auto ranges = [&] {
    piece_.assign(pieces_->size(), Piece{});
    for (std::size_t k = 0; k < piece_.size(); ++k)
      if (!pieces_->y_range(k, piece_[k].y0, piece_[k].y1)) return false;
    return true;
  };
  if (!ranges()) {  // as prepare_item does when a piece finds a repeat: the stroke cut again without them
    pieces_->drop_repeats();
    if (pieces_->size() == 0 || !ranges()) {
      pieces_.reset();
      return false;
    }
  }
  g_ = &g;
  s_ = &s;
  clip_ = clip;
  order_.resize(piece_.size());
  for (std::uint32_t k = 0; k < order_.size(); ++k) order_[k] = k;
  std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return piece_[a].y0 < piece_[b].y0; });
  ymin_ = INFINITY;
  ymax_ = -INFINITY;
  for (const Piece& p : piece_) {
    ymin_ = std::min(ymin_, p.y0);
    ymax_ = std::max(ymax_, p.y1);
  }
  ymin_ = std::clamp(ymin_, clip.y0, clip.y1);  // chains are cut to the clip box
  ymax_ = std::clamp(ymax_, clip.y0, clip.y1);
  reserve_huge(g.verts, 3 * pieces_->points() + 64);  // as the whole outline would: never moved
  s.chain_begin = s.chain_end = g.chains.size();
  return true;
}

void OutlineStream::advance(double y0, double y1) {
  Geometry& g = *g_;
  // Pieces whose chains all end at or above y0: nothing reads their vertices again.
  for (const std::uint32_t k : built_)
    if (!piece_[k].released && piece_[k].chains_ymax <= y0) release(k);
  if (!(next_ < order_.size() && piece_[order_[next_]].y0 < y1)) return;
  const std::size_t old_end = g.chains.size();
  while (next_ < order_.size() && piece_[order_[next_]].y0 < y1) {
    const std::uint32_t k = order_[next_++];
    Piece& p = piece_[k];
    p.vert0 = g.verts.size();
    const std::size_t c0 = g.chains.size();
    ChainBuilder b(g, clip_);
    pieces_->build(k, b);  // true: start() dropped any repeats
    p.vert1 = g.verts.size();
    p.built = true;
    built_.push_back(k);
    for (std::size_t c = c0; c < g.chains.size(); ++c) {
      // Begun above y0, a chain would come after the sweep has passed its first rows.
      if (g.chains[c].ymin < y0) throw std::logic_error("outline piece reaching above the heights of its points");
      p.chains_ymax = std::max(p.chains_ymax, g.chains[c].ymax);
      chains_ymin_ = std::min(chains_ymin_, g.chains[c].ymin);
      chains_ymax_ = std::max(chains_ymax_, g.chains[c].ymax);
    }
  }
  // The chains from y0 on (none of them taken by the sweep yet) in the order of the whole
  // outline's sort: by ymin, then by vertex in piece order.
  const auto begin = g.chains.begin() + static_cast<std::ptrdiff_t>(s_->chain_begin);
  const auto from = std::lower_bound(begin, g.chains.begin() + static_cast<std::ptrdiff_t>(old_end), y0,
                                     [](const Chain& c, double y) { return c.ymin < y; });
  auto piece_of = [&](const Chain& c) {  // built_ is in vertex order
    const auto it = std::upper_bound(built_.begin(), built_.end(), c.first,
                                     [&](std::size_t v, std::uint32_t k) { return v < piece_[k].vert0; });
    return *(it - 1);
  };
  std::sort(from, g.chains.end(), [&](const Chain& a, const Chain& b) {
    if (a.ymin != b.ymin) return a.ymin < b.ymin;
    const std::uint32_t pa = piece_of(a), pb = piece_of(b);
    return pa < pb || (pa == pb && a.first < b.first);
  });
  s_->chain_end = g.chains.size();
  for (const std::uint32_t k : built_)  // pieces without chains on the canvas
    if (!piece_[k].released && piece_[k].chains_ymax <= y0) release(k);
}

// Gives back the memory of the run of released pieces around piece k, in vertex order: the
// blocks of it that lie wholly inside such a run (huge_pages.hpp).
void OutlineStream::release(std::size_t k) {
  piece_[k].released = true;
  const auto at = std::find(built_.begin(), built_.end(), static_cast<std::uint32_t>(k));
  auto lo = at, hi = at + 1;
  while (lo != built_.begin() && piece_[*(lo - 1)].released) --lo;
  while (hi != built_.end() && piece_[*hi].released) ++hi;
  const std::size_t v0 = piece_[*lo].vert0, v1 = piece_[*(hi - 1)].vert1;
  release_pages(g_->verts.data() + v0, (v1 - v0) * sizeof(Vec2));
}

}  // namespace splinefig::render::detail
