#pragma once
// Internal: clipping an exact path (lines and cubic Beziers) to a rectangle. Each piece is
// split where it crosses a side of the rectangle (a cubic restricted to a parameter interval
// is again a cubic: de Casteljau), the sub-pieces inside are kept and consecutive ones joined,
// so the clipped curve stays exact.
#include "../layout/panel.hpp"

#include <splinefig/renderer/path.hpp>

#include <array>
#include <vector>

namespace splinefig::figures::detail {

// The parameters t in (0, 1), ascending and distinct, where the cubic with Bernstein
// coefficients b (b0 (1-t)^3 + 3 b1 (1-t)^2 t + 3 b2 (1-t) t^2 + b3 t^3) equals v, each to
// full double precision. A cubic that equals v everywhere has none. A line is the cubic with
// b1 = (2 b0 + b3) / 3, b2 = (b0 + 2 b3) / 3.
std::vector<double> cubic_crossings(const std::array<double, 4>& b, double v);

// The parts of `path` inside `r` (its sides included), as paths of one subpath each, in
// order. A part is open, except a closed subpath of which nothing lies outside, which stays
// closed; a closed subpath that starts inside has its last part joined to its first.
std::vector<render::Path> clip_path(const render::Path& path, const Rect& r);

}  // namespace splinefig::figures::detail
