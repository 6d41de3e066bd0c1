#pragma once
// Interpolating cubic splines through data points S_0..S_n by way of B-splines (seed 003 §5, §9).
//
// The uniform cubic B-spline with control points B_0..B_n passes through the joints
//   S_i = (B_{i-1} + 4 B_i + B_{i+1}) / 6,
// so interpolation solves the "1 4 1" system B_{i-1} + 4 B_i + B_{i+1} = 6 S_i for the B_i.
// The two missing conditions are the end conditions:
//   relaxed   P''(0) = P''(n) = 0:  B_0 = S_0, B_n = S_n (the natural cubic spline);
//   clamped   P'(0) = v, P'(n) = w:  2B_0 + B_1 = 3S_0 + v,  B_{n-1} + 2B_n = 3S_n - w;
//   periodic  S_n = S_0 and the equations wrap around (B_{-1} = B_{n-1}), B_n = B_0.
// The systems are tridiagonal (cyclic for periodic) and strictly diagonally dominant, so
// elimination without pivoting is stable; the solve is O(n) in any dimension.
//
// The curve P(t), t in [0, n], P(i) = S_i, is n cubic Bezier pieces: piece i (i = 1..n) has
// control points S_{i-1}, (2B_{i-1} + B_i)/3, (B_{i-1} + 2B_i)/3, S_i, i.e. the division
// points at thirds of each leg of the B-spline polygon, with S_i the midpoints of the A-frames.
//
// Minimum sizes: relaxed and clamped need 2 data points (n >= 1); periodic needs 3 (n >= 2,
// two distinct points plus the repeated first one). Fewer throw CurveError.
#include <splinefig/spline/bezier.hpp>
#include <splinefig/spline/points.hpp>

#include <span>

namespace splinefig {

enum class EndCondition { relaxed, clamped, periodic };

struct Interpolant {
  EndCondition ends = EndCondition::relaxed;
  Points data;     // S_0..S_n
  Points control;  // B_0..B_n

  std::size_t pieces() const { return data.size() - 1; }  // n
};

Interpolant interpolate_relaxed(const Points& data);
// v = P'(0), w = P'(n), each with data.dim coordinates.
Interpolant interpolate_clamped(const Points& data, std::span<const double> v, std::span<const double> w);
// data's last point must equal its first (CurveError otherwise).
Interpolant interpolate_periodic(const Points& data);

// Seed 003 §4, the relaxed uniform cubic B-spline of control points B_0..B_n (n >= 1):
// S_0 = B_0, S_n = B_n, S_i = (B_{i-1} + 4B_i + B_{i+1})/6 between.
Points relaxed_joints(const Points& control);

// The n Bezier pieces (3n+1 points) of an interpolant, or of the relaxed B-spline
// with the given control points (seed 003 §4's construction).
BezierSpline bezier_pieces(const Interpolant& s);
BezierSpline relaxed_bspline_bezier(const Points& control);

// P(t) (or its derivative) at t in [0, n].
void evaluate(const Interpolant& s, double t, int derivative, std::span<double> out);

// P(t) at t = 0, 1/grain, ..., n: n*grain+1 points (grain >= 1).
Points sample(const Interpolant& s, int grain);

// Seed 003 §8: the basis functions f_0..f_n of relaxed interpolation on t in [0, n] (f_k is
// the relaxed spline through the data e_k), as one curve t -> (f_0(t), ..., f_n(t)) in R^(n+1):
// the relaxed interpolant of the n+1 unit points. Then P(t) = sum_k f_k(t) S_k for any data.
Interpolant relaxed_basis(int n);

}  // namespace splinefig
