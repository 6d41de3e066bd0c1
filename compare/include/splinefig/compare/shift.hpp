#pragma once
// Tolerance to small translations (anti-aliased edges that move by a fraction of a pixel).
//
// For pixel p, channel c and radius N, let [lo_B, hi_B] be the range of B's values over the
// (2N+1) x (2N+1) pixels around p (those inside the image). A value that lies in that range
// is one that B takes, or interpolates, within N pixels: an edge translated by t <= N pixels
// produces exactly such values. The tolerated error is the distance to the range, taken both
// ways so that a line missing from either image is caught:
//   e(p, c) = max(dist(A(p,c), [lo_B, hi_B]), dist(B(p,c), [lo_A, hi_A])).
// With N = 0 this is |A - B|. A pixel then passes when e <= the fail threshold, which includes
// "some neighbour within N pixels matches within the threshold".
#include <splinefig/compare/image.hpp>

namespace splinefig::compare {

// `a` and `b` on the same window with the same channel count; radius >= 0.
Image shift_tolerant_error(const Image& a, const Image& b, int radius);

}  // namespace splinefig::compare
