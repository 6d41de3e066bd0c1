#pragma once
// Bezier curves of any degree (seed 003 §2-4): de Casteljau evaluation, splitting, the
// hodograph (derivative curve), and the piecewise-Bezier form of a spline.
//
// A Bezier curve of degree d is its d+1 control points P_0..P_d; P(t) = sum_k C(d,k)
// (1-t)^(d-k) t^k P_k for t in [0,1]. de Casteljau's algorithm evaluates it by repeated linear
// interpolation, which is also what splits it: the points on the two outer edges of the
// triangle of interpolants are the control points of the two halves.
//
// A spline made of n cubic pieces glued end to end is stored as 3n+1 points
// (BezierSpline): piece i (i = 0..n-1) is points 3i .. 3i+3, so neighbours share their joint.
#include <splinefig/spline/points.hpp>

#include <span>
#include <utility>

namespace splinefig {

// P(t) of one Bezier curve (control.size() >= 1) by de Casteljau; out has control.dim entries.
void de_casteljau(const Points& control, double t, std::span<double> out);

// The two halves of a Bezier curve split at t: [0,t] and [t,1], each reparametrized to [0,1].
std::pair<Points, Points> split_bezier(const Points& control, double t);

// The hodograph: the derivative P'(t) is the degree d-1 Bezier curve with control points
// d (P_{k+1} - P_k). A single point (degree 0) gives the zero curve of one point.
Points bezier_derivative(const Points& control);

// Cubic pieces glued end to end: points 3i .. 3i+3 are piece i.
struct BezierSpline {
  Points points;  // 3n+1 points for n pieces

  std::size_t pieces() const { return points.size() >= 4 ? (points.size() - 1) / 3 : 0; }
  Points piece(std::size_t i) const;
};

// P(t) for t in [0, n]: piece floor(t) at u = t - floor(t) (t = n is the end of the last piece).
// derivative 0, 1 or 2 gives P, dP/dt or d2P/dt2.
void evaluate(const BezierSpline& s, double t, int derivative, std::span<double> out);

}  // namespace splinefig
