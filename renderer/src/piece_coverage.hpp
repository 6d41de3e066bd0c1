#pragma once
// Box-filter coverage of a stroke's rows from its convex pieces (stroke.hpp: stroke_pieces), for
// the bands where the outline's exact sweep would cost too much: a stroke that overlaps itself
// densely has billions of outline crossings, nearly all of them inside ink that is solid anyway.
//
// Row by row (the slab y in [r, r + 1]), each piece P meeting the row gives two intervals of x:
//  - its inner interval: the x whose whole vertical segment {x} x [r, r + 1] lies in P. For a
//    convex P spanning the slab, P's cross-section at height y is [L(y), R(y)] with L convex and
//    R concave, so the interval is [max(L(r), L(r + 1)), min(R(r), R(r + 1))];
//  - its outer interval: the x-extent of P inside the slab.
// A pixel inside the union of the inner intervals lies in the union of the pieces: its
// coverage is exactly 1, whatever the crossings inside it. A pixel outside the union of the
// outer intervals meets no piece: 0. Every other pixel is resolved exactly: the pieces whose
// outer interval meets its run of such pixels are clipped to the run's box and swept with the
// nonzero rule (sweep.hpp), which gives the area of their union there, and the union of all
// pieces is the stroke (stroke.hpp). So the coverage is the exact sweep's, up to rounding (the
// inner intervals are shrunk by 1e-9 px so that rounding never certifies a pixel it should not):
// the error is at most 1e-9 per pixel beyond the arcs' flattening, which both paths share.
//
// The cost is the sum over rows of the pieces meeting them, plus the sweeps of the pixels that
// are neither solid nor empty: for dense random strokes that is about the cost of scan
// converting the pieces' edges once, where the outline's sweep pays for every crossing.
#include "box_coverage.hpp"
#include "stroke.hpp"
#include "sweep.hpp"

#include <cstdint>
#include <vector>

namespace splinefig::render::detail {

// Rows are tested for solid pixels in this many slabs of equal height (a pixel is solid when
// each slab's inner intervals cover it): a piece's inner interval in a slab of height d loses
// d cot(theta) to its slope, so thinner slabs find more of the solid pixels of thin strokes.
inline constexpr int kSubSlabs = 4;

// A convex polygon's cross-sections [l[k], r[k]] at the heights y0 + k / kSubSlabs of a row
// (valid at the heights it spans), and its x-extent [x0, x1] within the row.
struct SlabExtent {
  double l[kSubSlabs + 1], r[kSubSlabs + 1];
  double x0, x1;
};

class PieceCoverage {
 public:
  // The pieces of one stroke on a canvas of the given size, listed by band of `band_rows` rows.
  PieceCoverage(ConvexPieces pieces, int width, int height, int band_rows);

  // What one thread needs between calls (kept to avoid reallocating).
  struct Scratch {
    std::vector<std::pair<double, double>> inner[kSubSlabs];
    struct Outer {
      double x0, x1;
      std::uint32_t piece;
    };
    std::vector<Outer> outer, sorted;
    std::vector<int> count;           // per column: a counting sort's buckets, then a difference array
    std::vector<double> reach;        // per grid point: the farthest end of an interval starting there
    std::vector<std::uint8_t> state;  // per column: 0 empty, else 1 + the sub-slabs that fill it
    SlabExtent extent;
    std::vector<std::uint32_t> live;
    Geometry g;
    StripSweep sweep;
  };

  // Adds the coverage of the rows [r0, r1) of band `b` (its rows begun, their accumulators zero)
  // to `band`, and returns the work done in the sweep's units (StripSweep::work()), counting
  // each piece met in a row as one unit. Past `budget` it stops where it is (the rows are then
  // incomplete and the caller refuses the item) and returns more than `budget`.
  std::uint64_t draw(int b, int r0, int r1, BoxBand& band, Scratch& s, std::uint64_t budget) const;
  std::size_t size() const { return pieces_.size(); }

 private:
  void row(int r, const std::uint32_t* ids, std::size_t n, BoxBand& band, Scratch& s, std::uint64_t& work,
           std::uint64_t budget) const;

  ConvexPieces pieces_;
  int width_;
  std::vector<std::size_t> band_start_;  // pieces of band b: by_band_[band_start_[b], band_start_[b + 1])
  std::vector<std::uint32_t> by_band_;
};

}  // namespace splinefig::render::detail
