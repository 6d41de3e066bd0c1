#pragma once
// Internal: the plot elements of the companion texts (docs/companion.md, seeds 002 and 003)
// for figure specs. Each expands, when the spec is loaded, into ordinary series (polylines and
// point sets) computed by the spline library, so drawing needs nothing new:
//   [[axes.interp]]          curve / control points / Bezier points of the spline through data
//   [[axes.relaxed_bspline]] seed 003 §4: curve, joints, division points, Bezier points, A-frames
//   [[axes.bezier]]          one Bezier curve of any degree
//   [[axes.lagrange]]        the Lagrange polynomial y(x) through data
//   [[axes.relaxed_basis]]   basis function f_k of relaxed interpolation (seed 003 §8)
//   [[axes.subdivision]]     refined control polygons and limit points (seed 002 §4.16.9)
//   [[axes.local_betas]]     continuously shaped Beta-spline with per-knot b1, b2
//   [[axes.inbetween]]       a frame interpolated between keyframes (seed 003 §6)
// The keys are documented in docs/companion.md.
#include "toml_reader.hpp"

#include <utility>
#include <vector>

namespace splinefig::figures::detail {

// Parses every companion element of one [axes] table (reader `r`), appending each generated
// series with the source line of its table (for document order).
void parse_companion_elements(TableReader& r, std::vector<std::pair<size_t, PlotElement>>& elements);

}  // namespace splinefig::figures::detail
