#pragma once
// What the exact sweep (sweep.hpp) will cost a shape, known before it runs: a lower bound on the
// number of times the shape's chains cross each other inside the canvas.
//
// The sweep's work grows with those crossings (every one is an event of its queue, about 0.2 us
// each), and a stroke that overlaps itself densely has billions of them: 10^5 uniformly random
// points on 1024^2 cross about 4.5e9 times. The bound lets the rasterizer refuse such a shape at
// once instead of sweeping it for a quarter of an hour.
//
// The bound: the canvas is cut into bands of rows; in each band, take the chains that run through
// its whole height, ordered by x at the band's top. Two of them whose order at the bottom is the
// reverse of their order at the top cross an odd number of times inside the band, so at least
// once. The number of such inverted pairs (counted by merge sort) summed over the bands is a lower
// bound on the crossings: it never exceeds the true count, so a shape under the limit is never
// refused. Chains that start or end inside a band are left out of that band (the bound stays a
// bound).
#include "sweep.hpp"

#include <cstdint>

namespace splinefig::render::detail {

// A lower bound on the crossings of the shape's chains between rows y0 and y1, in bands of `band`
// rows; the count stops once it reaches `stop_at` (the caller only asks whether a limit is
// reached). A simple shape (|winding| <= 1) is swept without crossings: 0.
// `chains`, if given, receives the number of chains meeting the last band looked at.
double crossings_lower_bound(const Geometry& g, const Shape& s, int y0, int y1, int band, double stop_at,
                             std::size_t* chains = nullptr);

// The integral of the shape's winding number over the rows [y0, y1), in absolute value: for a
// stroke (whose outline's winding is >= 0 everywhere, stroke.hpp) about the area of its pieces
// there counted with multiplicity, so divided by the rows' area it says how many times over
// the ink covers them.
double winding_area(const Geometry& g, const Shape& s, double y0, double y1);

}  // namespace splinefig::render::detail
