#pragma once
// A long stroke's outline built as the bands of one thread reach it, and given back behind them:
// drawing a stroke of 10^6 points then holds the few outline pieces the current band meets
// (about 10 MB for a Lissajous figure on 1024^2), not the whole outline (30 MB).
//
// The outline comes in pieces of kOutlinePiecePoints points (stroke.hpp: OutlinePieces), and a
// piece's outline stays within the stroke's reach of the points it is built from
// (OutlinePieces::y_range), so how high its chains can begin is known before it is built.
// Before the band [y0, y1) is drawn, every piece that can reach above y1 is built, and its
// chains go where sorting all the outline's chains at once would put them (by ymin, then by
// piece and vertex, as prepare_item sorts them when the pieces are built in order). Those chains
// begin at or below y0, where the sweep has taken none yet, so the sweep, the crossing bound and
// the winding area of every band see the chains the whole outline would give, in the same
// order: the same bytes. A piece none of whose chains goes below y0 is never read again, and
// its vertices' memory is given back (huge_pages.hpp: release_pages).
#include "stroke.hpp"
#include "sweep.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace splinefig::render::detail {

class OutlineStream {
 public:
  // Starts the stroke of `pts` into the empty geometry g and the shape s (no chains yet), clipped
  // to `clip` (the canvas, unshifted). False, with g and s untouched, if the outline is not built
  // in pieces (an open solid stroke of over two pieces' worth of points, repeats dropped).
  bool start(std::span<const Vec2> pts, bool closed, const StrokeStyle& style, const Box& clip, Geometry& g, Shape& s);
  // Heights every chain of the outline lies within (before any is built).
  double ymin() const { return ymin_; }
  double ymax() const { return ymax_; }
  // Before the band [y0, y1): bands in increasing order, each starting where the last ended.
  // Builds every piece that can reach above y1 and gives back the pieces that end above y0.
  void advance(double y0, double y1);
  // Pieces not built yet (the sweep may run out of chains before their bands come).
  bool pending() const { return next_ < order_.size(); }
  // The lowest ymin and highest ymax of the chains built so far.
  double chains_ymin() const { return chains_ymin_; }
  double chains_ymax() const { return chains_ymax_; }

 private:
  struct Piece {
    double y0 = 0, y1 = 0;             // OutlinePieces::y_range
    std::size_t vert0 = 0, vert1 = 0;  // its vertices in g
    double chains_ymax = -INFINITY;    // the lowest end of its chains
    bool built = false, released = false;
  };
  void release(std::size_t k);

  std::optional<OutlinePieces> pieces_;
  Geometry* g_ = nullptr;
  Shape* s_ = nullptr;
  Box clip_{};
  std::vector<Piece> piece_;
  std::vector<std::uint32_t> order_;  // pieces by y0
  std::size_t next_ = 0;              // in order_: the first piece not built
  std::vector<std::uint32_t> built_;  // pieces in the order built (increasing vertex index)
  double ymin_ = 0, ymax_ = 0, chains_ymin_ = INFINITY, chains_ymax_ = -INFINITY;
};

}  // namespace splinefig::render::detail
