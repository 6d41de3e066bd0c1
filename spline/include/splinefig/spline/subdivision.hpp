#pragma once
// The uniform cubic B-spline by subdivision (seed 002 §4.16.9, Chaikin-style refinement).
//
// One refinement step replaces a control polygon by a finer one that defines the same
// B-spline: each edge P_{i}P_{i+1} gets its midpoint (an "edge point") and each interior
// vertex P_i is moved to (P_{i-1} + 6P_i + P_{i+1})/8 (a "vertex point"):
//   (E_0, V_1, E_1, V_2, ..., V_{m-1}, E_{m-1}) = 1/8 [4 4 0 0; 1 6 1 0; 0 4 4 0; ...] (P_0..P_m).
// An open polygon of c points becomes one of 2c - 3 points, so the four points of one segment
// give 3 + 2^k points after k steps (5, 7, 11, 19, ...). Seen as knot insertion, a step inserts
// a knot at the middle of every span (Boehm), halving the knot spacing.
//
// Repeated steps converge to the curve; the limit of the vertex P_i of any step is
// (P_{i-1} + 4P_i + P_{i+1})/6, the B-spline's joint (the eigen-analysis of the 3x3 matrix A
// in the seed: A^infinity has rows (1 4 1)/6).
#include <splinefig/spline/points.hpp>

namespace splinefig {

// One refinement step of an open polygon (c >= 3 points -> 2c - 3 points).
Points refine(const Points& polygon);
// k refinement steps.
Points refine(const Points& polygon, int steps);
// One step of a closed polygon (c >= 3 points, the last joined to the first -> 2c points:
// an edge point and a vertex point per original vertex, starting with the vertex point of P_0).
Points refine_closed(const Points& polygon);

// The limit points (P_{i-1} + 4P_i + P_{i+1})/6 of the interior vertices i = 1..c-2 of an open
// polygon: the points of the B-spline curve at its joints.
Points limit_points(const Points& polygon);

}  // namespace splinefig
